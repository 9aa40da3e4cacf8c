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

void interface_load(const Model& model, const Data& data, int body, Eigen::VectorXd& f) {
  const FlexibleBodyData& fd = data.flex.at(static_cast<std::size_t>(body));
  const auto nb = 6 * static_cast<Eigen::Index>(model.flexible_bodies[static_cast<std::size_t>(body)].nodes.size());
  f = fd.f_el.head(nb) + fd.f_in.head(nb) + fd.f_damp.head(nb);
}

namespace {

void fill_element_sample(const HingeForceResult& r, const LockState* lock, ElementSample& es) {
  es.value = r.value;
  es.energy = r.energy;
  es.hinge_torques.assign(r.tau.data(), r.tau.data() + r.tau.size());  // same size each time: no allocation
  es.latched = lock ? lock->latched : false;
  es.t_latch = lock ? lock->t_latch : 0.0;
}

}  // namespace

ElementSample element_sample(const HingeForceResult& r, const LockState* lock) {
  ElementSample es;
  fill_element_sample(r, lock, es);
  return es;
}

void make_sample(const Model& model, const State& s, const Data& data, Sample& out) {
  out.t = s.t;
  out.nodes.resize(data.nodes.size());
  for (std::size_t k = 0; k < data.nodes.size(); ++k) out.nodes[k] = Pose{data.nodes[k].R, data.nodes[k].p};
  out.hinges.resize(data.hinges.size());
  for (std::size_t k = 0; k < data.hinges.size(); ++k) {
    const auto& hk = data.hinges[k];
    out.hinges[k] = HingeSample{hk.phi, hk.phidot, hk.phiddot, hk.joint_torque};
  }
  out.elements.resize(model.force_elements.size());
  for (std::size_t i = 0; i < model.force_elements.size(); ++i)
    fill_element_sample(data.forces[i], i < s.locks.size() ? &s.locks[i] : nullptr, out.elements[i]);
  out.flexible.resize(data.flex.size());
  for (std::size_t b = 0; b < data.flex.size(); ++b) {
    const auto& fd = data.flex[b];
    FlexibleBodySample& fs = out.flexible[b];
    fs.frame = Pose{fd.kin.frame.R_WB, fd.kin.frame.p_WBo};
    fs.xi = fd.kin.xi;
    fs.kinetic = fd.kinetic;
    fs.elastic = fd.elastic;
    if (model.flexible_bodies[b].options.interface_loads) interface_load(model, data, static_cast<int>(b), fs.interface_load);
  }
  out.rigid.resize(model.rigid_bodies.size());
  for (std::size_t b = 0; b < model.rigid_bodies.size(); ++b) {
    const RigidBody& rb = model.rigid_bodies[b];
    const NodeKinematics& A = data.nodes[static_cast<std::size_t>(rb.anchor.value)];
    out.rigid[b] = RigidBodySample{Pose{A.R * rb.R_NB, A.p + A.R * rb.p_NBo_N}, data.rigid[b].kinetic};
  }
  out.energy = energies(model, s, data);
}

Sample make_sample(const Model& model, const State& s, const Data& data) {
  Sample out;
  make_sample(model, s, data, out);
  return out;
}

}  // namespace seflex::mbd
