// Thermal loads of CQUAD4 and CTRIA3 (element_shell_thermal.hpp).
#include "seflex/fem/element_shell_thermal.hpp"

#include <Eigen/Dense>
#include <array>

#include "seflex/common/error.hpp"

namespace seflex::fem {
namespace {

/// u_free (6N, basic) of section strains `ek` for an element with corner positions x (basic):
/// mean-plane frame as the elements build it (e3 from the diagonals of a quad or the edges of a
/// triangle, e1 along the projected G1-G2 edge, origin at the centroid).
template <int N>
Eigen::Matrix<double, 6 * N, 1> free_deformation(const std::array<Eigen::Vector3d, N>& x, const Eigen::Vector3d& n,
                                                 const Eigen::Matrix<double, 6, 1>& ek) {
  const Eigen::Vector3d e3 = n.normalized();
  const Eigen::Vector3d a = (x[1] - x[0]) - (x[1] - x[0]).dot(e3) * e3;
  Eigen::Matrix3d R_BL;
  R_BL.col(0) = a.normalized();
  R_BL.col(1) = e3.cross(R_BL.col(0));
  R_BL.col(2) = e3;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& xi : x) c += xi / N;
  const double exx = ek[0], eyy = ek[1], gxy = ek[2], kxx = ek[3], kyy = ek[4], kxy = ek[5];
  Eigen::Matrix<double, 6 * N, 1> u;
  for (int i = 0; i < N; ++i) {
    const Eigen::Vector3d r = R_BL.transpose() * (x[static_cast<std::size_t>(i)] - c);
    const double X = r.x(), Y = r.y(), Z = r.z();
    const double w = -0.5 * (kxx * X * X + kyy * Y * Y + kxy * X * Y);
    const double theta_y = kxx * X + 0.5 * kxy * Y;     // -w,x
    const double theta_x = -(kyy * Y + 0.5 * kxy * X);  //  w,y
    const Eigen::Vector3d u_L(exx * X + 0.5 * gxy * Y + Z * theta_y, 0.5 * gxy * X + eyy * Y - Z * theta_x, w);
    u.template segment<3>(6 * i) = R_BL * u_L;
    u.template segment<3>(6 * i + 3) = R_BL * Eigen::Vector3d(theta_x, theta_y, 0.0);
  }
  return u;
}

}  // namespace

Eigen::Matrix<double, 6, 1> shell_free_thermal_strains(const ShellSection& s, double dT) {
  Eigen::Matrix<double, 6, 6> ABD;
  ABD << s.A, s.B, s.B, s.D;
  Eigen::Matrix<double, 6, 1> r;
  r << s.NT * dT, s.MT * dT;
  if (r.isZero(0.0)) return Eigen::Matrix<double, 6, 1>::Zero();
  // Membrane-only (or bending-only) sections have a zero block: the minimum-norm solution leaves
  // the strains that nothing resists (and no resultant loads) at zero.
  const Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<double, 6, 6>> cod(ABD);
  return cod.solve(r);
}

Eigen::Matrix<double, 24, 1> quad4_thermal_load(const Quad4Element& e, double dT, double k6rot, const MystranPlate* mystran) {
  const auto& x = e.x;
  const Eigen::Matrix<double, 24, 1> u =
      free_deformation<4>(x, (x[2] - x[0]).cross(x[3] - x[1]), shell_free_thermal_strains(e.section, dT));
  return quad4_stiffness(e, k6rot, mystran) * u;
}

Eigen::Matrix<double, 18, 1> tria3_thermal_load(const Tria3Element& e, double dT, double k6rot, const MystranPlate* mystran) {
  const auto& x = e.x;
  const Eigen::Matrix<double, 18, 1> u =
      free_deformation<3>(x, (x[1] - x[0]).cross(x[2] - x[0]), shell_free_thermal_strains(e.section, dT));
  return tria3_stiffness(e, k6rot, mystran) * u;
}

}  // namespace seflex::fem
