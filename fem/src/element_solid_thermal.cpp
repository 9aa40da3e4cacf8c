// Thermal loads of the isoparametric solids (element_solid.hpp: solid_thermal_load).
#include <Eigen/Dense>
#include <cmath>

#include "seflex/fem/element_solid.hpp"
#include "solid_kinematics.hpp"

namespace seflex::fem {

Eigen::VectorXd solid_thermal_load(const SolidElement& e, double alpha, const Eigen::Ref<const Eigen::VectorXd>& dT_grid) {
  const int n = 3 * e.nnode;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  if (alpha == 0.0) return f;
  Eigen::Matrix<double, 6, 1> unit;  // D (1 1 1 0 0 0): the stress of a unit thermal strain
  unit << 1, 1, 1, 0, 0, 0;
  const Eigen::Matrix<double, 6, 1> Dm = e.D * unit;
  const bool bubbles = e.scheme == SolidElement::Scheme::IncompatibleModes;
  Eigen::MatrixXd Kci, Kii;
  Eigen::Matrix<double, 9, 1> fi = Eigen::Matrix<double, 9, 1>::Zero();
  detail::BubbleCentre centre;
  if (bubbles) {
    Kci = Eigen::MatrixXd::Zero(n, 9);
    Kii = Eigen::MatrixXd::Zero(9, 9);
    centre = detail::bubble_centre(e);
  }
  // The reduced-shear scheme changes only the shear rows of B, which D (1 1 1 0 0 0) does not load.
  detail::SolidPointData p;
  for (const auto& q : detail::solid_rule(e.shape, e.points)) {
    detail::evaluate(e, q.xi, p);
    const Eigen::MatrixXd B = detail::strain_matrix(e, p);
    const double dV = std::abs(p.detJ) * q.w;
    double dT = 0;
    for (int a = 0; a < e.nnode; ++a) dT += p.s.N[a] * dT_grid[a];
    const Eigen::Matrix<double, 6, 1> sigma_T = (alpha * dT) * Dm;
    f.noalias() += B.transpose() * sigma_T * dV;
    if (bubbles) {
      const Eigen::Matrix<double, 6, 9> Bi = detail::bubble_strain_matrix(centre, q.xi, p.detJ);
      Kci.noalias() += (e.D * B).transpose() * Bi * dV;
      Kii.noalias() += Bi.transpose() * e.D * Bi * dV;
      fi.noalias() += Bi.transpose() * sigma_T * dV;
    }
  }
  if (bubbles) f -= Kci * Kii.ldlt().solve(fi);
  return f;
}

}  // namespace seflex::fem
