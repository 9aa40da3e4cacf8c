// Forward kinematics of the node forest: poses, Jacobians, twists and accelerations.
//   p_c = p_P + d,  d = R_P p_PN_P;   R_c = R_P exp(phi a~) R_PN;   a_W = R_P a
//   v_c = v_P + w_P x d;              w_c = w_P + a_W phidot
//   a_c = a_P + alpha_P x d + w_P x (w_P x d);  alpha_c = alpha_P + a_W phiddot + w_P x a_W phidot
//   Jacobian columns: [J_r + J_w x d; J_w] for the parent's dofs, [0; a_W] for the hinge dof.
//   Convective Jacobian G = d[a; alpha]/dv at fixed vdot (for the velocity matrix C):
//   G_a = G_aP - d~ G_alphaP - ((w_P x d)~ + w_P~ d~) J_wP,  G_alpha = G_alphaP - (a_W phidot)~ J_wP,
//   and for the hinge dof G = [0; w_P x a_W].
#include "seflex/common/so3.hpp"
#include "seflex/mbd/assembly/assembly.hpp"

namespace seflex::mbd {

using Eigen::Vector3d;

void update_kinematics(const Model& model, const State& s, Data& data, bool dynamics) {
  for (std::size_t h = 0; h < model.hinges.size(); ++h) {
    const Hinge& hg = model.hinges[h];
    HingeKinematics& hk = data.hinges[h];
    if (hg.follower()) continue;  // below, from its leader
    if (hg.drive) {
      const DriveValue d = hg.drive(s.t);
      hk.phi = d.phi;
      hk.phidot = dynamics ? d.phidot : 0.0;
      hk.phiddot = dynamics ? d.phiddot : 0.0;
    } else {
      hk.phi = s.phi[static_cast<Eigen::Index>(h)];
      hk.phidot = dynamics ? s.v[hg.dof] : 0.0;
      hk.phiddot = dynamics ? s.vdot[hg.dof] : 0.0;
    }
  }
  for (std::size_t h = 0; h < model.hinges.size(); ++h) {
    const Hinge& hg = model.hinges[h];
    if (!hg.follower()) continue;
    const HingeKinematics& L = data.hinges[static_cast<std::size_t>(hg.leader.value)];
    HingeKinematics& hk = data.hinges[h];
    hk.phi = hg.follow_sign * L.phi + hg.follow_offset;
    hk.phidot = hg.follow_sign * L.phidot;
    hk.phiddot = hg.follow_sign * L.phiddot;
  }
  for (std::size_t k = 0; k < model.nodes.size(); ++k) {
    const Node& n = model.nodes[k];
    NodeKinematics& nk = data.nodes[k];
    switch (n.kind) {
      case NodeKind::Fixed:
        nk.R = n.X_WN0.R;
        nk.p = n.X_WN0.p;
        nk.v.setZero();
        nk.w.setZero();
        nk.a.setZero();
        nk.alpha.setZero();
        break;
      case NodeKind::Free: {
        nk.R = s.R_WN[k];
        nk.p = s.p_WN[k];
        if (dynamics) {
          nk.v = s.v.segment<3>(n.dof);
          nk.w = s.v.segment<3>(n.dof + 3);
          nk.a = s.vdot.segment<3>(n.dof);
          nk.alpha = s.vdot.segment<3>(n.dof + 3);
        } else {
          nk.v.setZero();
          nk.w.setZero();
          nk.a.setZero();
          nk.alpha.setZero();
        }
        for (int c = 0; c < 6; ++c) {
          nk.J[static_cast<std::size_t>(c)].setZero();
          nk.J[static_cast<std::size_t>(c)][c] = 1.0;
        }
        break;
      }
      case NodeKind::Attached: {
        const NodeKinematics& P = data.nodes[static_cast<std::size_t>(n.parent.value)];
        const Vector3d d = P.R * n.p_PN_P;
        nk.p = P.p + d;
        nk.v = P.v + P.w.cross(d);
        nk.a = P.a + P.alpha.cross(d) + P.w.cross(P.w.cross(d));
        nk.w = P.w;
        nk.alpha = P.alpha;
        const std::size_t np = P.J.size();
        const Eigen::Matrix3d dx = so3::skew(d);
        const Eigen::Matrix3d Gw = -(so3::skew(P.w.cross(d)) + so3::skew(P.w) * dx);
        for (std::size_t c = 0; c < np; ++c) {
          const Vector6d& jp = P.J[c];
          nk.J[c].head<3>() = jp.head<3>() + jp.tail<3>().cross(d);
          nk.J[c].tail<3>() = jp.tail<3>();
          const Vector6d& gp = P.G[c];
          nk.G[c].head<3>() = gp.head<3>() - dx * gp.tail<3>() + Gw * jp.tail<3>();
          nk.G[c].tail<3>() = gp.tail<3>();
        }
        if (n.hinge.valid()) {
          const Hinge& hg = model.hinge(n.hinge);
          HingeKinematics& hk = data.hinges[static_cast<std::size_t>(n.hinge.value)];
          hk.axis_W = P.R * hg.axis_P;
          nk.R = P.R * so3::exp(hk.phi * hg.axis_P) * n.R_PN;
          nk.w += hk.axis_W * hk.phidot;
          nk.alpha += hk.axis_W * hk.phiddot + P.w.cross(hk.axis_W) * hk.phidot;
          const Eigen::Matrix3d ax = so3::skew(hk.axis_W * hk.phidot);
          for (std::size_t c = 0; c < np; ++c) nk.G[c].tail<3>() -= ax * P.J[c].tail<3>();
          if (hg.dof >= 0) {
            nk.J[np].head<3>().setZero();
            nk.J[np].tail<3>() = hk.axis_W;
            nk.G[np].head<3>().setZero();
            nk.G[np].tail<3>() = P.w.cross(hk.axis_W);
          }
        } else {
          nk.R = P.R * n.R_PN;
        }
        break;
      }
    }
  }
  for (std::size_t h = 0; h < model.hinges.size(); ++h)  // a follower's axis: its leader's, signed
    if (model.hinges[h].follower())
      data.hinges[h].axis_W = model.hinges[h].follow_sign * data.hinges[static_cast<std::size_t>(model.hinges[h].leader.value)].axis_W;
}

void store_derived(const Model& model, const Data& data, State& s) {
  for (std::size_t k = 0; k < model.nodes.size(); ++k) {
    s.p_WN[k] = data.nodes[k].p;
    s.R_WN[k] = data.nodes[k].R;
  }
  for (std::size_t h = 0; h < model.hinges.size(); ++h)
    if (model.hinges[h].drive || model.hinges[h].follower()) s.phi[static_cast<Eigen::Index>(h)] = data.hinges[h].phi;
  for (std::size_t b = 0; b < model.flexible_bodies.size(); ++b) s.frames[b] = data.flex[b].kin.frame;
}

}  // namespace seflex::mbd
