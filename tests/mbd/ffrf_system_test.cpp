// FFRF-LM system checks: the body's inertia against the superelement file's mass properties, the
// Newton iteration matrix against central finite differences of the step residual, and the
// conditioning of the multiplier system as the step shrinks, with and without scaling.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "mbd_models.hpp"
#include "pendulum_reference.hpp"
#include "seflex/mbd/ffrf/ffrf.hpp"

using namespace seflex;
using namespace seflex::mbd;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {

test::ChainOptions chain() {
  test::ChainOptions o;
  o.bodies = 2;
  o.elements = 4;
  o.section.E = 7e9;
  o.inertia = InertiaModel::Full;
  return o;
}

}  // namespace

// Kinetic energy of a rigid motion (v of the frame origin, omega) of an undeformed flexible body,
// computed by the FFRF kernel from the FE nodal mass (N^T M_fe N at z = 0), against the mass
// properties the superelement file states (mass, centre of mass, inertia about it: computed by the
// reduction from the full FE model): 1/2 m |v + w x c|^2 + 1/2 w . I_c w.
TEST(FfrfSystem, RigidKineticEnergyMatchesTheFileMassProperties) {
  test::ChainOptions o = chain();
  auto fe = test::straight_beam(o.length, o.elements, o.section);
  const se::Superelement s = test::craig_bampton(fe, {0, o.elements}, o.elements / 2, 0, "link");
  const Model model = test::pendulum_chain(o);
  const FfrfSystem sys = make_ffrf_system(model, FfrfOptions{});
  FfrfState st = ffrf_initial_state(sys);
  const Vector3d v(0.3, -1.1, 0.7), w(2.0, -0.5, 1.3);
  st.v.setZero();
  st.v.segment<3>(sys.bodies[0].coord) = v;
  st.v.segment<3>(sys.bodies[0].coord + 3) = w;
  const Sample smp = ffrf_sample(sys, st);
  const Eigen::Matrix3d& R = st.R_WB[0];
  const Vector3d c = R * s.p_BoCm_B;
  const double T_ref = 0.5 * s.mass * (v + w.cross(c)).squaredNorm() + 0.5 * w.dot(R * s.I_Cm_B * R.transpose() * w);
  std::printf("rigid kinetic energy: FFRF %.12f J, file mass properties %.12f J\n", smp.flexible[0].kinetic, T_ref);
  EXPECT_NEAR(smp.flexible[0].kinetic, T_ref, 1e-10 * T_ref);
  EXPECT_EQ(smp.flexible[1].kinetic, 0.0);
}

// The iteration matrix of one step (analytic mass matrices, constraint Jacobians and body tangents,
// the joints' geometric stiffness by element-wise finite differences, Lie tangent J_l(h Dq), scaling)
// against central differences of the whole step residual R(x), x = [h Dq; mu], at a state in motion
// with nonzero multipliers (measured: 6.1e-7 scaled, 7.5e-13 unscaled; 3.0e-10 unscaled with the
// bodies' finite differences).
TEST(FfrfSystem, IterationMatrixMatchesFiniteDifferences) {
  const Model model = test::pendulum_chain(chain());
  for (bool scaled : {true, false}) {
    FfrfOptions fo;
    fo.scale_constraints = scaled;
    const FfrfSystem sys = make_ffrf_system(model, fo);
    FfrfState s0 = ffrf_initial_state(sys);
    s0.v += 0.1 * VectorXd::Ones(s0.v.size());  // in motion (need not satisfy the constraints for this check)
    const double h = 2e-3, rho = 0.8;
    const int n = sys.num_coords + sys.num_multipliers();
    VectorXd x(n);
    x.head(sys.num_coords) = h * s0.v;
    for (int i = 0; i < sys.num_coords; ++i) x[i] += 1e-4 * std::sin(1.0 + i) / sys.weight[i];  // off the predictor
    x.tail(sys.num_multipliers()) = (scaled ? 0.25 * h * h : 1.0) * s0.lambda;
    FfrfState s1;
    VectorXd R, Rp, Rm;
    Eigen::SparseMatrix<double> S;
    ffrf_step_system(sys, s0, h, rho, x, s1, R, &S);
    const Eigen::MatrixXd A(S);
    Eigen::MatrixXd F(n, n);
    for (int j = 0; j < n; ++j) {
      const double d = 1e-6 * (j < sys.num_coords ? 1.0 / sys.weight[j] : std::max(1e-3, std::abs(x[j])));
      VectorXd xp = x, xm = x;
      xp[j] += d;
      xm[j] -= d;
      ffrf_step_system(sys, s0, h, rho, xp, s1, Rp, nullptr);
      ffrf_step_system(sys, s0, h, rho, xm, s1, Rm, nullptr);
      F.col(j) = (Rp - Rm) / (2 * d);
    }
    const double err = (A - F).cwiseAbs().maxCoeff() / A.cwiseAbs().maxCoeff();
    std::printf("%s: iteration matrix %dx%d, max |S - S_fd| / max |S| = %.2e\n", scaled ? "scaled" : "unscaled", n, n, err);
    // Scaled, the multipliers' unknowns are beta h^2 lambda ~ 1e-6 lambda and their difference step
    // (1e-6 of |x|) is tiny: the round-off of the differences is ~1e-7..1e-6 there. Unscaled every step
    // is of its unknown's size and the differences are good to ~1e-12 (measured 7.5e-13).
    EXPECT_LT(err, scaled ? 1e-6 : 1e-10);
  }
}

// Issue 7: the conditioning of the Lagrange-multiplier system as the step shrinks. Unscaled, the
// iteration matrix [M/(beta h^2) + ..., G^T; G, 0] has a 2-norm condition growing like h^-4 (its
// largest singular values ~ |M|/(beta h^2), its smallest ~ beta h^2 |G|^2/|M| from the Schur
// complement; Bottasso, Bauchau and Cardona 2007); with the beta h^2 scaling it stays bounded.
// Rigid double pendulum, 10 constant steps each (measured: 46 for every h scaled; 8e9, 8e13 and
// 1.5e17 = 1/eps unscaled).
TEST(FfrfSystem, ScalingKeepsTheConditionBoundedAsTheStepShrinks) {
  const Model model = test::double_pendulum();
  auto cond = [&](double h, bool scaled) {
    IntegratorSettings st;
    st.t_end = 10 * h;
    st.h_initial = h;
    st.adaptive = false;
    st.reuse_iteration_matrix = false;
    FfrfOptions fo;
    fo.scale_constraints = scaled;
    fo.condition_estimate = true;
    return simulate_ffrf(model, st, fo).condition_max;
  };
  std::vector<double> c_s, c_u;
  for (double h : {1e-2, 1e-3, 1e-4}) {
    c_s.push_back(cond(h, true));
    c_u.push_back(cond(h, false));
    std::printf("h %.0e: condition scaled %.3e, unscaled %.3e\n", h, c_s.back(), c_u.back());
  }
  EXPECT_GT(c_u[1] / c_u[0], 1e3);  // h^-4: 1e4 per decade (h^-2 would give 1e2)
  EXPECT_GT(c_u[2], 1e15);          // at h = 1e-4 s the unscaled system is numerically singular
  EXPECT_LT(c_s[2] / c_s[0], 10.0);
}

// Issue 12: FFRF-LM's flexible bodies take their inertia from the superelement's inertia invariants
// (a cost set by the reduced size) instead of summing over the FE nodes; the nodal sums stay as the
// reference. The step residual and iteration matrix of both, at states off the predictor with
// velocities, elastic deformation and nonzero multipliers, for the flexible chain (full inertia, CB
// beams with lumped translational and rotary mass). The nodal sums without the one term the
// invariants leave out (the gyroscopic moment quadratic in the elastic rotation rates,
// docs/inertia-invariants.md) agree to round-off; that term (measured 4e-5..8e-5 of max |R|) is far
// above the round-off bound: a term of its size missing from the invariants would be caught.
TEST(FfrfSystem, InvariantInertiaEqualsTheNodalSums) {
  const Model model = test::pendulum_chain(chain());
  FfrfOptions fi, fn, fg;
  fi.inertia = FfrfOptions::Inertia::Invariants;
  fn.inertia = fg.inertia = FfrfOptions::Inertia::Nodal;
  fg.elastic_gyro = true;
  const FfrfSystem si = make_ffrf_system(model, fi), sn = make_ffrf_system(model, fn), sg = make_ffrf_system(model, fg);
  ASSERT_EQ(si.num_coords, sn.num_coords);
  ASSERT_GT(si.num_z, 0);
  for (int trial = 0; trial < 3; ++trial) {
    FfrfState s0 = ffrf_initial_state(si);
    for (Eigen::Index i = 0; i < s0.v.size(); ++i) s0.v[i] += (0.5 + trial) * std::sin(2.0 + 3.0 * i + trial);
    for (Eigen::Index i = 0; i < s0.z.size(); ++i) s0.z[i] = trial == 0 ? 0.0 : 1e-3 * std::cos(1.0 + i + trial);
    const double h = 2e-3, rho = 0.8;
    const int n = si.num_coords + si.num_multipliers();
    VectorXd x(n);
    x.head(si.num_coords) = h * s0.v;
    for (int i = 0; i < si.num_coords; ++i)
      x[i] += 1e-3 * std::sin(1.0 + i + trial) * (si.kind[static_cast<std::size_t>(i)] == 'e' ? 1.0 : 1.0 / si.weight[i]);
    x.tail(si.num_multipliers()) = 0.25 * h * h * (s0.lambda + VectorXd::Constant(s0.lambda.size(), 10.0));
    FfrfState s1;
    VectorXd Ri, Rn, Rg;
    Eigen::SparseMatrix<double> Si, Sn;
    ffrf_step_system(si, s0, h, rho, x, s1, Ri, &Si);
    ffrf_step_system(sn, s0, h, rho, x, s1, Rn, &Sn);
    ffrf_step_system(sg, s0, h, rho, x, s1, Rg, nullptr);
    const double eR = (Ri - Rn).cwiseAbs().maxCoeff() / Rn.cwiseAbs().maxCoeff();
    const Eigen::MatrixXd Ai(Si), An(Sn);
    const double eS = (Ai - An).cwiseAbs().maxCoeff() / An.cwiseAbs().maxCoeff();
    const double dropped = (Rg - Rn).cwiseAbs().maxCoeff() / Rn.cwiseAbs().maxCoeff();
    std::printf("trial %d: max |R_inv - R_nodal| / max |R| = %.2e, iteration matrix %.2e; the elastic-gyro term %.2e\n", trial, eR,
                eS, dropped);
    EXPECT_LT(eR, 1e-14);  // round-off of sums in another order (measured 5e-19..2e-18)
    EXPECT_GT(dropped, 1e-6);
    // The bodies' stiffness and gyroscopic parts are analytic (ffrf_body_tangents.cpp; measured
    // 1.5e-18). With FfrfOptions::fd_body_jacobians they are central differences of the body force
    // (step 1e-6 of each coordinate's scale): round-off differences of the force (1e-15) become
    // 7e-13..5e-12 there.
    EXPECT_LT(eS, 1e-14);
  }
}
