// MIN4T plate quadrilateral (see element_plate_min4t.hpp).
#include "seflex/fem/element_plate_min4t.hpp"

#include <Eigen/LU>

#include "seflex/common/error.hpp"
#include "seflex/fem/element_plate_min3.hpp"

namespace seflex::fem {
namespace {

using Matrix15 = Eigen::Matrix<double, 15, 15>;
using Vector15 = Eigen::Matrix<double, 15, 1>;

Eigen::Vector2d centre(const std::array<Eigen::Vector2d, 4>& p) {
  // p0 + s (p2 - p0) = p1 + r (p3 - p1)
  Eigen::Matrix2d A;
  A.col(0) = p[2] - p[0];
  A.col(1) = p[1] - p[3];
  const double det = A.determinant();
  SEFLEX_DEMAND(det != 0.0, "MIN4T: parallel diagonals");
  const Eigen::Vector2d sr = A.inverse() * (p[1] - p[0]);
  return p[0] + sr[0] * (p[2] - p[0]);
}

// The 5-node (corners, then the centre at 12..14) stiffness and pressure load.
void five_node(const std::array<Eigen::Vector2d, 4>& p, const Eigen::Matrix3d& D, const Eigen::Matrix2d& S, double cb,
               double q, Matrix15& K, Vector15& f) {
  const Eigen::Vector2d c = centre(p);
  K.setZero();
  f.setZero();
  for (int t = 0; t < 4; ++t) {
    const int node[3] = {t, (t + 1) % 4, 4};
    const std::array<Eigen::Vector2d, 3> x = {p[node[0]], p[node[1]], c};
    const PlateMatrix3 Kt = min3_stiffness(x, D, S, cb);
    const PlateVector3 ft = q != 0.0 ? min3_pressure_load(x, q) : PlateVector3::Zero();
    for (int a = 0; a < 3; ++a) {
      f.segment<3>(3 * node[a]) += ft.segment<3>(3 * a);
      for (int b = 0; b < 3; ++b) K.block<3, 3>(3 * node[a], 3 * node[b]) += Kt.block<3, 3>(3 * a, 3 * b);
    }
  }
}

}  // namespace

PlateMatrix4 min4t_stiffness(const std::array<Eigen::Vector2d, 4>& p, const Eigen::Matrix3d& D, const Eigen::Matrix2d& S,
                             double cb) {
  Matrix15 K;
  Vector15 f;
  five_node(p, D, S, cb, 0.0, K, f);
  const Eigen::Matrix3d Kcc = K.bottomRightCorner<3, 3>();
  PlateMatrix4 Kaa = K.topLeftCorner<12, 12>();
  if (!(Kcc.trace() > 0.0)) return Kaa;  // no bending stiffness (membrane-only section)
  const Eigen::Matrix<double, 12, 3> Kac = K.topRightCorner<12, 3>();
  Kaa.noalias() -= Kac * Kcc.inverse() * Kac.transpose();
  return 0.5 * (Kaa + Kaa.transpose());
}

PlateVector4 min4t_pressure_load(const std::array<Eigen::Vector2d, 4>& p, const Eigen::Matrix3d& D,
                                 const Eigen::Matrix2d& S, double cb, double q) {
  Matrix15 K;
  Vector15 f;
  five_node(p, D, S, cb, q, K, f);
  const Eigen::Matrix3d Kcc = K.bottomRightCorner<3, 3>();
  PlateVector4 fa = f.head<12>();
  if (!(Kcc.trace() > 0.0)) {  // no stiffness to condense with: the centre's force to the corners
    for (int i = 0; i < 4; ++i) fa[3 * i] += 0.25 * f[12];
    return fa;
  }
  fa.noalias() -= K.topRightCorner<12, 3>() * Kcc.inverse() * f.tail<3>();
  return fa;
}

}  // namespace seflex::fem
