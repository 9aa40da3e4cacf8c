// FFRF-LM assembly: body forces, node loads, force elements on hinge angles and the constraint
// forces G^T lambda into the residual; mass matrices analytic, the configuration and velocity
// derivatives of each element by central differences over that element's own coordinates (a body's
// 6 + k, a constraint's two sides, a load's node), so the cost stays linear in the model size.
#include <Eigen/Dense>
#include <cmath>

#include "ffrf/ffrf_detail.hpp"
#include "seflex/mbd/forces/force_element.hpp"

namespace seflex::mbd::detail {

using Eigen::VectorXd;

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

/// Central differences of f (a local vector over `rows`) w.r.t. the coordinates `cols` (>= 0
/// only), added to T as rows x cols triplets.
template <class F>
void fd_configuration(const FfrfSystem& sys, FfrfState& s, const std::vector<int>& rows, const std::vector<int>& cols, F&& f,
                      Triplets& T) {
  for (int col : cols) {
    if (col < 0) continue;
    const double eps = fd_step(sys, col);
    Saved sv = perturb(sys, s, col, eps);
    const VectorXd fp = f();
    restore(sys, s, col, sv);
    sv = perturb(sys, s, col, -eps);
    const VectorXd fm = f();
    restore(sys, s, col, sv);
    const VectorXd d = (fp - fm) / (2.0 * eps);
    for (std::size_t r = 0; r < rows.size(); ++r)
      if (rows[r] >= 0 && d[static_cast<Eigen::Index>(r)] != 0.0) T.emplace_back(rows[r], col, d[static_cast<Eigen::Index>(r)]);
  }
}

void bodies(const FfrfSystem& sys, FfrfState& s, bool matrices, FfrfEval& ev) {
  ev.bodies.resize(sys.bodies.size());
  for (std::size_t bi = 0; bi < sys.bodies.size(); ++bi) {
    const FfrfBody& b = sys.bodies[bi];
    const int nb = 6 + b.k, b0 = b.coord;
    BodyForce& bf = ev.bodies[bi];
    body_force(sys, s, static_cast<int>(bi), matrices, bf);
    ev.r.segment(b0, nb) += bf.f;
    ev.scale.segment(b0, nb) += bf.f.cwiseAbs();
    if (!matrices) continue;
    for (int i = 0; i < nb; ++i)
      for (int j = 0; j < nb; ++j)
        if (bf.M(i, j) != 0.0) ev.M.emplace_back(b0 + i, b0 + j, bf.M(i, j));
    std::vector<int> idx(static_cast<std::size_t>(nb));
    for (int i = 0; i < nb; ++i) idx[static_cast<std::size_t>(i)] = b0 + i;
    BodyForce tmp;
    auto f = [&] {
      body_force(sys, s, static_cast<int>(bi), false, tmp);
      return tmp.f;
    };
    fd_configuration(sys, s, idx, idx, f, ev.K);
    for (int i = 0; i < nb; ++i) {  // the force is quadratic in the velocities: central differences are exact
      const double eps = fd_step(sys, b0 + i), v0 = s.v[b0 + i];
      s.v[b0 + i] = v0 + eps;
      const VectorXd fp = f();
      s.v[b0 + i] = v0 - eps;
      const VectorXd fm = f();
      s.v[b0 + i] = v0;
      const VectorXd d = (fp - fm) / (2.0 * eps);
      for (int r = 0; r < nb; ++r)
        if (d[r] != 0.0) ev.C.emplace_back(b0 + r, b0 + i, d[r]);
    }
  }
}

void loads(const FfrfSystem& sys, FfrfState& s, bool matrices, FfrfEval& ev) {
  for (const NodeLoad& load : sys.model->loads) {
    auto f = [&] {
      const PoseJ P = node_pose(sys, s, load.node.value, false);
      const double factor = load.scale ? load.scale(s.t) : 1.0;
      Vector6d F;
      F.head<3>() = factor * (load.follower ? Eigen::Vector3d(P.R * load.force) : load.force);
      F.tail<3>() = factor * (load.follower ? Eigen::Vector3d(P.R * load.moment) : load.moment);
      return VectorXd(-(P.J.transpose() * F));
    };
    const PoseJ P = node_pose(sys, s, load.node.value, false);
    const VectorXd q = f();
    for (std::size_t c = 0; c < P.cols.size(); ++c) {
      if (P.cols[c] < 0) continue;
      ev.r[P.cols[c]] += q[static_cast<Eigen::Index>(c)];
      ev.scale[P.cols[c]] += std::abs(q[static_cast<Eigen::Index>(c)]);
    }
    if (matrices) fd_configuration(sys, s, P.cols, P.cols, f, ev.K);
  }
}

void force_elements(const FfrfSystem& sys, const FfrfState& s, bool matrices, FfrfEval& ev) {
  const Model& model = *sys.model;
  VectorXd phi, phidot;
  hinge_values(sys, s, phi, phidot);
  const HingeValues hv{phi, phidot};
  ev.forces.resize(model.force_elements.size());
  for (std::size_t i = 0; i < model.force_elements.size(); ++i) {
    const bool latched = i < s.locks.size() && s.locks[i].latched;
    HingeForceResult& r = ev.forces[i];
    r = evaluate(model.force_elements[i].element, hv, latched);
    const int nh = static_cast<int>(r.hinges.size());
    for (int a = 0; a < nh; ++a) {
      const int h = r.hinges[static_cast<std::size_t>(a)].value;
      ev.joint_torque[h] -= r.tau[a];
      const int ca = sys.hinge_coord[static_cast<std::size_t>(h)];
      if (ca < 0) continue;
      ev.r[ca] -= r.tau[a];
      ev.scale[ca] += std::abs(r.tau[a]);
      if (!matrices) continue;
      for (int b = 0; b < nh; ++b) {
        const int cb = sys.hinge_coord[static_cast<std::size_t>(r.hinges[static_cast<std::size_t>(b)].value)];
        if (cb < 0) continue;
        ev.K.emplace_back(ca, cb, -r.dtau_dphi(a, b));
        ev.C.emplace_back(ca, cb, -r.dtau_dphidot(a, b));
      }
    }
  }
}

/// The hinge a Jacobian column belongs to, or -1.
int hinge_of(const FfrfSystem& sys, int col) {
  if (col < 0) return -col - 1;
  return sys.kind[static_cast<std::size_t>(col)] == 'h' ? sys.owner[static_cast<std::size_t>(col)] : -1;
}

void constraints(const FfrfSystem& sys, FfrfState& s, bool matrices, FfrfEval& ev) {
  ConstraintEval ce;
  for (std::size_t c = 0; c < sys.constraints.size(); ++c) {
    eval_constraint(sys, s, static_cast<int>(c), ce);
    const Vector6d lam = s.lambda.segment<6>(6 * static_cast<Eigen::Index>(c));
    ev.g.segment<6>(6 * static_cast<Eigen::Index>(c)) = ce.g;
    const VectorXd q = ce.G.transpose() * lam;
    for (std::size_t i = 0; i < ce.cols.size(); ++i) {
      const int col = ce.cols[i];
      const double qi = q[static_cast<Eigen::Index>(i)];
      const int h = hinge_of(sys, col);
      if (h >= 0) ev.joint_torque[h] += qi;
      if (col < 0) continue;
      ev.r[col] += qi;
      ev.scale[col] += std::abs(qi);
      if (!matrices) continue;
      for (int k = 0; k < 6; ++k)
        if (ce.G(k, static_cast<Eigen::Index>(i)) != 0.0)
          ev.G.emplace_back(6 * static_cast<int>(c) + k, col, ce.G(k, static_cast<Eigen::Index>(i)));
    }
    if (!matrices || lam.isZero(0.0)) continue;
    ConstraintEval cp;
    auto f = [&] {
      eval_constraint(sys, s, static_cast<int>(c), cp);
      return VectorXd(cp.G.transpose() * lam);
    };
    fd_configuration(sys, s, ce.cols, ce.cols, f, ev.K);
  }
}

}  // namespace

void ffrf_assemble(const FfrfSystem& sys, FfrfState& s, bool matrices, FfrfEval& ev) {
  const int nq = sys.num_coords;
  ev.r = VectorXd::Zero(nq);
  ev.scale = VectorXd::Zero(nq);
  ev.g = VectorXd::Zero(sys.num_multipliers());
  ev.joint_torque = VectorXd::Zero(static_cast<Eigen::Index>(sys.model->hinges.size()));
  ev.K.clear();
  ev.C.clear();
  ev.M.clear();
  ev.G.clear();
  bodies(sys, s, matrices, ev);
  loads(sys, s, matrices, ev);
  force_elements(sys, s, matrices, ev);
  constraints(sys, s, matrices, ev);
}

}  // namespace seflex::mbd::detail
