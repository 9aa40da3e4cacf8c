#include "seflex/mbd/state.hpp"

#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"

namespace seflex::mbd {

State initial_state(const Model& model) {
  State s;
  s.t = 0.0;
  for (const Node& n : model.nodes) {
    s.p_WN.push_back(n.X_WN0.p);
    s.R_WN.push_back(n.X_WN0.R);
  }
  s.phi.resize(static_cast<Eigen::Index>(model.hinges.size()));
  s.v = Eigen::VectorXd::Zero(model.num_dofs);
  s.vdot = Eigen::VectorXd::Zero(model.num_dofs);
  s.a = Eigen::VectorXd::Zero(model.num_dofs);
  s.eta = Eigen::VectorXd::Zero(model.num_modal);
  for (std::size_t h = 0; h < model.hinges.size(); ++h) {
    const Hinge& hg = model.hinges[h];
    s.phi[static_cast<Eigen::Index>(h)] = hg.phi0;
    if (hg.dof >= 0) s.v[hg.dof] = hg.phidot0;
  }
  for (const Node& n : model.nodes) {
    if (n.kind != NodeKind::Free) continue;
    s.v.segment<3>(n.dof) = n.v0;
    s.v.segment<3>(n.dof + 3) = n.w0;
  }
  for (const auto& b : model.flexible_bodies) s.frames.push_back(FloatingFrame{b.X_WB0.R, b.X_WB0.p});
  s.locks.resize(model.force_elements.size());
  for (std::size_t i = 0; i < model.force_elements.size(); ++i) {
    if (const auto* l = std::get_if<HingeLock>(&model.force_elements[i].element)) {
      const double phi0 = s.phi[l->hinge.value];
      s.locks[i].side = phi0 <= l->phi_lock ? 1.0 : -1.0;
      if (phi0 == l->phi_lock) s.locks[i].latched = true;
    }
  }
  return s;
}

void set_rigid_velocity(const Model& model, State& s, const Eigen::Vector3d& v_W, const Eigen::Vector3d& w_W) {
  for (std::size_t k = 0; k < model.nodes.size(); ++k) {
    const Node& n = model.nodes[k];
    if (n.kind != NodeKind::Free) continue;
    s.v.segment<3>(n.dof) = v_W + w_W.cross(s.p_WN[k]);
    s.v.segment<3>(n.dof + 3) = w_W;
  }
}

void follow_leaders(const Model& model, State& s) {
  for (std::size_t h = 0; h < model.hinges.size(); ++h) {
    const Hinge& hg = model.hinges[h];
    if (hg.follower())
      s.phi[static_cast<Eigen::Index>(h)] = hg.follow_sign * s.phi[static_cast<Eigen::Index>(hg.leader.value)] + hg.follow_offset;
  }
}

void apply_increment(const Model& model, State& s, const Eigen::Ref<const Eigen::VectorXd>& dx) {
  SEFLEX_DEMAND(dx.size() == model.num_dofs, "increment size");
  for (std::size_t k = 0; k < model.nodes.size(); ++k) {
    const Node& n = model.nodes[k];
    if (n.kind != NodeKind::Free) continue;
    s.p_WN[k] += dx.segment<3>(n.dof);
    s.R_WN[k] = so3::exp(dx.segment<3>(n.dof + 3)) * s.R_WN[k];
  }
  for (std::size_t h = 0; h < model.hinges.size(); ++h)
    if (model.hinges[h].dof >= 0) s.phi[static_cast<Eigen::Index>(h)] += dx[model.hinges[h].dof];
  follow_leaders(model, s);
  for (const auto& b : model.flexible_bodies) {
    const int m = model.superelement(b.se).m;
    if (m > 0) s.eta.segment(b.eta_offset, m) += dx.segment(b.eta_dof, m);
  }
}

}  // namespace seflex::mbd
