// FFRF-LM samples: the same content as the AIC solver's (node poses, hinges, force elements,
// frames and xi = V z in the superelement's order, energies).
#include "ffrf/ffrf_detail.hpp"

namespace seflex::mbd {

namespace detail {

void ffrf_sample(const FfrfSystem& sys, const FfrfState& state, SampleScratch& w, Sample& out) {
  const Model& model = *sys.model;
  FfrfState& s = w.s;
  s = state;
  FfrfEval& ev = w.ev;
  ffrf_assemble(sys, s, false, ev);
  out.t = s.t;
  out.nodes.resize(model.nodes.size());
  for (std::size_t k = 0; k < model.nodes.size(); ++k) {
    node_pose(sys, s, static_cast<int>(k), false, w.pose);
    out.nodes[k] = Pose{w.pose.R, w.pose.p};
  }
  const Eigen::VectorXd &phi = w.phi, &phidot = w.phidot;
  hinge_values(sys, s, w.phi, w.phidot);
  out.hinges.resize(model.hinges.size());
  for (std::size_t h = 0; h < model.hinges.size(); ++h) {
    const auto hi = static_cast<Eigen::Index>(h);
    const int c = sys.hinge_coord[h];
    const double phidd = c >= 0 ? s.vdot[c] : model.hinges[h].drive(s.t).phiddot;
    out.hinges[h] = HingeSample{phi[hi], phidot[hi], phidd, ev.joint_torque[hi]};
  }
  out.energy = Energies{};
  out.elements.resize(model.force_elements.size());
  for (std::size_t i = 0; i < model.force_elements.size(); ++i) {
    const HingeForceResult& r = ev.forces[i];
    ElementSample& es = out.elements[i];  // as element_sample, its storage reused
    es.value = r.value;
    es.energy = r.energy;
    es.hinge_torques.assign(r.tau.data(), r.tau.data() + r.tau.size());
    es.latched = s.locks[i].latched;
    es.t_latch = s.locks[i].t_latch;
    out.energy.spring += r.energy;
  }
  std::size_t n_rigid = 0, n_flexible = 0;
  for (const FfrfBody& bd : sys.bodies) ++(bd.from_rigid ? n_rigid : n_flexible);
  out.rigid.resize(n_rigid);
  out.flexible.resize(n_flexible);
  n_rigid = n_flexible = 0;
  const Eigen::Vector3d& g = model.gravity;
  for (std::size_t b = 0; b < sys.bodies.size(); ++b) {
    const FfrfBody& bd = sys.bodies[b];
    const BodyForce& bf = ev.bodies[b];
    const Pose frame{s.R_WB[b], s.p_WB[b]};
    out.energy.kinetic += bf.kinetic;
    out.energy.elastic += bf.elastic;
    if (bd.from_rigid) {
      out.rigid[n_rigid++] = RigidBodySample{frame, bf.kinetic};
      out.energy.gravity -= bd.mass * g.dot(frame.p + frame.R * bd.p_BoCm_B);
      continue;
    }
    const AicElement& e = model.superelement(model.flexible_bodies[static_cast<std::size_t>(bd.model_index)].se);
    FlexibleBodySample& fs = out.flexible[n_flexible++];
    Eigen::VectorXd& xi = fs.xi;
    if (bd.k > 0)
      xi.noalias() = bd.V * s.z.segment(bd.z_offset, bd.k);
    else
      xi.setZero(e.n);
    const Eigen::Vector3d c_B = bd.flexible ? deformed_com(e, xi) : bd.p_BoCm_B;
    out.energy.gravity -= bd.mass * g.dot(frame.p + frame.R * c_B);
    fs.frame = frame;
    fs.kinetic = bf.kinetic;
    fs.elastic = bf.elastic;
  }
}

}  // namespace detail

Sample ffrf_sample(const FfrfSystem& sys, const FfrfState& state) {
  detail::SampleScratch w;
  Sample out;
  detail::ffrf_sample(sys, state, w, out);
  return out;
}

}  // namespace seflex::mbd
