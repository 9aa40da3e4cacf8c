// Rigid bodies with Lagrange multipliers (rigid-LM) on the rigid double pendulum against the same
// independent reference as the AIC test, and rigid-LM against AIC rigid bodies on a chain.
#include <gtest/gtest.h>

#include "mbd_models.hpp"
#include "pendulum_reference.hpp"
#include "seflex/mbd/ffrf/ffrf.hpp"

using namespace seflex;
using namespace seflex::mbd;

// Reference and tolerances as Pendulum.RigidDoublePendulumMatchesReference (pendulum_reference.hpp):
// angles 2e-5 rad, rates 2e-4 rad/s, energy 2e-6 of (m1 + m2) g L. Each rod is a 6-dof body here,
// its hinges 6 constraint equations each plus the hinge angle: 14 coordinates, 12 multipliers.
TEST(FfrfPendulum, RigidLmDoublePendulumMatchesReference) {
  const auto ref = test::read_reference("double_pendulum_reference.csv");
  ASSERT_EQ(ref.size(), 201u);
  const Model model = test::double_pendulum();
  IntegratorSettings st;
  st.t_end = 2.0;
  st.output_interval = 0.01;
  st.h_initial = 1e-3;
  st.tol_angle = st.tol_position = 1e-9;
  st.rho_inf = 0.9;
  test::Recorder rec;
  const FfrfStats stats = simulate_ffrf(model, st, FfrfOptions{}, &rec);
  EXPECT_EQ(stats.coordinates, 14);
  EXPECT_EQ(stats.constraints, 12);
  ASSERT_EQ(rec.samples.size(), ref.size());
  const test::ReferenceErrors err = test::reference_errors(rec.samples, ref);
  const double e_phi = err.phi, e_w = err.rate, e_E = err.energy;
  std::printf("rigid-LM double pendulum: max errors phi %.2e rad, rate %.2e rad/s, energy %.2e; %ld steps, %ld Newton its; "
              "drift %.1e m %.1e rad, %.1e m/s\n",
              e_phi, e_w, e_E, stats.run.steps, stats.run.newton_iterations, stats.drift_position, stats.drift_rotation,
              stats.drift_velocity);
  EXPECT_LT(e_phi, 2e-5);
  EXPECT_LT(e_w, 2e-4);
  EXPECT_LT(e_E, 2e-6);
  // Index 3: positions are enforced to the Newton tolerance (increment tolerance 1e-9 x 2 m).
  EXPECT_LT(stats.drift_position, 1e-8);
  EXPECT_LT(stats.drift_rotation, 1e-8);
}
