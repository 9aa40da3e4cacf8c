// FFRF-LM samples: the same content as the AIC solver's (node poses, hinges, force elements,
// frames and xi = V z in the superelement's order, energies).
#include "ffrf/ffrf_detail.hpp"

namespace seflex::mbd {

Sample ffrf_sample(const FfrfSystem& sys, const FfrfState& state) {
  const Model& model = *sys.model;
  FfrfState s = state;
  detail::FfrfEval ev;
  detail::ffrf_assemble(sys, s, false, ev);
  Sample out;
  out.t = s.t;
  for (std::size_t k = 0; k < model.nodes.size(); ++k) {
    const detail::PoseJ P = detail::node_pose(sys, s, static_cast<int>(k), false);
    out.nodes.push_back(Pose{P.R, P.p});
  }
  Eigen::VectorXd phi, phidot;
  detail::hinge_values(sys, s, phi, phidot);
  for (std::size_t h = 0; h < model.hinges.size(); ++h) {
    const auto hi = static_cast<Eigen::Index>(h);
    const int c = sys.hinge_coord[h];
    const double phidd = c >= 0 ? s.vdot[c] : model.hinges[h].drive(s.t).phiddot;
    out.hinges.push_back(HingeSample{phi[hi], phidot[hi], phidd, ev.joint_torque[hi]});
  }
  for (std::size_t i = 0; i < model.force_elements.size(); ++i) {
    out.elements.push_back(element_sample(ev.forces[i], &s.locks[i]));
    out.energy.spring += ev.forces[i].energy;
  }
  const Eigen::Vector3d& g = model.gravity;
  for (std::size_t b = 0; b < sys.bodies.size(); ++b) {
    const FfrfBody& bd = sys.bodies[b];
    const detail::BodyForce& bf = ev.bodies[b];
    const Pose frame{s.R_WB[b], s.p_WB[b]};
    out.energy.kinetic += bf.kinetic;
    out.energy.elastic += bf.elastic;
    if (bd.from_rigid) {
      out.rigid.push_back(RigidBodySample{frame, bf.kinetic});
      out.energy.gravity -= bd.mass * g.dot(frame.p + frame.R * bd.p_BoCm_B);
      continue;
    }
    const AicElement& e = model.superelement(model.flexible_bodies[static_cast<std::size_t>(bd.model_index)].se);
    Eigen::VectorXd xi = Eigen::VectorXd::Zero(e.n);
    if (bd.k > 0) xi = bd.V * s.z.segment(bd.z_offset, bd.k);
    const Eigen::Vector3d c_B = bd.flexible ? deformed_com(e, xi) : bd.p_BoCm_B;
    out.energy.gravity -= bd.mass * g.dot(frame.p + frame.R * c_B);
    out.flexible.push_back(FlexibleBodySample{frame, xi, bf.kinetic, bf.elastic});
  }
  return out;
}

}  // namespace seflex::mbd
