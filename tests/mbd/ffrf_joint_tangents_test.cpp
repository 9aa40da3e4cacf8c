// FFRF-LM joint and node-load tangents (mbd/src/ffrf/ffrf_joint_tangents.cpp): the analytic
// d(G^T lambda)/dq of every constraint and d(-J^T F)/dq of every node load (rotation increments
// R <- exp(dpi~) R) against central differences of G^T lambda and -J^T F over the element's own
// coordinates (perturb/restore, as the assembly's FfrfOptions::fd_joint_jacobians), at random states:
// frames moved and turned (the joints violated: log(R_B^T R_A) up to ~1 rad, so J_l^-1's derivative
// matters), modes deformed (elastic interface rotations of 0.05 and 0.5 of a mode's scale: J_l's
// derivative on both sides of the series/closed-form switch), nonzero multipliers. Then the whole
// assembled K with the analytic tangents against the one with fd_joint_jacobians.
//
// Error of the reference: step eps = 1e-4 of each coordinate's scale (below). Round-off, ~1e-16 |q| / eps
// with |q| the element's generalized force, dominates at smaller steps: on the flexible chain with
// consistent joints the largest difference is 3e-6, 3e-7, 4e-8, 3.5e-9 of the largest entry at eps =
// 1e-7, 1e-6, 1e-5, 1e-4 (falling as 1/eps; the twist modes' rows carry the largest |q|); truncation,
// eps^2 f''' / 6, is ~1e-9 at 1e-4 (the rigid chains, whose round-off is smaller). Measured at 1e-4:
// at most 1.8e-9 (rigid), 3.9e-9 (flexible chain), 9.5e-9 (joint model; loads 1.7e-9), printed. A
// missing term (J_l^-1's or J_l's derivative, the moment transport along a chain, the follower's
// rotation) is 0.1..1 of the largest entry (J_l^-1's derivative but its constant part dropped: 0.13-0.2
// on the rigid chains; J_l's: ~1 on the flexible ones). Asserted: 1e-7. The assembled K against the
// assembly's own differences (fd_joint_jacobians, step 1e-6 of FfrfSystem::weight's scale) is compared
// relative to the largest entry of the elements' tangents, without the columns of the twist modes.
#include "ffrf/ffrf_joint_tangents.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <cmath>
#include <cstdio>

#include "beam_superelement.hpp"
#include "ffrf/ffrf_detail.hpp"
#include "mbd_models.hpp"
#include "pendulum_reference.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/ffrf/ffrf.hpp"

using namespace seflex;
using namespace seflex::mbd;
using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using mbd::detail::Vector6d;

namespace {

/// A coordinate's scale: its natural scale (1 / FfrfSystem::weight), for a mode the larger of its largest
/// interface translation and rotation per unit amplitude (FfrfSystem::weight has the translation only, so
/// a mode that turns the interfaces without moving them, the twist of a beam with rotary inertia, gets a
/// step of ~1e6 L there: docs/ffrf.md "Limits").
double coordinate_scale(const FfrfSystem& sys, int col) {
  if (sys.kind[static_cast<std::size_t>(col)] != 'e') return 1.0 / sys.weight[col];
  const FfrfBody& b = sys.bodies[static_cast<std::size_t>(sys.owner[static_cast<std::size_t>(col)])];
  const Eigen::Index i = col - b.coord - 6;
  return 1.0 / std::max(sys.weight[col],
                        b.V.col(i).head(6 * static_cast<Eigen::Index>(b.nodes.size())).cwiseAbs().maxCoeff());
}

/// A state off the initial one (trial-dependent, deterministic): frames moved by 0.1 m and turned by
/// up to `turn` rad per axis, hinge angles by up to `turn` rad, modes at `deform` of their natural
/// scale, velocities, multipliers of 50.
FfrfState random_state(const FfrfSystem& sys, int trial, double turn, double deform) {
  FfrfState s = ffrf_initial_state(sys);
  int c = 0;
  auto r = [trial, &c]() { return std::sin(1.3 + 2.7 * c++ + 0.9 * trial); };
  auto r3 = [&r]() { return Vector3d(r(), r(), r()); };
  for (std::size_t b = 0; b < sys.bodies.size(); ++b) {
    s.p_WB[b] += 0.1 * r3();
    s.R_WB[b] = so3::exp(turn * r3()) * s.R_WB[b];
  }
  for (const FfrfBody& b : sys.bodies)
    for (int i = 0; i < b.k; ++i) s.z[b.z_offset + i] = deform * r() * coordinate_scale(sys, b.coord + 6 + i);
  for (Eigen::Index i = 0; i < s.phi.size(); ++i) s.phi[i] += turn * r();
  for (Eigen::Index i = 0; i < s.v.size(); ++i) s.v[i] = r() / sys.weight[i];
  for (Eigen::Index i = 0; i < s.lambda.size(); ++i) s.lambda[i] = 50.0 * r();
  return s;
}

/// Central differences of q(s) (over `cols`) w.r.t. the coordinates cols (>= 0), as a dense matrix: step
/// 1e-4 of the coordinate's scale.
template <class Q>
MatrixXd central_differences(const FfrfSystem& sys, FfrfState& s, const std::vector<int>& cols, Q&& q) {
  const auto n = static_cast<Eigen::Index>(cols.size());
  MatrixXd D = MatrixXd::Zero(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const int col = cols[static_cast<std::size_t>(j)];
    if (col < 0) continue;
    const double eps = 1e-4 * coordinate_scale(sys, col);
    detail::Saved sv = detail::perturb(sys, s, col, eps);
    const VectorXd qp = q();
    detail::restore(sys, s, col, sv);
    sv = detail::perturb(sys, s, col, -eps);
    const VectorXd qm = q();
    detail::restore(sys, s, col, sv);
    D.col(j) = (qp - qm) / (2.0 * eps);
  }
  return D;
}

/// The analytic tangent without the rows and columns of driven hinges (negative columns).
MatrixXd configuration_part(const MatrixXd& K, const std::vector<int>& cols) {
  MatrixXd A = K;
  for (std::size_t i = 0; i < cols.size(); ++i)
    if (cols[i] < 0) {
      A.row(static_cast<Eigen::Index>(i)).setZero();
      A.col(static_cast<Eigen::Index>(i)).setZero();
    }
  return A;
}

double relative(const MatrixXd& A, const MatrixXd& F) {
  return (A - F).cwiseAbs().maxCoeff() / F.cwiseAbs().maxCoeff();
}

/// The load's world wrench at s (as the assembly's).
Vector6d load_wrench(const NodeLoad& load, const detail::PoseJ& P, double t) {
  const double f = load.scale ? load.scale(t) : 1.0;
  Vector6d F;
  F.head<3>() = f * (load.follower ? Vector3d(P.R * load.force) : load.force);
  F.tail<3>() = f * (load.follower ? Vector3d(P.R * load.moment) : load.moment);
  return F;
}

struct Worst {
  double constraint = 0, load = 0, assembled = 0;
  double largest = 0;  ///< the largest entry of the elements' tangents (the assembled K's bodies' part is larger)
  int chains = 0, welds = 0, loads = 0, skipped = 0;
};

Worst compare(const Model& model, int trial, double turn, double deform) {
  FfrfOptions fo;
  const FfrfSystem sys = make_ffrf_system(model, fo);
  FfrfState s = random_state(sys, trial, turn, deform);
  Worst worst;
  detail::ConstraintEval ce;
  detail::JointTangentScratch w;
  for (std::size_t c = 0; c < sys.constraints.size(); ++c) {
    const Vector6d lam = s.lambda.segment<6>(6 * static_cast<Eigen::Index>(c));
    detail::eval_constraint(sys, s, static_cast<int>(c), ce);
    detail::constraint_tangent(sys, s, sys.constraints[c], ce, lam, w);
    const std::vector<int> cols = ce.cols;
    const MatrixXd K = configuration_part(w.K.topLeftCorner(ce.size(), ce.size()), cols);
    detail::ConstraintEval cp;
    const MatrixXd F = central_differences(sys, s, cols, [&] {
      detail::eval_constraint(sys, s, static_cast<int>(c), cp);
      EXPECT_EQ(cp.cols, cols);
      return VectorXd(cp.jacobian().transpose() * lam);
    });
    worst.constraint = std::max(worst.constraint, relative(K, configuration_part(F, cols)));
    worst.largest = std::max(worst.largest, F.cwiseAbs().maxCoeff());
    (sys.constraints[c].chain ? worst.chains : worst.welds)++;
  }
  detail::PoseJ P;
  for (const NodeLoad& load : model.loads) {
    detail::node_pose(sys, s, load.node.value, false, P);
    detail::load_tangent(sys, s, load, P, load_wrench(load, P, s.t), w);
    const std::vector<int> cols = P.cols;
    const MatrixXd K = configuration_part(w.K.topLeftCorner(P.size(), P.size()), cols);
    detail::PoseJ Pp;
    const MatrixXd F = central_differences(sys, s, cols, [&] {
      detail::node_pose(sys, s, load.node.value, false, Pp);
      return VectorXd(-(Pp.jacobian().transpose() * load_wrench(load, Pp, s.t)));
    });
    worst.load = std::max(worst.load, relative(K, configuration_part(F, cols)));
    worst.largest = std::max(worst.largest, F.cwiseAbs().maxCoeff());
    ++worst.loads;
  }
  // The assembled K: analytic joints and loads against fd_joint_jacobians (the bodies' K the same),
  // relative to the largest entry of the joints' and loads' tangents.
  fo.fd_joint_jacobians = true;
  const FfrfSystem sf = make_ffrf_system(model, fo);
  detail::FfrfEval ea, ef;
  detail::ffrf_assemble(sys, s, true, ea);
  detail::ffrf_assemble(sf, s, true, ef);
  EXPECT_EQ((ea.r - ef.r).cwiseAbs().maxCoeff(), 0.0);
  const int n = sys.num_coords;
  Eigen::SparseMatrix<double> Ka(n, n), Kf(n, n);
  Ka.setFromTriplets(ea.K.begin(), ea.K.end());
  Kf.setFromTriplets(ef.K.begin(), ef.K.end());
  // Without the columns of modes whose library step fd_step is meaningless (the twist modes above).
  MatrixXd A(Ka), F(Kf);
  for (int j = 0; j < n; ++j)
    if (detail::fd_step(sys, j) > 1e-6 * coordinate_scale(sys, j) * 1e3) {
      A.col(j).setZero();
      F.col(j).setZero();
      ++worst.skipped;
    }
  worst.assembled = (A - F).cwiseAbs().maxCoeff() / worst.largest;
  return worst;
}

void check(const char* what, const Model& model) {
  for (int trial = 0; trial < 3; ++trial)
    for (const auto& [turn, deform] : {std::pair{0.3, 0.05}, std::pair{0.6, 0.5}, std::pair{1e-3, 0.05}}) {
      const Worst e = compare(model, trial, turn, deform);
      std::printf("%s, trial %d, turn %.0e, deformation %.0e: %d chain and %d welded constraints: max rel. error "
                  "%.2e; %d loads: %.2e; assembled K: %.2e (%d twist columns left out)\n",
                  what, trial, turn, deform, e.chains, e.welds, e.constraint, e.loads, e.load, e.assembled, e.skipped);
      EXPECT_LT(e.constraint, 1e-7) << what;
      EXPECT_LT(e.load, 1e-7) << what;
      EXPECT_LT(e.assembled, 1e-7) << what;
    }
}

/// Three flexible CB links (2 fixed-interface modes) and a rigid one, in 3D: H1 on the ground; H2 about a
/// skew axis on a node attached to link 1's tip with an offset (a chain of two levels to the body);
/// link 3 welded to link 2's tip (a constraint between two bodies' interfaces); a driven hinge H3 at
/// link 3's tip carrying a rigid link; follower and fixed-direction loads on a body's node, the offset
/// node and the rigid link's tip, one scaled in time.
Model joint_model() {
  test::BeamSection sec;
  sec.E = 7e9;
  auto fe = test::straight_beam(1.0, 4, sec);
  const se::Superelement s = test::craig_bampton(fe, {0, 4}, 2, 2, "link");
  ModelBuilder mb;
  const auto sei = mb.add_superelement(s);
  const Matrix3d I = Matrix3d::Identity();
  FlexibleBodyOptions fo;
  fo.inertia = InertiaModel::Full;
  const auto g = mb.add_ground("ground", Pose{});
  const auto h1 = mb.add_hinge("H1", g, Vector3d::UnitZ());
  const auto n1 = mb.add_node("n1", Pose{I, Vector3d(1.0, 0, 0)});
  mb.add_flexible_body("link1", sei, {mb.hinge_child(h1), n1}, Pose{I, Vector3d(0.5, 0, 0)}, fo);
  const auto a1 = mb.add_attached_node("a1", n1, Pose{I, Vector3d(1.0, 0.1, 0)});
  HingeOptions o2;
  o2.phi0 = 0.0;
  const auto h2 = mb.add_hinge("H2", a1, Vector3d(0, 1, 1).normalized(), o2);
  const auto n2 = mb.add_node("n2", Pose{I, Vector3d(2.0, 0.1, 0)});
  mb.add_flexible_body("link2", sei, {mb.hinge_child(h2), n2}, Pose{I, Vector3d(1.5, 0.1, 0)}, fo);
  const auto n3 = mb.add_node("n3", Pose{I, Vector3d(3.0, 0.1, 0)});
  mb.add_flexible_body("link3", sei, {n2, n3}, Pose{I, Vector3d(2.5, 0.1, 0)}, fo);
  HingeOptions o3;
  o3.drive = [](double t) { return DriveValue{0.4 + 0.5 * t, 0.5, 0.0}; };
  const auto h3 = mb.add_hinge("H3", n3, Vector3d(1, 0, 1).normalized(), o3);
  const auto r4 = mb.add_rigid_body("link4", sei, mb.hinge_child(h3), 0, Pose{I, Vector3d(3.5, 0.1, 0)});
  const auto tip = mb.rigid_body(r4).nodes[1];
  mb.add_load(NodeLoad{"follower at n3", n3, Vector3d(3, -20, 7), Vector3d(-2, 5, 4), true, {}});
  mb.add_load(
      NodeLoad{"follower at a1", a1, Vector3d(-8, 4, 15), Vector3d(6, 1, -3), true, [](double t) { return 0.7 + t; }});
  mb.add_load(NodeLoad{"fixed at the tip", tip, Vector3d(5, 9, -4), Vector3d(1, -2, 3), false, {}});
  mb.add_load(NodeLoad{"follower at the tip", tip, Vector3d(-1, 2, 12), Vector3d(0.5, 3, -1), true, {}});
  mb.set_gravity(Vector3d(0, -9.81, 0));
  return mb.build();
}

}  // namespace

// d(J_l(theta)^T u)/dtheta and d(J_l^-1(theta)^T u)/dtheta against central differences of so3::jl and
// so3::jl_inv (step 1e-6: truncation ~1e-12, round-off ~1e-10), on both sides of the series switch
// (|theta|^2 = 0.1) and near zero.
TEST(FfrfJointTangents, LeftJacobianDerivativesMatchFiniteDifferences) {
  const Vector3d u(0.3, -1.2, 0.8), dir = Vector3d(0.6, -0.3, 0.9).normalized();
  for (double t : {0.0, 1e-5, 1e-2, 0.3, 0.316, 0.317, 0.5, 1.0, 2.0, 3.0}) {
    const Vector3d th = t * dir + Vector3d(0.0, 1e-3 * t, 0.0);
    Matrix3d Fl, Fi;
    const double h = 1e-6;
    for (int j = 0; j < 3; ++j) {
      const Vector3d e = h * Vector3d::Unit(j);
      Fl.col(j) = (so3::jl(th + e).transpose() * u - so3::jl(th - e).transpose() * u) / (2 * h);
      Fi.col(j) = (so3::jl_inv(th + e).transpose() * u - so3::jl_inv(th - e).transpose() * u) / (2 * h);
    }
    const double el = (detail::jl_transpose_tangent(th, u) - Fl).cwiseAbs().maxCoeff() / Fl.cwiseAbs().maxCoeff();
    const double ei = (detail::jl_inv_transpose_tangent(th, u) - Fi).cwiseAbs().maxCoeff() / Fi.cwiseAbs().maxCoeff();
    std::printf("|theta| = %.3g: J_l^T u %.1e, J_l^-T u %.1e\n", th.norm(), el, ei);
    EXPECT_LT(el, 1e-8) << t;
    EXPECT_LT(ei, 1e-8) << t;
  }
}

// (a) rigid pendulum chains: the rigid double pendulum and the CB chain made rigid.
TEST(FfrfJointTangents, RigidChainsMatchFiniteDifferences) {
  check("double pendulum", test::double_pendulum());
  test::ChainOptions o;
  o.bodies = 3;
  o.rigid = true;
  o.axis = Vector3d(0.2, 0.3, 1.0).normalized();
  check("rigid chain of 3", test::pendulum_chain(o));
}

// (b) flexible bodies whose interfaces rotate with the modes (J_l of the elastic rotation), hinged
// through a parent that a body carries: the CB chain with fixed-interface modes.
TEST(FfrfJointTangents, FlexibleChainMatchesFiniteDifferences) {
  test::ChainOptions o;
  o.bodies = 3;
  o.modes = 2;
  o.section.E = 7e9;
  o.inertia = InertiaModel::Full;
  o.axis = Vector3d(0.2, 0.3, 1.0).normalized();
  check("flexible chain of 3", test::pendulum_chain(o));
}

// (c) a node through two levels of parents, a welded pair of interfaces, a driven hinge, and (d)
// follower and fixed-direction node loads on a body's node, an attached node and a rigid link's node.
TEST(FfrfJointTangents, ChainsWeldsDrivenHingesAndLoadsMatchFiniteDifferences) {
  const Model model = joint_model();
  const FfrfSystem sys = make_ffrf_system(model, FfrfOptions{});
  int welds = 0, deep = 0;
  for (const FfrfConstraint& c : sys.constraints) {
    welds += !c.chain;
    const Node& n = model.nodes[static_cast<std::size_t>(c.node.value)];
    if (c.chain && model.nodes[static_cast<std::size_t>(n.parent.value)].kind == NodeKind::Attached &&
        sys.node_source[static_cast<std::size_t>(n.parent.value)].kind == FfrfNodeSource::Kind::Chain)
      ++deep;
  }
  ASSERT_EQ(welds, 1);
  ASSERT_EQ(deep, 1);
  check("joint model", model);
}
