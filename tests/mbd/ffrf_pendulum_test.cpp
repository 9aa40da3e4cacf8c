// Rigid bodies with Lagrange multipliers (rigid-LM) on the rigid double pendulum against the same
// independent reference as the AIC test, and rigid-LM against AIC rigid bodies on a chain.
#include <gtest/gtest.h>

#include "mbd_models.hpp"
#include "pendulum_reference.hpp"
#include "seflex/mbd/ffrf/ffrf.hpp"
#include "seflex/mbd/solvers/integrator.hpp"

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

// Rigid-LM on pendulum chains of rigid rods released horizontally, against AIC's rigid bodies (hinge
// angles as the only unknowns: an independent formulation of the same mechanism). The FFRF-LM
// iteration matrix is factorised densely up to 150 unknowns and by the sparse LU above
// (ffrf_iteration_matrix.hpp): 5 rods (5 x 7 = 35 coordinates, 30 multipliers) take the dense path,
// 12 rods (84 + 72 = 156) the sparse one; both must agree with AIC to the integration error.
// Measured, max hinge-angle difference over 0.4 s at local error tolerance 1e-8 / 1e-9 / 1e-10 / 1e-11:
// 4.4e-6 / 8.9e-7 / 1.8e-7 / 3.4e-8 rad (5 rods), 1.1e-5 / 2.3e-6 / 5.3e-7 / 1.1e-7 rad (12 rods):
// the integration error of the two formulations, shrinking with the tolerance. Checked at 1e-9.
class FfrfRigidChain : public ::testing::TestWithParam<int> {};

TEST_P(FfrfRigidChain, RigidLmMatchesAicRigidBodies) {
  test::ChainOptions o;
  o.bodies = GetParam();
  o.length = 0.2;
  o.rigid = true;
  const Model model = pendulum_chain(o);
  IntegratorSettings st;
  st.t_end = 0.4;
  st.output_interval = 0.02;
  st.h_initial = 1e-4;
  st.tol_angle = st.tol_position = 1e-9;
  st.rho_inf = 0.9;
  test::Recorder lm, aic;
  const FfrfStats stats = simulate_ffrf(model, st, FfrfOptions{}, &lm);
  State s = initial_state(model);
  Data data(model);
  simulate(model, s, data, st, &aic);
  const int unknowns = stats.coordinates + stats.constraints;
  EXPECT_EQ(stats.coordinates, 7 * o.bodies);
  EXPECT_EQ(unknowns > 150, o.bodies > 10);  // the path this case is meant to take
  ASSERT_EQ(lm.samples.size(), aic.samples.size());
  double err = 0.0, swing = 0.0;
  for (std::size_t k = 0; k < lm.samples.size(); ++k)
    for (std::size_t h = 0; h < lm.samples[k].hinges.size(); ++h) {
      err = std::max(err, std::abs(lm.samples[k].hinges[h].phi - aic.samples[k].hinges[h].phi));
      swing = std::max(swing, std::abs(aic.samples[k].hinges[h].phi));
    }
  std::printf("rigid-LM chain of %d rods (%d unknowns): max hinge-angle difference to AIC %.2e rad (largest angle %.2f rad)\n",
              o.bodies, unknowns, err, swing);
  EXPECT_GT(swing, 0.1);  // the chain has swung
  EXPECT_LT(err, 5e-6);
}

INSTANTIATE_TEST_SUITE_P(DenseAndSparse, FfrfRigidChain, ::testing::Values(5, 12));
