// Rigid double pendulum against an independent reference time history, and second-order
// convergence of the integrator in the step size on a flexible pendulum chain.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "mbd_models.hpp"
#include "pendulum_reference.hpp"
#include "seflex/mbd/solvers/explicit_integrator.hpp"
#include "seflex/mbd/solvers/integrator.hpp"
#include "test_support.hpp"

using namespace seflex;
using namespace seflex::mbd;
using Eigen::Matrix3d;
using Eigen::Vector3d;

using test::double_pendulum;
using test::read_reference;

// Reference: tests/data/mbd/double_pendulum_reference.csv (double_pendulum_reference.py: Lagrange's
// equations in absolute angles, scipy DOP853 at rtol = atol = 1e-12; independent of seflex).
// Tolerances per quantity: angles 2e-5 rad, rates 2e-4 rad/s, energy 2e-6 relative (the integrator
// runs at a local error tolerance of 1e-9; the motion reaches 12 rad/s). The energy error is
// measured against the potential-energy scale (m1 + m2) g L = 19.6 J: the total is nearly zero.
TEST(Pendulum, RigidDoublePendulumMatchesReference) {
  const auto ref = read_reference("double_pendulum_reference.csv");
  ASSERT_EQ(ref.size(), 201u);
  const Model model = double_pendulum();
  ASSERT_EQ(model.num_dofs, 2);  // two hinge angles: minimal coordinates
  State s = initial_state(model);
  Data data(model);
  IntegratorSettings st;
  st.t_end = 2.0;
  st.output_interval = 0.01;
  st.h_initial = 1e-3;
  st.tol_angle = st.tol_position = 1e-9;
  st.rho_inf = 0.9;
  test::Recorder rec;
  const RunStats stats = simulate(model, s, data, st, &rec);
  ASSERT_EQ(rec.samples.size(), ref.size());
  const test::ReferenceErrors err = test::reference_errors(rec.samples, ref);
  const double e_phi = err.phi, e_w = err.rate, e_E = err.energy;
  std::printf("double pendulum: max errors phi %.2e rad, rate %.2e rad/s, energy %.2e; %ld steps, %ld Newton its\n", e_phi, e_w,
              e_E, stats.steps, stats.newton_iterations);
  EXPECT_LT(e_phi, 2e-5);
  EXPECT_LT(e_w, 2e-4);
  EXPECT_LT(e_E, 2e-6);
}

// Second-order convergence in the step size on a two-body flexible pendulum chain swinging under
// gravity from the horizontal. The links are stiff (E = 7e12 Pa: lowest elastic mode ~600 Hz) so
// that every elastic mode has omega h >> 1 over the steps tested and is removed by the numerical
// damping (rho_inf = 0.5) while the quasi-static elastic response remains. (With resolved-but-
// coarse elastic vibrations the error is dominated by their phase error, which is not yet in its
// asymptotic range at affordable steps.) Differences between successive halvings,
// |x(h) - x(h/2)| for x = (tip position, hinge angles) at t = 0.4 s, fall by 4 per halving.
TEST(Pendulum, FlexibleChainConvergesAtSecondOrder) {
  test::ChainOptions o;
  o.bodies = 2;
  o.elements = 2;
  o.section.E = 7e12;
  o.inertia = InertiaModel::Full;
  const Model model = test::pendulum_chain(o);
  auto run = [&](double h) {
    State s = initial_state(model);
    Data data(model);
    IntegratorSettings st;
    st.t_end = 0.4;
    st.h_initial = h;
    st.adaptive = false;
    st.rho_inf = 0.5;
    st.newton_residual_tol = 1e-11;
    st.newton_increment_tol = 1e-12;
    simulate(model, s, data, st);
    Eigen::VectorXd out(5);
    out << s.p_WN.back(), s.phi[0], s.phi[1];
    return out;
  };
  const double h0 = 8e-3;
  Eigen::VectorXd prev = run(h0);
  double d_prev = 0;
  for (int k = 1; k <= 4; ++k) {
    const Eigen::VectorXd x = run(h0 / (1 << k));
    const double d = (x - prev).norm();
    prev = x;
    if (k > 1) {
      const double ratio = d_prev / d;
      std::printf("h = %.2e: |x(h) - x(2h)| = %.3e, ratio %.2f\n", h0 / (1 << k), d, ratio);
      EXPECT_NEAR(ratio, 4.0, 0.3);
    }
    d_prev = d;
  }
}

// The explicit RK4 (mbd/explicit_integrator.hpp) on the same reference (see above): a constant step
// of 1 ms is far inside its stability limit (rates up to 12 rad/s) and its error, O(h^4), is below
// the tolerances of the implicit run; halving the step cuts the angle error by about 16.
TEST(Pendulum, RigidDoublePendulumRk4MatchesReference) {
  const auto ref = read_reference("double_pendulum_reference.csv");
  const Model model = double_pendulum();
  auto max_error = [&](double h) {
    State s = initial_state(model);
    Data data(model);
    IntegratorSettings st;
    st.t_end = 2.0;
    st.output_interval = 0.01;
    st.h_initial = h;
    test::Recorder rec;
    simulate_rk4(model, s, data, st, &rec);
    EXPECT_EQ(rec.samples.size(), ref.size());
    double e = 0;
    for (std::size_t k = 0; k < std::min(ref.size(), rec.samples.size()); ++k)
      e = std::max({e, std::abs(rec.samples[k].hinges[0].phi - ref[k].phi1), std::abs(rec.samples[k].hinges[1].phi - ref[k].phi2)});
    return e;
  };
  const double e1 = max_error(2e-3), e2 = max_error(1e-3);
  std::printf("double pendulum rk4: max angle error %.2e rad (h = 2 ms), %.2e rad (1 ms), order %.2f\n", e1, e2, std::log2(e1 / e2));
  EXPECT_LT(e2, 2e-5);
  EXPECT_NEAR(std::log2(e1 / e2), 4.0, 0.5);
}
