// A fully driven rigid model: the spin-up beam of bench/study (L = 10 m, 10 CBARs with lumped
// translational mass, rho A = 1.2 kg/m) made rigid, its hub driven by the Simo and Vu-Quoc ramp
// to 6 rad/s over 15 s. AIC has 0 unknowns (the body hangs on the driven hinge); rigid-LM has the
// body's 6 frame coordinates and 6 multipliers. Both must run, and their motion is the prescribed
// one:
//   phi(t) = w/T (t^2/2 + (cos(2 pi t/T) - 1)/(2 pi/T)^2), phi'' = w/T (1 - cos(2 pi t/T)) (t < T),
// the drive torque about the hub axis is J phi'' and the kinetic energy J phi'^2 / 2, with
// J = sum m_i x_i^2 of the lumped masses (0.6 kg at x = 0 and 10 m, 1.2 kg at x = 1..9 m):
// 1.2 * 285 + 0.6 * 100 = 402 kg m^2 (the CONM2 of the deck adds inertia about the beam's axis only).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene_fixture.hpp"

namespace seflex::test {
namespace {

constexpr double kW = 6.0, kT = 15.0, kJ = 1.2 * 285.0 + 0.6 * 100.0;

struct Drive {
  double phi, phidot, phiddot;
};

Drive spin_up(double t) {
  const double c = 2.0 * std::numbers::pi / kT;
  if (t >= kT) return {kW * (t - kT / 2.0), kW, 0.0};
  return {kW / kT * (t * t / 2.0 + (std::cos(c * t) - 1.0) / (c * c)), kW / kT * (t - std::sin(c * t) / c),
          kW / kT * (1.0 - std::cos(c * t))};
}

struct Errors {
  double angle = 0, torque = 0, kinetic = 0;
  std::size_t samples = 0;
};

Errors run_rigid(const TempDir& dir, const std::string& options, const std::string& out) {
  const auto r = run_seflex("run " + q(dir / "spinup.yaml") + " -o " + q(dir / out) + " --no-animation " + options);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const Csv h = read_csv(dir / out / "history.csv");
  const auto t = h.column("t"), phi = h.column("hub.phi_deg"), tau = h.column("hub.drive_torque"), ek = h.column("E_kinetic");
  Errors e;
  e.samples = t.size();
  for (std::size_t i = 0; i < t.size(); ++i) {
    const Drive d = spin_up(t[i]);
    e.angle = std::max(e.angle, std::abs(phi[i] * std::numbers::pi / 180.0 - d.phi));
    e.torque = std::max(e.torque, std::abs(tau[i] - kJ * d.phiddot));
    e.kinetic = std::max(e.kinetic, std::abs(ek[i] - 0.5 * kJ * d.phidot * d.phidot));
  }
  return e;
}

TEST(RigidSpinUp, BothRigidFormulationsFollowThePrescribedMotion) {
  TempDir dir;
  const auto deck = source_dir() / "bench" / "study" / "spinup_beam.bdf";
  const auto red = run_seflex("reduce " + q(deck) + " --interface 1,11 --modes 0 -o " + q(dir / "spinup_beam.se"));
  ASSERT_EQ(red.exit_code, 0) << red.err;
  dir.write("spinup.yaml", read_file(source_dir() / "bench" / "study" / "spinup.yaml"));

  const Errors aic = run_rigid(dir, "--fidelity rigid", "aic");
  const Errors lm = run_rigid(dir, "--formulation rigid-lm", "lm");
  std::printf("rigid AIC (0 dofs): angle %.2e rad, torque %.2e N m, kinetic %.2e J; rigid-LM: %.2e rad, %.2e N m, %.2e J\n",
              aic.angle, aic.torque, aic.kinetic, lm.angle, lm.torque, lm.kinetic);
  ASSERT_GE(aic.samples, 400u);  // 20 s at 0.05 s
  const double peak_torque = kJ * 2.0 * kW / kT;  // J max phi'' = 321.6 N m at t = T/2
  // AIC: nothing is integrated; angle, torque (inverse dynamics of the rigid body) and energy are
  // evaluated at the drive's values, exact to round-off.
  EXPECT_LT(aic.angle, 1e-12);
  // measured (2026-11-28): 6e-15 and 5e-16 relative
  EXPECT_LT(aic.torque, 1e-12 * peak_torque);
  EXPECT_LT(aic.kinetic, 1e-12 * 0.5 * kJ * kW * kW);
  // rigid-LM integrates the body's frame under 6 constraints: its angle is the drive's, its
  // kinetic energy follows to the integration error of the frame's rotation (measured 1.7-1.9 J of
  // 7236 J, 2.3-2.6e-4, at the local error 1e-6 over 5600 steps). Its drive torque (from the
  // multipliers) is noisy with the adaptive step (up to ~2000 N m at speed: the index-3
  // generalized-alpha's algorithmic accelerations after step-size changes, docs/ffrf.md) and is
  // asserted at a constant step below.
  EXPECT_LT(lm.angle, 1e-12);
  EXPECT_LT(lm.kinetic, 5e-4 * 0.5 * kJ * kW * kW);
  // Constant step 1 ms: the multipliers give J phi'' to the O(h^2) error of the method (measured
  // 0.005 N m, 1.5e-5 of the peak) and the energy to 0.033 J.
  std::string fixed = read_file(dir / "spinup.yaml");
  const std::string from = "step: 1.0e-3, max_step: 2.0e-2,";
  ASSERT_NE(fixed.find(from), std::string::npos);
  fixed.replace(fixed.find(from), from.size(), "step: 1.0e-3, adaptive: false, min_step: 1.0e-3,");
  dir.write("spinup.yaml", fixed);
  const Errors lm_fixed = run_rigid(dir, "--formulation rigid", "lm_fixed");  // issue 7's spelling of rigid-lm
  std::printf("rigid-LM at a constant 1 ms: angle %.2e rad, torque %.2e N m, kinetic %.2e J\n", lm_fixed.angle, lm_fixed.torque,
              lm_fixed.kinetic);
  EXPECT_LT(lm_fixed.angle, 1e-12);
  EXPECT_LT(lm_fixed.torque, 1e-4 * peak_torque);
  EXPECT_LT(lm_fixed.kinetic, 2e-5 * 0.5 * kJ * kW * kW);
}

}  // namespace
}  // namespace seflex::test
