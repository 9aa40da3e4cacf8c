// Element results of the line and spring elements: CBAR/CBEAM, CROD/CONROD/CTUBE, CBUSH
// (element_results.hpp).
#include "seflex/fem/element_bar.hpp"
#include "seflex/fem/element_bush.hpp"
#include "seflex/fem/element_results.hpp"
#include "seflex/fem/element_rod.hpp"

namespace seflex::fem {

Eigen::Matrix<double, 8, 1> bar_results(const BarElement& e, const Eigen::Matrix<double, 12, 1>& u) {
  // Internal resultants R(x) on the part [A, x] from the part beyond: R(0) = -f_A, R(L) = f_B. Plane 1
  // (x-y): M1 = R_mz, V1 = R_y, so dM1/dx = -V1; plane 2 (x-z): V2 = R_z and M2 = -R_my, so that
  // dM2/dx = -V2 as well (Nastran's CBAR force output; a tip load +P along y or z of a cantilever gives
  // M1(A) = P L or M2(A) = P L).
  const Eigen::Matrix<double, 12, 1> f = bar_end_forces(e, u);
  Eigen::Matrix<double, 8, 1> r;
  r << -f(5), f(4), f(11), -f(10), f(7), f(8), f(6), f(9);
  return r;
}

Eigen::Vector3d rod_results(const RodElement& e, const Eigen::Matrix<double, 12, 1>& u) {
  const Eigen::Vector3d d = e.x_B - e.x_A;
  const double L = d.norm();
  const Eigen::Vector3d n = d / L;
  const double axial = e.material.E * e.A / L * n.dot(u.segment<3>(6) - u.segment<3>(0));
  const double torque = e.material.G * e.J / L * n.dot(u.segment<3>(9) - u.segment<3>(3));
  return {axial, torque, e.A > 0 ? axial / e.A : 0.0};
}

Eigen::Matrix<double, 6, 1> bush_results(const BushElement& e, const Eigen::Matrix<double, 12, 1>& u) {
  // Motion of the spring point with each grid, in element axes: K (u_B - u_A) (GB blank: u_B = 0).
  Eigen::Matrix<double, 6, 1> d = -rigid_link(e.p_P - e.x_A) * u.head<6>();
  if (!e.grounded) d += rigid_link(e.p_P - e.x_B) * u.tail<6>();
  Eigen::Matrix<double, 6, 1> r;
  for (int h = 0; h < 2; ++h) r.segment<3>(3 * h) = e.R_BE.transpose() * d.segment<3>(3 * h);
  for (int i = 0; i < 6; ++i) r(i) *= e.k[static_cast<std::size_t>(i)];
  return r;
}

}  // namespace seflex::fem
