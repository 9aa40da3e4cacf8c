#include "seflex/mbd/output.hpp"

namespace seflex::mbd {

Energies energies(const Model& model, const State& s, const Data& data) {
  Energies E;
  const Eigen::Vector3d& g = model.gravity;
  for (std::size_t b = 0; b < model.flexible_bodies.size(); ++b) {
    const FlexibleBodyData& fd = data.flex[b];
    const AicElement& e = model.superelement(model.flexible_bodies[b].se);
    E.kinetic += fd.kinetic;
    E.elastic += fd.elastic;
    if (g.squaredNorm() > 0.0) {
      const Eigen::Vector3d p_cm = fd.kin.frame.p_WBo + fd.kin.frame.R_WB * deformed_com(e, fd.kin.xi);
      E.gravity -= e.mass * g.dot(p_cm);
    }
  }
  for (std::size_t b = 0; b < model.rigid_bodies.size(); ++b) {
    E.kinetic += data.rigid[b].kinetic;
    E.gravity -= model.rigid_bodies[b].mass * g.dot(data.rigid[b].p_WCm);
  }
  for (std::size_t i = 0; i < model.force_elements.size(); ++i) E.spring += data.forces[i].energy;
  (void)s;
  return E;
}

ElementSample element_sample(const HingeForceResult& r, const LockState* lock) {
  ElementSample es;
  es.value = r.value;
  es.energy = r.energy;
  es.hinge_torques.assign(r.tau.data(), r.tau.data() + r.tau.size());
  if (lock) {
    es.latched = lock->latched;
    es.t_latch = lock->t_latch;
  }
  return es;
}

Sample make_sample(const Model& model, const State& s, const Data& data) {
  Sample out;
  out.t = s.t;
  for (const auto& nk : data.nodes) out.nodes.push_back(Pose{nk.R, nk.p});
  for (const auto& hk : data.hinges) out.hinges.push_back(HingeSample{hk.phi, hk.phidot, hk.phiddot, hk.joint_torque});
  for (std::size_t i = 0; i < model.force_elements.size(); ++i)
    out.elements.push_back(element_sample(data.forces[i], i < s.locks.size() ? &s.locks[i] : nullptr));
  for (const auto& fd : data.flex)
    out.flexible.push_back(FlexibleBodySample{Pose{fd.kin.frame.R_WB, fd.kin.frame.p_WBo}, fd.kin.xi, fd.kinetic, fd.elastic});
  for (std::size_t b = 0; b < model.rigid_bodies.size(); ++b) {
    const RigidBody& rb = model.rigid_bodies[b];
    const NodeKinematics& A = data.nodes[static_cast<std::size_t>(rb.anchor.value)];
    out.rigid.push_back(RigidBodySample{Pose{A.R * rb.R_NB, A.p + A.R * rb.p_NBo_N}, data.rigid[b].kinetic});
  }
  out.energy = energies(model, s, data);
  return out;
}

}  // namespace seflex::mbd
