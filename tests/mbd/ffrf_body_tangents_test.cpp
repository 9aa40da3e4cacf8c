// FFRF-LM body tangents (mbd/src/ffrf/ffrf_body_tangents.cpp): the analytic configuration and
// velocity derivatives K = df/dq (rotation increments R <- exp(dpi~) R) and C = df/dv of every body
// force against the central differences the assembly used before (FfrfOptions::fd_body_jacobians,
// kept as this reference), at random states with velocities, accelerations, rotated frames and
// elastic deformation. The multipliers are zero, so that the assembled K and C are the bodies' only.
//
// Error of the reference: central differences with step eps = 1e-6 of each coordinate's natural
// scale; the force is quadratic in the velocities (exact there but for round-off) and smooth in the
// configuration (truncation eps^2 f''' / 6 ~ 1e-12 relative); round-off ~1e-16 |f| / eps ~ 1e-10 of
// |f| per unit scale. So the two agree to ~1e-9 of the largest entry when the analytic tangents are
// exact; a missing term (e.g. the gyroscopic moment's, the stiffening's spin dependence) is 1e-4..1.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "fem_models.hpp"
#include "ffrf/ffrf_detail.hpp"
#include "mbd_models.hpp"
#include "pendulum_reference.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/ffrf/ffrf.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"

using namespace seflex;
using namespace seflex::mbd;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {

MatrixXd dense(const std::vector<Eigen::Triplet<double>>& T, int n) {
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(T.begin(), T.end());
  return MatrixXd(A);
}

/// A state off the initial one: frames moved and turned, modes deformed, velocities and accelerations
/// of the size of the model's natural scales (trial-dependent, deterministic).
FfrfState random_state(const FfrfSystem& sys, int trial) {
  FfrfState s = ffrf_initial_state(sys);
  int c = 0;
  auto r = [trial, &c]() { return std::sin(1.3 + 2.7 * c++ + 0.9 * trial); };
  auto r3 = [&r]() {
    Vector3d x;
    for (int i = 0; i < 3; ++i) x[i] = r();
    return x;
  };
  for (std::size_t b = 0; b < sys.bodies.size(); ++b) {
    s.p_WB[b] += 0.1 * r3();
    s.R_WB[b] = so3::exp(r3()) * s.R_WB[b];
  }
  // Natural scales: m, rad; a mode's amplitude of unit largest interface translation or rotation.
  VectorXd scale = sys.weight.cwiseInverse();
  for (const FfrfBody& b : sys.bodies)
    for (int i = 0; i < b.k; ++i) {
      const int col = b.coord + 6 + i;
      scale[col] = 1.0 / std::max(sys.weight[col], b.V.col(i).head(6 * static_cast<Eigen::Index>(b.nodes.size())).cwiseAbs().maxCoeff());
      s.z[b.z_offset + i] = 0.05 * r() * scale[col];  // deformations of 5 % of that
    }
  for (Eigen::Index i = 0; i < s.v.size(); ++i) {
    s.v[i] = 2.0 * scale[i] * r();
    s.vdot[i] = 30.0 * scale[i] * r();
  }
  s.lambda.setZero();
  return s;
}

/// The largest |analytic - finite differences| of K and C, relative to max |finite differences| (K, C)
/// and to the reference's own error bound (Kb, Cb: below 1 when within it): the round-off of the
/// central differences, 64 eps max|f| / step_j in column j (eps max|f|: the round-off of one force
/// evaluation, max|f| the largest sum of absolute contributions to an equation, FfrfEval::scale), plus
/// 1e-9 of the largest entry (the truncation error).
struct Errors {
  double K = 0, C = 0, M = 0, Kb = 0, Cb = 0;
};

Errors compare(const Model& model, FfrfOptions fo, int trial) {
  fo.fd_body_jacobians = false;
  const FfrfSystem sa = make_ffrf_system(model, fo);
  fo.fd_body_jacobians = true;
  const FfrfSystem sf = make_ffrf_system(model, fo);
  FfrfState s = random_state(sa, trial);
  mbd::detail::FfrfEval ea, ef;
  mbd::detail::ffrf_assemble(sa, s, true, ea);
  mbd::detail::ffrf_assemble(sf, s, true, ef);
  const int n = sa.num_coords;
  const MatrixXd Ka = dense(ea.K, n), Kf = dense(ef.K, n), Ca = dense(ea.C, n), Cf = dense(ef.C, n);
  const MatrixXd Ma = dense(ea.M, n), Mf = dense(ef.M, n);
  EXPECT_EQ((ea.r - ef.r).cwiseAbs().maxCoeff(), 0.0);  // the same residual
  const double fmax = ef.scale.cwiseAbs().maxCoeff();
  auto bound_ratio = [&](const MatrixXd& A, const MatrixXd& F) {
    double r = 0;
    for (int j = 0; j < n; ++j) {
      const double b = 64.0 * 2.2e-16 * fmax / (1e-6 / sa.weight[j]) + 1e-9 * F.cwiseAbs().maxCoeff();
      r = std::max(r, (A.col(j) - F.col(j)).cwiseAbs().maxCoeff() / b);
    }
    return r;
  };
  Errors e;
  e.K = (Ka - Kf).cwiseAbs().maxCoeff() / Kf.cwiseAbs().maxCoeff();
  e.C = (Ca - Cf).cwiseAbs().maxCoeff() / Cf.cwiseAbs().maxCoeff();
  e.M = (Ma - Mf).cwiseAbs().maxCoeff() / Mf.cwiseAbs().maxCoeff();
  e.Kb = bound_ratio(Ka, Kf);
  e.Cb = bound_ratio(Ca, Cf);
  return e;
}

void check(const char* what, const Model& model, const FfrfOptions& fo) {
  for (int trial = 0; trial < 3; ++trial) {
    const Errors e = compare(model, fo, trial);
    std::printf("%s, trial %d: max |K - K_fd| / max |K_fd| = %.2e (%.2f of the bound), C %.2e (%.2f of the bound), M %.1e\n", what,
                trial, e.K, e.Kb, e.C, e.Cb, e.M);
    EXPECT_LT(e.Kb, 1.0) << what;
    EXPECT_LT(e.Cb, 1.0) << what;
    EXPECT_LT(e.K, 1e-7) << what;
    EXPECT_LT(e.C, 1e-7) << what;
    EXPECT_EQ(e.M, 0.0) << what;
  }
}

test::ChainOptions chain() {
  test::ChainOptions o;
  o.bodies = 2;
  o.elements = 4;
  o.modes = 2;  // fixed-interface modes too: eta in the frame-clamped modes
  o.section.E = 7e9;
  o.inertia = InertiaModel::Full;
  return o;
}

Model damped(Model m) {
  for (FlexibleBody& fb : m.flexible_bodies) fb.options.stiffness_damping = 2e-3;
  return m;
}

/// A 2 m beam of 8 CBARs reduced by the production reduction (stiffening invariants, FE data), hanging
/// from a driven hub with a free tip, in gravity.
Model stiffened_beam() {
  fem::Model m;
  const int ne = 8;
  for (int i = 0; i <= ne; ++i) test::add_grid(m, i + 1, 2.0 * i / ne, 0, 0);
  test::add_mat1(m, 1, 7e9, 0.3, 2700.0);
  test::add_pbar(m, 1, 1, 1e-3, 2e-7, 3e-7, 4e-7);
  for (int i = 0; i < ne; ++i) test::add_cbar(m, i + 1, 1, i + 1, i + 2, {0, 0, 1});
  // Point masses without rotary inertia: a torsion mode would carry mass but no translation, and the
  // finite differences' step (1e-6 of the largest translation per unit mode) would be meaningless.
  for (int i = 0; i <= ne; ++i) fem::test::add_conm2(m, 1000 + i, i + 1, 0.01);
  test::finalize_for_test(m);
  reduction::SuperelementOptions o;
  o.interface_ids = {1, ne + 1};
  o.modes.modes = 3;
  o.name = "beam";
  const se::Superelement s = reduction::reduce_to_superelement(m, o);
  EXPECT_TRUE(s.stiffening.present());
  ModelBuilder mb;
  const auto sei = mb.add_superelement(s);
  const auto g = mb.add_ground("hub axis", Pose{});
  const auto h = mb.add_hinge("hub", g, Vector3d::UnitZ());
  const auto tip = mb.add_node("tip", Pose{Eigen::Matrix3d::Identity(), Vector3d(2.0, 0, 0)});
  FlexibleBodyOptions fo;
  fo.inertia = InertiaModel::Full;
  fo.geometric_stiffening = true;
  fo.stiffness_damping = 1e-3;
  mb.add_flexible_body("beam", sei, {mb.hinge_child(h), tip}, Pose{Eigen::Matrix3d::Identity(), s.p_OBo}, fo);
  mb.set_gravity(Vector3d(0.5, -9.81, 1.0));
  return mb.build();
}

}  // namespace

// The flexible chain of CB beams (full inertia; lumped translational and rotary FE mass), with
// stiffness-proportional damping: the inertia from the invariants and from the FE node sums (with and
// without the elastic-gyro term, which only the node sums have).
TEST(FfrfBodyTangents, FlexibleChainMatchesFiniteDifferences) {
  const Model model = damped(test::pendulum_chain(chain()));
  FfrfOptions fi, fn, fg;
  fi.inertia = FfrfOptions::Inertia::Invariants;
  fn.inertia = fg.inertia = FfrfOptions::Inertia::Nodal;
  fg.elastic_gyro = true;
  check("chain, invariants", model, fi);
  check("chain, nodal sums", model, fn);
  check("chain, nodal sums with the elastic gyro", model, fg);
}

// A body with geometric stiffening (load factors from the frame's accelerations and spin, the
// interface deformation's potential) and gravity.
TEST(FfrfBodyTangents, StiffenedBeamMatchesFiniteDifferences) {
  const Model model = stiffened_beam();
  ASSERT_TRUE(model.stiffened(model.flexible_bodies[0]));
  for (auto inertia : {FfrfOptions::Inertia::Invariants, FfrfOptions::Inertia::Nodal}) {
    FfrfOptions fo;
    fo.inertia = inertia;
    const FfrfSystem sys = make_ffrf_system(model, fo);
    ASSERT_TRUE(sys.bodies[0].stiffening);
    check(inertia == FfrfOptions::Inertia::Nodal ? "stiffened beam, nodal sums" : "stiffened beam, invariants", model, fo);
  }
}

// Rigid bodies: the flexible chain made rigid (rigid-LM) and the rigid double pendulum.
TEST(FfrfBodyTangents, RigidBodiesMatchFiniteDifferences) {
  FfrfOptions fr;
  fr.rigid = true;
  check("chain, rigid-LM", test::pendulum_chain(chain()), fr);
  check("double pendulum", test::double_pendulum(), FfrfOptions{});
}
