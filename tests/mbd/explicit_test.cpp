// The explicit foil (Runge-Kutta-Munthe-Kaas 4, mbd/explicit_integrator.hpp): fourth-order
// convergence on a smooth flexible problem (Free nodes on the rotation group), and the stability
// limit of RK4 on the imaginary axis, |omega h| <= 2 sqrt(2) (Hairer and Wanner, Solving ODEs II,
// section IV.2), checked against the highest frequency of the linearised model: a step 10 % below
// the limit stays bounded, a step 3x above it blows up and is reported as a ConvergenceError
// (after the last good state was delivered), not a crash. (The linearised bound is conservative on
// this chain: runs stay bounded up to 1.6x it and blow up from 2x; docs/stability.md.)
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "mbd_models.hpp"
#include "seflex/common/error.hpp"
#include "seflex/mbd/assembly/assembly.hpp"
#include "seflex/mbd/solvers/explicit_integrator.hpp"

namespace seflex::test {
namespace {

using namespace seflex::mbd;

Model soft_chain(double E) {
  ChainOptions o;
  o.bodies = 2;
  o.elements = 2;
  o.section.E = E;
  o.inertia = InertiaModel::Full;
  return pendulum_chain(o);
}

// Differences of successive halvings |x(h) - x(h/2)| (tip position, hinge angles at t = 0.2 s)
// fall by 2^4 per halving. E = 7e8 Pa; h0 = 2 / omega_max (omega_max = 8.9e3 rad/s from the linearised model) is inside the stability limit.
TEST(ExplicitRk4, FlexibleChainConvergesAtFourthOrder) {
  const Model model = soft_chain(7e8);
  const double w = highest_frequency(model);
  auto run = [&](double h) {
    State s = initial_state(model);
    Data data(model);
    IntegratorSettings st;
    st.t_end = 0.2;
    st.h_initial = h;
    simulate_rk4(model, s, data, st);
    Eigen::VectorXd out(5);
    out << s.p_WN.back(), s.phi[0], s.phi[1];
    return out;
  };
  const double h0 = 2.0 / w;
  std::vector<Eigen::VectorXd> x;
  for (int k = 0; k < 4; ++k) x.push_back(run(h0 / std::pow(2.0, k)));
  const double d1 = (x[0] - x[1]).norm(), d2 = (x[1] - x[2]).norm(), d3 = (x[2] - x[3]).norm();
  std::printf("rk4 chain: omega_max %.3g rad/s, h0 %.3g s; differences %.3e %.3e %.3e, orders %.2f %.2f\n", w, h0, d1, d2, d3,
              std::log2(d1 / d2), std::log2(d2 / d3));
  EXPECT_NEAR(std::log2(d2 / d3), 4.0, 0.4);
  EXPECT_GT(std::log2(d1 / d2), 3.4);
}

TEST(ExplicitRk4, StabilityLimitOfTheHighestMode) {
  const Model model = soft_chain(7e9);
  const double h_crit = 2.0 * std::sqrt(2.0) / highest_frequency(model);
  auto run = [&](double h, Recorder* rec) {
    State s = initial_state(model);
    Data data(model);
    IntegratorSettings st;
    st.t_end = 400 * h;
    st.h_initial = h;
    st.output_interval = 20 * h;
    simulate_rk4(model, s, data, st, rec);
    return s;
  };
  Recorder stable;
  const State s = run(0.9 * h_crit, &stable);
  EXPECT_TRUE(s.v.allFinite());
  ASSERT_EQ(stable.samples.size(), 21u);  // every 20 steps of 400, and t = 0
  EXPECT_LT(stable.samples.back().energy.kinetic, 10.0);  // released from rest: kinetic <= m g L (5.3 J)
  // Bounded in the sense of the conservation law: no damping, so the total energy stays at its initial
  // value up to RK4's truncation error (measured 1.7e-6 J over the 0.11 s run, kinetic energy 0.29 J);
  // a growing mode would feed it.
  double drift = 0.0, kinetic = 0.0;
  for (const auto& smp : stable.samples) {
    drift = std::max(drift, std::abs(smp.energy.total() - stable.samples.front().energy.total()));
    kinetic = std::max(kinetic, smp.energy.kinetic);
  }
  EXPECT_GT(kinetic, 0.1);
  EXPECT_LT(drift, 1e-4 * kinetic);
  Recorder unstable;
  try {
    run(3.0 * h_crit, &unstable);
    ADD_FAILURE() << "a step 3x above the RK4 limit " << h_crit << " s did not blow up";
  } catch (const seflex::ConvergenceError& e) {
    EXPECT_NE(std::string(e.what()).find("stability limit"), std::string::npos) << e.what();
    ASSERT_FALSE(unstable.samples.empty());
    EXPECT_TRUE(std::isfinite(unstable.samples.back().energy.kinetic));
  }
}

}  // namespace
}  // namespace seflex::test
