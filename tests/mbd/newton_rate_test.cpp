// Newton's stopping test from the contraction of the corrections (IntegratorSettings::
// newton_error_fraction, docs/benchmarks.md "Step economy"): it must save iterations without
// changing the solution beyond a small fraction of the integration error. Checked against the
// exact solution of a linear oscillator and the independent reference of the double pendulum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mbd_models.hpp"
#include "pendulum_reference.hpp"
#include "seflex/common/error.hpp"
#include "seflex/mbd/assembly/assembly.hpp"
#include "seflex/mbd/output.hpp"
#include "seflex/mbd/solvers/integrator.hpp"

using namespace seflex;
using namespace seflex::mbd;

namespace {

struct RunResult {
  RunStats stats;
  std::vector<Sample> samples;
};

RunResult simulate_model(const Model& model, IntegratorSettings st) {
  State s = initial_state(model);
  Data data(model);
  test::Recorder rec;
  RunResult r;
  r.stats = simulate(model, s, data, st, &rec);
  r.samples = rec.samples;
  return r;
}

double per_step(const RunStats& s) { return static_cast<double>(s.newton_iterations) / static_cast<double>(s.steps); }

}  // namespace

// A rigid rod (m = 1 kg, L = 1 m) on a ground hinge with a linear torsion spring k = 3 N m/rad,
// no gravity: J = m L^2 / 3 = 1/3 kg m^2, omega = sqrt(k / J) = 3 rad/s; released at phi = 0 with
// phidot = 0.3 rad/s: phi(t) = 0.1 sin(3 t) exactly. The residual is linear in the hinge angle
// (one dof), so one Newton correction solves each step exactly: the old stopping test still needs a
// second one in most steps (to see the increment below 1e-9), the contraction test does not.
TEST(NewtonRate, LinearOscillatorOneIterationPerStepSameSolution) {
  ModelBuilder mb;
  const auto rod = mb.add_superelement(test::rod(1.0, 1.0));
  const auto g = mb.add_ground("pivot", Pose{});
  HingeOptions ho;
  ho.phidot0 = 0.3;
  const auto h = mb.add_hinge("H", g, Eigen::Vector3d::UnitZ(), ho);
  mb.add_rigid_body("rod", rod, mb.hinge_child(h), 0, Pose{Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.5, 0, 0)});
  mb.add_force_element("spring", TorsionSpring{h, 0.0, -3.0, 1.0, {}, {}});  // tau = -3 phi
  mb.set_gravity(Eigen::Vector3d::Zero());
  const Model model = mb.build();
  ASSERT_EQ(model.num_dofs, 1);

  IntegratorSettings st;
  st.t_end = 10.0;  // about 5 periods
  st.output_interval = 0.05;
  st.tol_position = st.tol_angle = 1e-7;
  st.rho_inf = 0.9;
  auto error = [](const RunResult& r) {
    double e = 0.0;
    for (const auto& smp : r.samples) e = std::max(e, std::abs(smp.hinges[0].phi - 0.1 * std::sin(3.0 * smp.t)));
    return e;
  };
  st.newton_error_fraction = 0.0;  // residual and increment tests only
  const RunResult old_test = simulate_model(model, st);
  st.newton_error_fraction = 1e-3;  // the default
  const RunResult rate_test = simulate_model(model, st);
  const double e_old = error(old_test), e_rate = error(rate_test);
  std::printf("oscillator: residual+increment test %ld steps %.3f its/step, error %.3e rad; contraction test %ld steps %.3f its/step, error %.3e rad\n",
              old_test.stats.steps, per_step(old_test.stats), e_old, rate_test.stats.steps, per_step(rate_test.stats), e_rate);
  EXPECT_GE(per_step(old_test.stats), 1.5);  // 1.70 measured
  EXPECT_LE(per_step(rate_test.stats), 1.05);  // 1.008: the first step has no rate yet
  EXPECT_EQ(rate_test.stats.steps, old_test.stats.steps);
  // The integration error (second order, local error 1e-7; 1.3e-4 rad after 5 periods, mostly
  // phase) is far above the iteration error: both tests give it to 0.1 %.
  EXPECT_LT(e_rate, 2e-4);
  EXPECT_LE(std::abs(e_rate - e_old), 1e-3 * e_old);
}

// The rigid double pendulum released horizontally (tests/data/mbd/double_pendulum_reference.csv,
// scipy DOP853 at 1e-12, independent of seflex): nonlinear, the rods reach 12 rad/s. At a local
// error of 1e-6 the contraction test takes fewer iterations and gives the same errors against the
// reference to 1 % (the iteration error is 1e-3 of the local error tolerance).
TEST(NewtonRate, DoublePendulumFewerIterationsSameErrorAgainstReference) {
  const auto ref = test::read_reference("double_pendulum_reference.csv");
  ASSERT_EQ(ref.size(), 201u);
  const Model model = test::double_pendulum();
  IntegratorSettings st;
  st.t_end = 2.0;
  st.output_interval = 0.01;
  st.h_initial = 1e-3;
  st.tol_angle = st.tol_position = 1e-6;
  st.rho_inf = 0.9;
  st.newton_error_fraction = 0.0;
  const RunResult old_test = simulate_model(model, st);
  st.newton_error_fraction = 1e-3;
  const RunResult rate_test = simulate_model(model, st);
  ASSERT_EQ(old_test.samples.size(), ref.size());
  ASSERT_EQ(rate_test.samples.size(), ref.size());
  const auto e_old = test::reference_errors(old_test.samples, ref);
  const auto e_rate = test::reference_errors(rate_test.samples, ref);
  std::printf("double pendulum: residual+increment test %ld steps %.3f its/step, phi error %.3e rad; contraction test %ld steps %.3f its/step, phi error %.3e rad\n",
              old_test.stats.steps, per_step(old_test.stats), e_old.phi, rate_test.stats.steps, per_step(rate_test.stats), e_rate.phi);
  EXPECT_LT(per_step(rate_test.stats), 0.75 * per_step(old_test.stats));  // 1.01 against 1.99 measured
  EXPECT_LT(e_rate.phi, 5e-4);  // 1.8e-4 rad measured: local error 1e-6 per step over 2 s
  EXPECT_LE(std::abs(e_rate.phi - e_old.phi), 0.01 * e_old.phi);
  EXPECT_LE(std::abs(e_rate.rate - e_old.rate), 0.01 * e_old.rate);
}

// A fraction outside [0, 1) is refused with a message naming the setting.
TEST(NewtonRate, BadFractionIsRefused) {
  const Model model = test::double_pendulum();
  for (const double f : {-0.1, 1.0, std::nan("")}) {
    IntegratorSettings st;
    st.newton_error_fraction = f;
    State s = initial_state(model);
    Data data(model);
    try {
      simulate(model, s, data, st);
      ADD_FAILURE() << "fraction " << f << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("Newton error fraction must lie in [0, 1)"), std::string::npos) << e.what();
    }
  }
}

// When the contraction test accepts a corrected iterate, Newton does not evaluate it (the bodies are
// evaluated only when a sample needs them, and at the end of simulate). The samples and the caller's
// Data must still be those of the accepted state: compared with a fresh evaluation of the final
// state, on the rigid double pendulum (1.01 Newton iterations per step: nearly every step skips the
// evaluation) and on a flexible chain with full inertia and 2 fixed-interface modes per link
// (local error 1e-3: 1.38 iterations per step).
namespace {
void expect_samples_and_data_of_the_accepted_state(const Model& model, const IntegratorSettings& st, double max_per_step) {
  State s = initial_state(model);
  Data data(model);
  test::Recorder rec;
  const RunStats stats = simulate(model, s, data, st, &rec);
  ASSERT_LT(per_step(stats), max_per_step);  // so most steps ended without evaluating their result
  // A fresh Data recovers the bodies' frames from the state's frame, `data` from its last evaluation:
  // the two agree to the frame recovery's tolerance (~1e-9 rad), hence the bounds for flexible bodies.
  const double tol = model.flexible_bodies.empty() ? 1e-12 : 1e-8;
  Data fresh(model);
  assemble(model, s, fresh, AssemblyOptions{false, true, 1.0});
  EXPECT_LE((data.residual - fresh.residual).norm(), tol * (1.0 + fresh.scale.norm()));
  for (std::size_t b = 0; b < model.flexible_bodies.size(); ++b) {
    EXPECT_LT((data.flex[b].kin.frame.R_WB - fresh.flex[b].kin.frame.R_WB).norm(), tol);
    EXPECT_LT((data.flex[b].kin.xi - fresh.flex[b].kin.xi).norm(), tol);
  }
  ASSERT_FALSE(rec.samples.empty());
  const Sample& last = rec.samples.back();
  ASSERT_NEAR(last.t, s.t, 1e-12);
  const Energies e = energies(model, s, fresh);
  EXPECT_NEAR(last.energy.kinetic, e.kinetic, tol * std::abs(e.kinetic));
  EXPECT_NEAR(last.energy.elastic, e.elastic, tol * std::abs(e.kinetic));
  // HingeSample's 4th member: a driven hinge's joint torque at the accepted state; without driven
  // hinges the samples are evaluated without the residual (AssemblyOptions::energies_only), whose
  // free hinges report 0 (their "joint torque" would be Newton's residual). The drives' torques in
  // samples are checked against references in flexible_dynamics_test and rigid_spinup_test.
  bool driven = false;
  for (const Hinge& hg : model.hinges) driven = driven || static_cast<bool>(hg.drive);
  for (std::size_t h = 0; h < model.hinges.size(); ++h) {
    if (driven)
      EXPECT_NEAR(last.hinges[h].drive_torque, fresh.hinges[h].joint_torque, tol * (1.0 + std::abs(fresh.hinges[h].joint_torque)));
    else
      EXPECT_EQ(last.hinges[h].drive_torque, 0.0);
  }
}
}  // namespace

TEST(NewtonRate, SamplesAndFinalDataBelongToTheAcceptedState) {
  IntegratorSettings st;
  st.t_end = 0.5;
  st.output_interval = 0.01;
  st.h_initial = 1e-3;
  st.tol_angle = st.tol_position = 1e-6;
  st.rho_inf = 0.9;
  expect_samples_and_data_of_the_accepted_state(test::double_pendulum(), st, 1.05);
  test::ChainOptions o;
  o.bodies = 2;
  o.modes = 2;
  o.inertia = InertiaModel::Full;
  st.t_end = 0.3;
  st.tol_angle = st.tol_position = 1e-3;
  st.h_max = 5e-3;  // steps of at most half the output interval: short enough for the contraction test
  expect_samples_and_data_of_the_accepted_state(test::pendulum_chain(o), st, 1.5);
}
