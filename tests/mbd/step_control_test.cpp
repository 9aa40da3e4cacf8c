// The step driver (mbd/src/solvers/step_control.cpp): when the local error allows it, the steps grow
// to the largest the settings permit. A step halved so as not to leave a sliver before an output
// time must not hold the steps down: the growth limit applies to the step the control asked for.
// Before that rule the steps stayed at half the output interval whatever the tolerance (the demo's
// sync-3d: 2.5 ms steps at a local error of 1e-2 as at 1e-5, docs/benchmarks.md "Step control").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mbd_models.hpp"
#include "pendulum_reference.hpp"
#include "seflex/mbd/solvers/integrator.hpp"

using namespace seflex;
using namespace seflex::mbd;

namespace {

RunStats run(const Model& model, const IntegratorSettings& st) {
  State s = initial_state(model);
  Data data(model);
  test::Recorder rec;
  return simulate(model, s, data, st, &rec);
}

}  // namespace

// A loose tolerance on the double pendulum: the error test never limits the step, so after the
// start-up ramp from h_initial (growth 1.5 per step) every step is h_max and lands on an output time.
TEST(StepControl, StepsReachTheLargestAllowedWhenTheErrorAllows) {
  const Model model = test::double_pendulum();
  for (const double interval : {0.01, 0.02}) {  // h_max equal to and half of the output interval
    IntegratorSettings st;
    st.t_end = 1.0;
    st.h_initial = 1e-3;
    st.h_max = 0.01;
    st.output_interval = interval;
    st.tol_angle = st.tol_position = 1e3;
    st.rho_inf = 0.9;
    const RunStats stats = run(model, st);
    EXPECT_EQ(stats.rejected_error, 0);
    // 100 steps of h_max, plus the ramp 1, 1.5, 2.25, 3.4, 5.1, 7.6 ms; before the rule, 200 steps
    // of 5 ms (interval 0.01) and 150 of 5 / 7.5 ms (interval 0.02).
    EXPECT_LE(stats.steps, 106) << "output interval " << interval;
    EXPECT_NEAR(stats.h_last, 0.01, 1e-12);
  }
}

// The rule only lifts the cap; the error test still sets the step. On the double pendulum against its
// independent reference (tests/data/mbd/double_pendulum_reference.csv, scipy DOP853 at 1e-12): a
// tolerance 100 times looser takes fewer steps and gives a larger error, and at a local error of
// 1e-6 the error stays that of NewtonRate.DoublePendulumFewerIterationsSameErrorAgainstReference.
TEST(StepControl, TheToleranceStillSetsTheStepAndTheError) {
  const auto ref = test::read_reference("double_pendulum_reference.csv");
  ASSERT_EQ(ref.size(), 201u);
  const Model model = test::double_pendulum();
  auto run_at = [&](double tol, RunStats& stats) {
    IntegratorSettings st;
    st.t_end = 2.0;
    st.h_initial = 1e-3;
    st.h_max = 0.01;
    st.output_interval = 0.01;
    st.tol_angle = st.tol_position = tol;
    st.rho_inf = 0.9;
    State s = initial_state(model);
    Data data(model);
    test::Recorder rec;
    stats = simulate(model, s, data, st, &rec);
    return test::reference_errors(rec.samples, ref).phi;
  };
  RunStats tight, loose;
  const double e_tight = run_at(1e-6, tight), e_loose = run_at(1e-4, loose);
  std::printf("double pendulum: local error 1e-6: %ld steps, phi error %.3e rad; 1e-4: %ld steps, %.3e rad\n", tight.steps,
              e_tight, loose.steps, e_loose);
  EXPECT_LT(e_tight, 5e-4);
  EXPECT_GT(e_loose, 2.0 * e_tight);
  EXPECT_LT(loose.steps, tight.steps / 2);
  EXPECT_GT(tight.steps, 400);  // far more than the 200 steps of h_max: the error limits them
}

// RunStats::steps_set_by names what set each accepted step's size (summary.json "steps_set_by"); the
// counts add up to the accepted steps. On the double pendulum, max_step 10 ms, outputs every 10 ms:
// - tolerance 1e3 (the error never limits, as in StepsReachTheLargestAllowedWhenTheErrorAllows):
//   after a start-up ramp of a few steps (the first step, growth by at most 1.5 per step, steps
//   shortened to land on the first outputs) every step is max_step;
// - tolerance 1e-6 with a sample at every step (no output schedule): the error estimate sets nearly
//   all (TheToleranceStillSetsTheStepAndTheError: 400+ steps where max_step would take 200), a few
//   are max_step, and only the last two are cut to end at t_end;
// - adaptive: false, 2 ms: the constant step sets them all (it divides the output interval).
TEST(StepControl, StepsSetByNameWhatSetTheStep) {
  const Model model = test::double_pendulum();
  auto run_with = [&](double tol, bool adaptive, double output_interval) {
    IntegratorSettings st;
    st.t_end = 2.0;
    st.h_initial = adaptive ? 1e-3 : 2e-3;
    st.h_max = 0.01;
    st.output_interval = output_interval;
    st.tol_angle = st.tol_position = tol;
    st.rho_inf = 0.9;
    st.adaptive = adaptive;
    return run(model, st);
  };
  auto count = [](const RunStats& s, StepLimit l) { return s.steps_set_by[static_cast<std::size_t>(l)]; };
  auto total = [](const RunStats& s) {
    long n = 0;
    for (const long c : s.steps_set_by) n += c;
    return n;
  };
  const RunStats loose = run_with(1e3, true, 0.01), tight = run_with(1e-6, true, 0.0), fixed = run_with(1e-6, false, 0.01);
  for (const RunStats* s : {&loose, &tight, &fixed}) EXPECT_EQ(total(*s), s->steps);
  std::printf("steps set by (loose / tight / fixed):");
  for (int k = 0; k < kStepLimits; ++k)
    std::printf(" %s %ld/%ld/%ld", step_limit_name(static_cast<StepLimit>(k)), loose.steps_set_by[static_cast<std::size_t>(k)],
                tight.steps_set_by[static_cast<std::size_t>(k)], fixed.steps_set_by[static_cast<std::size_t>(k)]);
  std::printf("\n");
  EXPECT_EQ(count(loose, StepLimit::Initial), 1);
  EXPECT_EQ(count(loose, StepLimit::Error), 0);
  EXPECT_GE(count(loose, StepLimit::Growth), 1);
  EXPECT_GE(count(loose, StepLimit::Largest), loose.steps - 10);
  EXPECT_GT(tight.steps, 400);
  EXPECT_GT(count(tight, StepLimit::Error), tight.steps * 9 / 10);
  EXPECT_LE(count(tight, StepLimit::Largest), 10);
  EXPECT_LE(count(tight, StepLimit::Output), 2);
  EXPECT_EQ(fixed.steps, 1000);
  EXPECT_EQ(count(fixed, StepLimit::Fixed), fixed.steps);
}
