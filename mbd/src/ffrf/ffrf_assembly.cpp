// FFRF-LM assembly: body forces, node loads, force elements on hinge angles and the constraint
// forces G^T lambda into the residual; mass matrices and the bodies' configuration and velocity
// derivatives analytic (ffrf_body_tangents.cpp; FfrfOptions::fd_body_jacobians: central differences
// over the body's 6 + k coordinates, the reference of the tests), and so are those of loads and
// constraints (d G^T lambda / dq, ffrf_joint_tangents.cpp; FfrfOptions::fd_joint_jacobians: central
// differences over the element's own coordinates, a constraint's two sides, a load's node), so the
// cost stays linear in the model size.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "ffrf/ffrf_detail.hpp"
#include "ffrf/ffrf_joint_tangents.hpp"
#include "seflex/mbd/forces/force_element.hpp"

namespace seflex::mbd::detail {

using Eigen::VectorXd;

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;
using Scratch = FfrfEval::Scratch;

/// v.head(n), v grown (never shrunk) to hold it.
Eigen::VectorBlock<VectorXd> head(VectorXd& v, Eigen::Index n) {
  if (v.size() < n) v.resize(n);
  return v.head(n);
}

/// The leading n x n block of K over the coordinates `cols` (>= 0 only) added to T, column by column.
void add_tangent(const std::vector<int>& cols, const Eigen::MatrixXd& K, Triplets& T) {
  const auto n = static_cast<Eigen::Index>(cols.size());
  for (Eigen::Index j = 0; j < n; ++j) {
    const int cj = cols[static_cast<std::size_t>(j)];
    if (cj < 0) continue;
    for (Eigen::Index i = 0; i < n; ++i) {
      const int ci = cols[static_cast<std::size_t>(i)];
      if (ci >= 0 && K(i, j) != 0.0) T.emplace_back(ci, cj, K(i, j));
    }
  }
}

/// Central differences of f (f(col, out) writes a local vector over `rows` into out, coordinate col
/// perturbed) w.r.t. the coordinates `cols` (>= 0 only), added to T as rows x cols triplets.
template <class F>
void fd_configuration(const FfrfSystem& sys, FfrfState& s, const std::vector<int>& rows, const std::vector<int>& cols, F&& f,
                      Scratch& w, Triplets& T) {
  const auto n = static_cast<Eigen::Index>(rows.size());
  auto fp = head(w.fp, n), fm = head(w.fm, n), d = head(w.d, n);
  for (int col : cols) {
    if (col < 0) continue;
    const double eps = fd_step(sys, col);
    Saved sv = perturb(sys, s, col, eps);
    f(col, fp);
    restore(sys, s, col, sv);
    sv = perturb(sys, s, col, -eps);
    f(col, fm);
    restore(sys, s, col, sv);
    d = (fp - fm) / (2.0 * eps);
    for (std::size_t r = 0; r < rows.size(); ++r)
      if (rows[r] >= 0 && d[static_cast<Eigen::Index>(r)] != 0.0) T.emplace_back(rows[r], col, d[static_cast<Eigen::Index>(r)]);
  }
}

void bodies(const FfrfSystem& sys, FfrfState& s, bool matrices, FfrfEval& ev) {
  Scratch& w = ev.scratch;
  ev.bodies.resize(sys.bodies.size());
  if (matrices) w.fd_bodies.resize(sys.bodies.size());
  for (std::size_t bi = 0; bi < sys.bodies.size(); ++bi) {
    const FfrfBody& b = sys.bodies[bi];
    const int nb = 6 + b.k, b0 = b.coord;
    BodyForce& bf = ev.bodies[bi];
    const bool analytic = matrices && !sys.options.fd_body_jacobians;
    body_force(sys, s, static_cast<int>(bi), matrices, bf, analytic);
    ev.r.segment(b0, nb) += bf.f;
    ev.scale.segment(b0, nb) += bf.f.cwiseAbs();
    if (!matrices) continue;
    const auto nb2 = static_cast<std::size_t>(nb * nb);
    w.max_M += nb2;
    w.max_K += nb2;
    w.max_C += nb2;
    for (int i = 0; i < nb; ++i)
      for (int j = 0; j < nb; ++j)
        if (bf.M(i, j) != 0.0) ev.M.emplace_back(b0 + i, b0 + j, bf.M(i, j));
    if (analytic) {
      for (int j = 0; j < nb; ++j)
        for (int i = 0; i < nb; ++i) {
          if (bf.K(i, j) != 0.0) ev.K.emplace_back(b0 + i, b0 + j, bf.K(i, j));
          if (bf.C(i, j) != 0.0) ev.C.emplace_back(b0 + i, b0 + j, bf.C(i, j));
        }
      continue;
    }
    w.idx.resize(static_cast<std::size_t>(nb));
    for (int i = 0; i < nb; ++i) w.idx[static_cast<std::size_t>(i)] = b0 + i;
    BodyForce& tmp = w.fd_bodies[bi];
    auto f = [&](int, Eigen::VectorBlock<VectorXd> out) {
      body_force(sys, s, static_cast<int>(bi), false, tmp);
      out = tmp.f;
    };
    fd_configuration(sys, s, w.idx, w.idx, f, w, ev.K);
    auto fp = head(w.fp, nb), fm = head(w.fm, nb), d = head(w.d, nb);
    for (int i = 0; i < nb; ++i) {  // the force is quadratic in the velocities: central differences are exact
      const double eps = fd_step(sys, b0 + i), v0 = s.v[b0 + i];
      s.v[b0 + i] = v0 + eps;
      f(-1, fp);
      s.v[b0 + i] = v0 - eps;
      f(-1, fm);
      s.v[b0 + i] = v0;
      d = (fp - fm) / (2.0 * eps);
      for (int r = 0; r < nb; ++r)
        if (d[r] != 0.0) ev.C.emplace_back(b0 + r, b0 + i, d[r]);
    }
  }
}

void loads(const FfrfSystem& sys, FfrfState& s, bool matrices, FfrfEval& ev) {
  Scratch& w = ev.scratch;
  PoseJ& P = w.pose;
  for (const NodeLoad& load : sys.model->loads) {
    Vector6d F;
    auto f = [&](int, Eigen::VectorBlock<VectorXd> out) {
      node_pose(sys, s, load.node.value, false, P);
      const double factor = load.scale ? load.scale(s.t) : 1.0;
      F.head<3>() = factor * (load.follower ? Eigen::Vector3d(P.R * load.force) : load.force);
      F.tail<3>() = factor * (load.follower ? Eigen::Vector3d(P.R * load.moment) : load.moment);
      out.noalias() = -(P.jacobian().transpose() * F);
    };
    node_pose(sys, s, load.node.value, false, P);
    const Eigen::Index n = P.size();
    auto q = head(w.q, n);
    f(-1, q);  // F: the load's world wrench at s
    for (std::size_t c = 0; c < P.cols.size(); ++c) {
      if (P.cols[c] < 0) continue;
      ev.r[P.cols[c]] += q[static_cast<Eigen::Index>(c)];
      ev.scale[P.cols[c]] += std::abs(q[static_cast<Eigen::Index>(c)]);
    }
    if (!matrices) continue;
    w.max_K += P.cols.size() * P.cols.size();
    if (!sys.options.fd_joint_jacobians) {
      load_tangent(sys, s, load, P, F, w.jt);
      add_tangent(P.cols, w.jt.K, ev.K);
      continue;
    }
    w.idx = P.cols;  // P is overwritten by the perturbed evaluations
    fd_configuration(sys, s, w.idx, w.idx, f, w, ev.K);
  }
}

void force_elements(const FfrfSystem& sys, const FfrfState& s, bool matrices, FfrfEval& ev) {
  const Model& model = *sys.model;
  Scratch& w = ev.scratch;
  hinge_values(sys, s, w.phi, w.phidot);
  const HingeValues hv{w.phi, w.phidot};
  ev.forces.resize(model.force_elements.size());
  for (std::size_t i = 0; i < model.force_elements.size(); ++i) {
    const bool latched = i < s.locks.size() && s.locks[i].latched;
    HingeForceResult& r = ev.forces[i];
    evaluate(model.force_elements[i].element, hv, latched, r);
    const int nh = static_cast<int>(r.hinges.size());
    if (matrices) {
      w.max_K += static_cast<std::size_t>(nh * nh);
      w.max_C += static_cast<std::size_t>(nh * nh);
    }
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
  Scratch& w = ev.scratch;
  ConstraintEval& ce = w.ce;
  for (std::size_t c = 0; c < sys.constraints.size(); ++c) {
    eval_constraint(sys, s, static_cast<int>(c), ce);
    const Vector6d lam = s.lambda.segment<6>(6 * static_cast<Eigen::Index>(c));
    ev.g.segment<6>(6 * static_cast<Eigen::Index>(c)) = ce.g;
    if (matrices) {
      w.max_G += 6 * ce.cols.size();
      w.max_K += ce.cols.size() * ce.cols.size();
    }
    auto q = head(w.q, ce.size());
    q.noalias() = ce.jacobian().transpose() * lam;
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
    if (!sys.options.fd_joint_jacobians) {
      constraint_tangent(sys, s, sys.constraints[c], ce, lam, w.jt);
      add_tangent(ce.cols, w.jt.K, ev.K);
      continue;
    }
    // A perturbed coordinate of one side only leaves the other side's pose as it is: only the
    // perturbed side is evaluated again (the same arithmetic as eval_constraint).
    ConstraintEval& cp = w.cp;
    const FfrfConstraint& con = sys.constraints[c];
    auto f = [&](int col, Eigen::VectorBlock<VectorXd> out) {
      const bool in_a = std::find(ce.A.cols.begin(), ce.A.cols.end(), col) != ce.A.cols.end();
      const bool in_b = std::find(ce.B.cols.begin(), ce.B.cols.end(), col) != ce.B.cols.end();
      if (in_a)
        interface_pose(sys, s, con.body, con.interface, cp.A);
      else
        cp.A.assign(ce.A);
      if (in_b)
        node_pose(sys, s, con.node.value, con.chain, cp.B);
      else
        cp.B.assign(ce.B);
      combine_constraint(cp);
      out.noalias() = cp.jacobian().transpose() * lam;
    };
    fd_configuration(sys, s, ce.cols, ce.cols, f, w, ev.K);
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
  Scratch& w = ev.scratch;
  w.max_K = w.max_C = w.max_M = w.max_G = 0;
  bodies(sys, s, matrices, ev);
  loads(sys, s, matrices, ev);
  force_elements(sys, s, matrices, ev);
  constraints(sys, s, matrices, ev);
  if (!matrices) return;
  ev.K.reserve(w.max_K);  // no-ops once reserved
  ev.C.reserve(w.max_C);
  ev.M.reserve(w.max_M);
  ev.G.reserve(w.max_G);
}

}  // namespace seflex::mbd::detail
