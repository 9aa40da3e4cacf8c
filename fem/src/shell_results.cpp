// Shell element results from the centroid resultants (shell_results.hpp, element_results.hpp).
#include "shell_results.hpp"

#include <Eigen/LU>
#include <cmath>

namespace seflex::fem::detail {
namespace {

// An in-plane tensor (xx, yy, xy) in axes rotated by phi about the normal.
Eigen::Vector3d rotate_tensor(const Eigen::Vector3d& t, double c, double s) {
  return {c * c * t[0] + s * s * t[1] + 2 * c * s * t[2], s * s * t[0] + c * c * t[1] - 2 * c * s * t[2],
          -c * s * t[0] + c * s * t[1] + (c * c - s * s) * t[2]};
}

}  // namespace

Eigen::Matrix<double, 14, 1> shell_results(const ShellSection& s, const ShellFibres& f, const Eigen::Vector3d& N,
                                           const Eigen::Vector3d& kappa, const Eigen::Vector2d& Q, double phi) {
  Eigen::Vector3d M = s.D * kappa;
  if (s.has_membrane && !s.B.isZero(0.0)) M += s.B * s.A.fullPivLu().solve(N - s.B * kappa);
  M -= f.zoffs * N;  // about the material mid-surface
  const double c = std::cos(phi), sn = std::sin(phi);
  const Eigen::Vector3d Nn = rotate_tensor(N, c, sn), Mn = -rotate_tensor(M, c, sn);
  const Eigen::Vector2d Qn(c * Q.x() + sn * Q.y(), -sn * Q.x() + c * Q.y());
  Eigen::Matrix<double, 14, 1> r;
  r << Nn, Mn, Qn, Eigen::Matrix<double, 6, 1>::Zero();
  const double t = s.t;
  for (int k = 0; k < 2; ++k) {
    const double z = k == 0 ? f.z1 : f.z2;
    for (int i = 0; i < 3; ++i)
      r(8 + 3 * k + i) = (t > 0 ? Nn[i] / t : 0.0) - (f.I > 0 ? Mn[i] * z / f.I : 0.0);
  }
  return r;
}

}  // namespace seflex::fem::detail
