// FFRF-LM against AIC (full inertia) on a flexible double pendulum of test beams.
#include <gtest/gtest.h>

#include "mbd_models.hpp"
#include "seflex/mbd/ffrf.hpp"

using namespace seflex;
using namespace seflex::mbd;

namespace {

test::ChainOptions flexible_double_pendulum() {
  test::ChainOptions o;
  o.bodies = 2;
  o.elements = 4;
  o.section.E = 7e9;  // soft aluminium-like links: lowest elastic modes ~ 10-50 Hz, visible bending
  o.inertia = InertiaModel::Full;
  return o;
}

IntegratorSettings fixed_step(double h, double t_end) {
  IntegratorSettings st;
  st.t_end = t_end;
  st.h_initial = h;
  st.adaptive = false;
  st.output_interval = 0.01;
  st.rho_inf = 0.8;
  st.newton_residual_tol = 1e-10;
  st.newton_increment_tol = 1e-11;
  return st;
}

/// max over samples of |phi_a - phi_b| (both hinges).
double max_angle_difference(const test::Recorder& a, const test::Recorder& b) {
  EXPECT_EQ(a.samples.size(), b.samples.size());
  double e = 0.0;
  for (std::size_t k = 0; k < std::min(a.samples.size(), b.samples.size()); ++k)
    for (std::size_t h = 0; h < a.samples[k].hinges.size(); ++h)
      e = std::max(e, std::abs(a.samples[k].hinges[h].phi - b.samples[k].hinges[h].phi));
  return e;
}

}  // namespace

// The two formulations share the frame (the superelement's frame node) and the mass model (FE
// nodal inertia); they differ in the kinematics of the elastic coordinates (AIC: absolute interface
// poses with the log map; FFRF: linear in the frame-clamped modes) and in the discretisation of the
// constraints, so their hinge angles must approach each other as the step is refined (second
// order: the difference falls by ~4 per halving) and as the modes are completed. Links of 1 m,
// E = 7e9 Pa: the lowest frame-clamped mode is ~8 Hz, the links bend visibly (tip ~cm).
TEST(FfrfFlexible, AgreesWithAicAsStepAndModesAreRefined) {
  const Model model = test::pendulum_chain(flexible_double_pendulum());
  const double t_end = 0.5;
  std::vector<double> diff;
  test::Recorder aic_fine;
  for (double h : {4e-3, 2e-3, 1e-3, 5e-4}) {
    test::Recorder aic, ff;
    State s = initial_state(model);
    Data data(model);
    simulate(model, s, data, fixed_step(h, t_end), &aic);
    const FfrfStats st = simulate_ffrf(model, fixed_step(h, t_end), FfrfOptions{}, &ff);
    diff.push_back(max_angle_difference(aic, ff));
    std::printf("h %.1e, all modes: max |phi_aic - phi_ffrf| = %.3e rad (drift %.1e m)\n", h, diff.back(), st.drift_position);
    EXPECT_LT(st.drift_position, 1e-10);
    EXPECT_LT(st.drift_rotation, 1e-10);
    aic_fine = aic;
  }
  for (std::size_t k = 1; k < diff.size(); ++k) EXPECT_GT(diff[k - 1] / diff[k], 2.5);  // second order: 4 (first order would give 2)
  EXPECT_LT(diff.back(), 1e-6);
  // Mode count at the finest step: the difference falls as modes are added.
  std::vector<double> by_modes;
  for (int modes : {1, 2, 4}) {
    test::Recorder ff;
    FfrfOptions fo;
    fo.modes = modes;
    simulate_ffrf(model, fixed_step(5e-4, t_end), fo, &ff);
    by_modes.push_back(max_angle_difference(aic_fine, ff));
    std::printf("h 5e-4, %d modes: max |phi_aic - phi_ffrf| = %.3e rad\n", modes, by_modes.back());
  }
  by_modes.push_back(diff.back());
  for (std::size_t k = 1; k < by_modes.size(); ++k) EXPECT_LT(by_modes[k], by_modes[k - 1]);
  EXPECT_GT(by_modes.front(), 1e-4);  // one mode is visibly not enough: the comparison can fail
}

// Energy conservation without numerical damping (rho_inf = 1): the chain of
// FlexibleDynamics.T11_EnergyConservationPendulumChain (two 0.25 m links, gravity 30 deg off the
// chain's normal) with FFRF-LM, all modes, constant step 1e-3 s over 4 s (two swings). Conservation
// law: kinetic + elastic + gravity energy is constant; the undamped scheme keeps it to its
// truncation error, bounded (no drift); same bound as the AIC test: 0.1 % of the peak kinetic energy.
TEST(FfrfFlexible, EnergyIsConservedWithoutNumericalDamping) {
  test::ChainOptions o;
  o.bodies = 2;
  o.elements = 2;
  o.length = 0.25;
  o.inertia = InertiaModel::Full;
  o.gravity = 9.81 * Eigen::Vector3d(std::cos(M_PI / 6), -std::sin(M_PI / 6), 0);
  const Model model = test::pendulum_chain(o);
  IntegratorSettings is;
  is.t_end = 4.0;
  is.rho_inf = 1.0;
  is.adaptive = false;  // see docs/ffrf.md: with rho_inf = 1 the error estimate of the index-3 system does not fall with h
  is.h_initial = 1e-3;
  is.output_interval = 0.05;
  test::Recorder rec;
  const FfrfStats st = simulate_ffrf(model, is, FfrfOptions{}, &rec);
  const double E0 = rec.samples.front().energy.total();
  double drift = 0, kinetic = 0;
  for (const auto& smp : rec.samples) {
    drift = std::max(drift, std::abs(smp.energy.total() - E0));
    kinetic = std::max(kinetic, smp.energy.kinetic);
  }
  std::printf("FFRF chain: energy drift %.2e J = %.3f %% of the largest kinetic energy %.4f J; %ld steps; constraint drift %.1e m, "
              "%.1e m/s\n",
              drift, 100 * drift / kinetic, kinetic, st.run.steps, st.drift_position, st.drift_velocity);
  EXPECT_LT(drift, 1e-3 * kinetic);
  EXPECT_LT(st.drift_position, 1e-9 * o.length);
}

// Force elements act on the same unwrapped hinge angles in both formulations: a torsion spring on
// H2 drives the outer link into a lock at 60 deg while a preloaded cable loop couples H1 and H2
// (no gravity). The lock latch time, the lock torque and the cable force histories of FFRF-LM must
// match AIC's (full inertia, all modes, same fixed step h = 5e-4 s).
TEST(FfrfFlexible, LockAndCableTorquesMatchAic) {
  test::ChainOptions o = flexible_double_pendulum();
  o.gravity.setZero();
  o.extra = [](ModelBuilder& mb, const std::vector<HingeIndex>& h) {
    TorsionSpring spring;
    spring.hinge = h[1];
    spring.tau0 = 3.0;
    spring.tau1 = 1.0;
    spring.phi_ref = M_PI / 2;
    mb.add_force_element("spring", spring);
    HingeLock lock;
    lock.hinge = h[1];
    lock.phi_lock = M_PI / 3;
    lock.k_lock = 2000.0;
    lock.c_lock = 2.0;
    mb.add_force_element("lock", lock);
    CableLoop cable;
    cable.hinges_a = {h[0]};
    cable.hinges_b = {h[1]};
    cable.r_a = cable.r_b = 0.05;
    cable.k = 2e4;
    cable.preload = 50.0;
    mb.add_force_element("cable", cable);
  };
  const Model model = test::pendulum_chain(o);
  const double t_end = 1.2;
  // Compare at the common output times (event samples differ in time between the runs).
  auto regular = [](const test::Recorder& r) {
    std::vector<const Sample*> out;
    for (const auto& smp : r.samples)
      if (!smp.event) out.push_back(&smp);
    return out;
  };
  std::vector<double> dt_latch, d_lock, d_cable;
  double peak_lock = 0, peak_cable = 0;
  for (double h : {5e-4}) {
    test::Recorder aic, ff;
    State s = initial_state(model);
    Data data(model);
    const IntegratorSettings st = fixed_step(h, t_end);
    simulate(model, s, data, st, &aic);
    simulate_ffrf(model, st, FfrfOptions{}, &ff);
    ASSERT_TRUE(aic.samples.back().elements[1].latched);
    ASSERT_TRUE(ff.samples.back().elements[1].latched);
    dt_latch.push_back(std::abs(aic.samples.back().elements[1].t_latch - ff.samples.back().elements[1].t_latch));
    const auto A = regular(aic), F = regular(ff);
    ASSERT_EQ(A.size(), F.size());
    double dl = 0, dc = 0;
    for (std::size_t k = 0; k < A.size(); ++k) {
      ASSERT_NEAR(A[k]->t, F[k]->t, 1e-12);
      peak_lock = std::max(peak_lock, std::abs(A[k]->elements[1].value));
      peak_cable = std::max(peak_cable, std::abs(A[k]->elements[2].value));
      dl = std::max(dl, std::abs(A[k]->elements[1].value - F[k]->elements[1].value));
      dc = std::max(dc, std::abs(A[k]->elements[2].value - F[k]->elements[2].value));
    }
    d_lock.push_back(dl);
    d_cable.push_back(dc);
    std::printf("h %.0e: latch time difference %.2e s (latch at %.6f s); lock torque difference %.2e of peak %.2f N m; cable "
                "force difference %.2e of peak %.2f N\n",
                h, dt_latch.back(), aic.samples.back().elements[1].t_latch, dl / peak_lock, peak_lock, dc / peak_cable, peak_cable);
  }
  EXPECT_GT(peak_lock, 1.0);    // the lock does work
  EXPECT_GT(peak_cable, 10.0);  // the cable does work
  // At equal steps the two formulations latch within 1e-5 s of each other and their torques agree
  // to 0.5 % of the peaks (the lock torque rises at k_lock phidot ~ 1e4 N m/s, so a latch-time
  // difference of 4e-6 s alone is 0.3 % of its peak). (The latch time itself still moves by
  // ~3 % between h = 1e-3 s and 5e-4 s in both formulations: the elastic response is not yet
  // converged at these steps, so no step trend is asserted here.)
  EXPECT_LT(dt_latch[0], 1e-5);
  EXPECT_LT(d_lock[0], 5e-3 * peak_lock);
  EXPECT_LT(d_cable[0], 5e-3 * peak_cable);
}
