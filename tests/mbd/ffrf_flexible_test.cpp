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
