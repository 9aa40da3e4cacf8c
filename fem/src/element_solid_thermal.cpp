// Thermal loads of the isoparametric solids (element_solid.hpp: solid_thermal_load).
#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "seflex/fem/element_solid.hpp"
#include "solid_kinematics.hpp"

namespace seflex::fem {

Eigen::VectorXd solid_thermal_load(const SolidElement& e, double alpha, const Eigen::Ref<const Eigen::VectorXd>& dT_grid) {
  const int n = 3 * e.nnode;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  if (alpha == 0.0) return f;
  // D e.thermal_strain (MAT1: D (1 1 1 0 0 0)): the stress of a unit thermal strain
  const Eigen::Matrix<double, 6, 1> Dm = e.D * e.thermal_strain;
  const bool bubbles = e.scheme == SolidElement::Scheme::IncompatibleModes;
  Eigen::MatrixXd Kci, Kii;
  Eigen::Matrix<double, 9, 1> fi = Eigen::Matrix<double, 9, 1>::Zero();
  detail::BubbleCentre centre;
  if (bubbles) {
    Kci = Eigen::MatrixXd::Zero(n, 9);
    Kii = Eigen::MatrixXd::Zero(9, 9);
    centre = detail::bubble_centre(e);
  }
  // The strain operator of the stiffness: with the reduced-shear scheme its shear rows are averaged
  // (an isotropic D (1 1 1 0 0 0) does not load them; an anisotropic D may).
  const std::vector<detail::QuadraturePoint> rule = detail::solid_rule(e.shape, e.points);
  std::vector<Eigen::MatrixXd> Bs(rule.size());
  std::vector<double> detJs(rule.size());
  detail::SolidPointData p;
  for (std::size_t i = 0; i < rule.size(); ++i) {
    detail::evaluate(e, rule[i].xi, p);
    Bs[i] = detail::strain_matrix(e, p);
    detJs[i] = std::abs(p.detJ);
  }
  if (e.scheme == SolidElement::Scheme::ReducedShear) detail::reduce_shear_rows(rule, detJs, Bs);
  for (std::size_t i = 0; i < rule.size(); ++i) {
    const detail::QuadraturePoint& q = rule[i];
    detail::evaluate(e, q.xi, p);
    const Eigen::MatrixXd& B = Bs[i];
    const double dV = detJs[i] * q.w;
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
