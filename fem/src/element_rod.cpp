// CROD / CONROD element (see element_rod.hpp).
#include "seflex/fem/element_rod.hpp"

#include "model_lookup.hpp"
#include "seflex/common/error.hpp"

namespace seflex::fem {
namespace {

// 2-node pattern [a b; b a] (x) block on the translations (rot = false) or rotations.
void add_pattern(double diag, double off, const Eigen::Matrix3d& block, bool rot, NodeMatrix<2>& K) {
  const int o = rot ? 3 : 0;
  K.block<3, 3>(o, o) += diag * block;
  K.block<3, 3>(6 + o, 6 + o) += diag * block;
  K.block<3, 3>(o, 6 + o) += off * block;
  K.block<3, 3>(6 + o, o) += off * block;
}

}  // namespace

NodeMatrix<2> rod_stiffness(const RodElement& e) {
  const Eigen::Vector3d d = e.x_B - e.x_A;
  const double L = d.norm();
  SEFLEX_DEMAND(L > 0.0, "rod of zero length");
  const Eigen::Vector3d n = d / L;
  const Eigen::Matrix3d nn = n * n.transpose();
  NodeMatrix<2> K = NodeMatrix<2>::Zero();
  const double ka = e.material.E * e.A / L, kt = e.material.G * e.J / L;
  add_pattern(ka, -ka, nn, false, K);
  add_pattern(kt, -kt, nn, true, K);
  return K;
}

NodeMatrix<2> rod_mass(const RodElement& e, MassKind kind) {
  const double m = (e.material.rho * e.A + e.nsm) * (e.x_B - e.x_A).norm();
  NodeMatrix<2> M = NodeMatrix<2>::Zero();
  if (kind == MassKind::Lumped)
    add_pattern(0.5 * m, 0.0, Eigen::Matrix3d::Identity(), false, M);
  else
    add_pattern(m / 3.0, m / 6.0, Eigen::Matrix3d::Identity(), false, M);
  return M;
}

Eigen::Matrix<double, 12, 1> rod_thermal_load(const RodElement& e, double alpha, double dT) {
  const Eigen::Vector3d d = e.x_B - e.x_A;
  const Eigen::Vector3d F = e.material.E * e.A * alpha * dT * d.normalized();
  Eigen::Matrix<double, 12, 1> f = Eigen::Matrix<double, 12, 1>::Zero();
  f.segment<3>(0) = -F;
  f.segment<3>(6) = F;
  return f;
}

RodElement make_rod_element(const Model& model, const Rod& rod) {
  const std::string card = rod_card(rod);
  RodElement e;
  e.x_A = model.grids[detail::grid_index(model, rod.ga, rod.ref, card, rod.id, rod.inline_property ? "3 (G1)" : "4 (G1)")]
              .x_basic;
  e.x_B = model.grids[detail::grid_index(model, rod.gb, rod.ref, card, rod.id, rod.inline_property ? "4 (G2)" : "5 (G2)")]
              .x_basic;
  if (rod.inline_property) {
    e.A = rod.A;
    e.J = rod.J;
    e.nsm = rod.nsm;
    e.material = detail::material(model, rod.mid, rod.ref, card, rod.id, "5 (MID)");
  } else {
    const auto it = model.rod_prop_index.find(rod.pid);
    if (it == model.rod_prop_index.end())
      detail::fail(model, rod.ref, card, rod.id, "3 (PID)",
                   std::string("references ") + (rod.tube ? "PTUBE " : "PROD ") + std::to_string(rod.pid) + ", which is not defined");
    const RodProperty& p = model.rod_props[it->second];
    e.A = p.A;
    e.J = p.J;
    e.nsm = p.nsm;
    e.material = detail::material(model, p.mid, p.ref, rod_property_card(p), p.id, "3 (MID)");
  }
  if (!((e.x_B - e.x_A).norm() > 0.0))
    detail::fail(model, rod.ref, card, rod.id, "", "connects two grids at the same position (zero length)");
  return e;
}

}  // namespace seflex::fem
