// FFRF-LM kinematics: interface and node poses with Jacobians, constraint residuals, coordinate
// perturbations for the finite-difference derivatives.
#include <Eigen/Dense>

#include "ffrf/ffrf_detail.hpp"
#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"

namespace seflex::mbd::detail {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using so3::skew;

void PoseJ::reset(Eigen::Index n) {
  cols.resize(static_cast<std::size_t>(n));
  if (J.cols() < n) J.resize(6, n);
  J.leftCols(n).setZero();
}

void PoseJ::push_column(int col) {
  const Eigen::Index n = size();
  if (J.cols() < n + 1) J.conservativeResize(Eigen::NoChange, n + 1);
  cols.push_back(col);
  J.col(n).setZero();
}

void PoseJ::assign(const PoseJ& from) {
  R = from.R;
  p = from.p;
  const Eigen::Index n = from.size();
  if (J.cols() < n) J.resize(6, n);
  cols.assign(from.cols.begin(), from.cols.end());
  J.leftCols(n) = from.J.leftCols(n);
}

void interface_pose(const FfrfSystem& sys, const FfrfState& s, int bi, int j, PoseJ& out) {
  const FfrfBody& b = sys.bodies[static_cast<std::size_t>(bi)];
  const Matrix3d& R = s.R_WB[static_cast<std::size_t>(bi)];
  const Pose& X_BN = b.X_BN[static_cast<std::size_t>(j)];
  const int nb = 6 + b.k;
  out.reset(nb);
  for (int c = 0; c < nb; ++c) out.cols[static_cast<std::size_t>(c)] = b.coord + c;
  Vector3d s_j = X_BN.p;
  Matrix3d R_BN = X_BN.R;
  if (b.flexible && b.k > 0) {
    const auto Vj = b.V.middleRows<6>(6 * j);
    const Eigen::Matrix<double, 6, 1> xi = Vj * s.z.segment(b.z_offset, b.k);
    s_j += xi.head<3>();
    R_BN = so3::exp(xi.tail<3>()) * X_BN.R;
    out.J.block(0, 6, 3, b.k).noalias() = R * Vj.topRows<3>();
    out.J.block(3, 6, 3, b.k).noalias() = R * so3::jl(xi.tail<3>()) * Vj.bottomRows<3>();
  }
  out.p = s.p_WB[static_cast<std::size_t>(bi)] + R * s_j;
  out.R = R * R_BN;
  out.J.block<3, 3>(0, 0).setIdentity();
  out.J.block<3, 3>(0, 3) = -skew(R * s_j);
  out.J.block<3, 3>(3, 3).setIdentity();
}

void node_pose(const FfrfSystem& sys, const FfrfState& s, int k, bool chain, PoseJ& out) {
  const Model& model = *sys.model;
  const Node& n = model.nodes[static_cast<std::size_t>(k)];
  const FfrfNodeSource& src = sys.node_source[static_cast<std::size_t>(k)];
  if (n.kind == NodeKind::Fixed) {
    out.R = n.X_WN0.R;
    out.p = n.X_WN0.p;
    out.reset(0);
    return;
  }
  if (!chain && src.kind == FfrfNodeSource::Kind::Body) {
    interface_pose(sys, s, src.body, src.interface, out);
    return;
  }
  SEFLEX_DEMAND(n.kind == NodeKind::Attached, "node pose through a parent of a node that has none");
  node_pose(sys, s, n.parent.value, false, out);
  attach_to_parent(sys, s, k, out);
}

void attach_to_parent(const FfrfSystem& sys, const FfrfState& s, int k, PoseJ& out) {
  const Model& model = *sys.model;
  const Node& n = model.nodes[static_cast<std::size_t>(k)];
  const Matrix3d R_P = out.R;
  const Vector3d d = R_P * n.p_PN_P;
  out.p += d;
  for (Eigen::Index c = 0; c < out.size(); ++c) out.J.col(c).head<3>() += out.J.col(c).tail<3>().cross(d);
  if (n.hinge.valid()) {
    const int h = n.hinge.value;
    const Vector3d& a = model.hinges[static_cast<std::size_t>(h)].axis_P;
    out.R = R_P * so3::exp(s.phi[h] * a) * n.R_PN;
    const int col = sys.hinge_coord[static_cast<std::size_t>(h)];
    out.push_column(col >= 0 ? col : -(h + 1));
    out.J.col(out.size() - 1) << Vector3d::Zero(), R_P * a;
  } else {
    out.R = R_P * n.R_PN;
  }
}

void eval_constraint(const FfrfSystem& sys, const FfrfState& s, int c, ConstraintEval& out) {
  const FfrfConstraint& con = sys.constraints[static_cast<std::size_t>(c)];
  interface_pose(sys, s, con.body, con.interface, out.A);
  node_pose(sys, s, con.node.value, con.chain, out.B);
  combine_constraint(out);
}

void combine_constraint(ConstraintEval& out) {
  const PoseJ& A = out.A;
  const PoseJ& B = out.B;
  out.g.head<3>() = A.p - B.p;
  out.g.tail<3>() = so3::log(B.R.transpose() * A.R);
  const Matrix3d L = so3::jl_inv(out.g.tail<3>()) * B.R.transpose();
  // A's columns are its body's coordinates, consecutive (interface_pose), so a column of B is one of
  // them iff it lies in that range, at its offset from the first (a linear search here was 12 % of an
  // FFRF-LM run: the joints' finite differences call this 2 (|A| + |B|) times per iteration matrix).
  const int a0 = A.cols.empty() ? 0 : A.cols.front();
  const auto na = static_cast<int>(A.size());
  auto in_A = [a0, na](int col) { return col >= a0 && col < a0 + na; };
  out.cols = A.cols;
  for (int col : B.cols)  // B's columns are distinct (one per coordinate or driven hinge on its chain)
    if (!in_A(col)) out.cols.push_back(col);
  const Eigen::Index n = out.size();
  if (out.G.cols() < n) out.G.resize(6, n);
  out.G.leftCols(n).setZero();
  for (std::size_t i = 0; i < A.cols.size(); ++i) {
    const auto ci = static_cast<Eigen::Index>(i);
    out.G.col(ci).head<3>() += A.J.col(ci).head<3>();
    out.G.col(ci).tail<3>() += L * A.J.col(ci).tail<3>();
  }
  Eigen::Index next = na;  // B's columns outside A follow A's in out.cols, in B's order
  out.b_at.resize(B.cols.size());
  for (std::size_t i = 0; i < B.cols.size(); ++i) {
    const Eigen::Index at = in_A(B.cols[i]) ? B.cols[i] - a0 : next++;
    out.b_at[i] = static_cast<int>(at);
    const auto ci = static_cast<Eigen::Index>(i);
    out.G.col(at).head<3>() -= B.J.col(ci).head<3>();
    out.G.col(at).tail<3>() -= L * B.J.col(ci).tail<3>();
  }
}

void constraint_rates(const FfrfSystem& sys, const FfrfState& s, Eigen::VectorXd& phi, Eigen::VectorXd& phidot, ConstraintEval& ce,
                      Eigen::VectorXd& g, Eigen::VectorXd& gdot) {
  hinge_values(sys, s, phi, phidot);
  const auto nc = static_cast<int>(sys.constraints.size());
  g.resize(6 * nc);
  gdot.resize(6 * nc);
  for (int c = 0; c < nc; ++c) {
    eval_constraint(sys, s, c, ce);
    g.segment<6>(6 * c) = ce.g;
    Vector6d gd = Vector6d::Zero();
    for (std::size_t i = 0; i < ce.cols.size(); ++i) {
      const int col = ce.cols[i];
      gd += ce.G.col(static_cast<Eigen::Index>(i)) * (col >= 0 ? s.v[col] : phidot[-col - 1]);
    }
    gdot.segment<6>(6 * c) = gd;
  }
}

Saved perturb(const FfrfSystem& sys, FfrfState& s, int i, double eps) {
  Saved sv;
  const auto iu = static_cast<std::size_t>(i);
  const int owner = sys.owner[iu];
  const auto o = static_cast<std::size_t>(owner);
  switch (sys.kind[iu]) {
    case 't': {
      const int c = i - sys.bodies[o].coord;
      sv.x = s.p_WB[o][c];
      s.p_WB[o][c] += eps;
      break;
    }
    case 'r': {
      const int c = i - sys.bodies[o].coord - 3;
      sv.R = s.R_WB[o];
      s.R_WB[o] = so3::exp(eps * Vector3d::Unit(c)) * s.R_WB[o];
      break;
    }
    case 'e': {
      const int c = sys.bodies[o].z_offset + i - sys.bodies[o].coord - 6;
      sv.x = s.z[c];
      s.z[c] += eps;
      break;
    }
    default:
      sv.x = s.phi[owner];
      s.phi[owner] += eps;
  }
  return sv;
}

void restore(const FfrfSystem& sys, FfrfState& s, int i, const Saved& sv) {
  const auto iu = static_cast<std::size_t>(i);
  const int owner = sys.owner[iu];
  const auto o = static_cast<std::size_t>(owner);
  switch (sys.kind[iu]) {
    case 't': s.p_WB[o][i - sys.bodies[o].coord] = sv.x; break;
    case 'r': s.R_WB[o] = sv.R; break;
    case 'e': s.z[sys.bodies[o].z_offset + i - sys.bodies[o].coord - 6] = sv.x; break;
    default: s.phi[owner] = sv.x;
  }
}

double fd_step(const FfrfSystem& sys, int i) { return 1e-6 / sys.weight[i]; }

void hinge_values(const FfrfSystem& sys, const FfrfState& s, Eigen::VectorXd& phi, Eigen::VectorXd& phidot) {
  const Model& model = *sys.model;
  phi = s.phi;
  phidot.resize(phi.size());
  for (std::size_t h = 0; h < model.hinges.size(); ++h) {
    const int c = sys.hinge_coord[h];
    if (!model.hinges[h].follower()) phidot[static_cast<Eigen::Index>(h)] = c >= 0 ? s.v[c] : model.hinges[h].drive(s.t).phidot;
  }
  for (std::size_t h = 0; h < model.hinges.size(); ++h) {  // a follower: from its leader (ModelBuilder::add_follower_hinge)
    const Hinge& hg = model.hinges[h];
    if (!hg.follower()) continue;
    const auto i = static_cast<Eigen::Index>(h), l = static_cast<Eigen::Index>(hg.leader.value);
    phi[i] = hg.follow_sign * phi[l] + hg.follow_offset;
    phidot[i] = hg.follow_sign * phidot[l];
  }
}

}  // namespace seflex::mbd::detail
