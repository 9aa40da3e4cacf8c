// Dynamic tests of flexible AIC bodies: T9 rotating radial bar (code_aster V3.04.104 closed form),
// T10 floating-frame node independence, T11 energy conservation (formulation.md section 6.2).
#include <gtest/gtest.h>

#include <cmath>

#include "mbd_models.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/solvers/integrator.hpp"

using namespace seflex;
using namespace seflex::mbd;
using Eigen::Matrix3d;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {

/// Smooth spin-up to omega over T, then constant rate.
Drive ramp(double omega, double T) {
  return [omega, T](double t) {
    DriveValue d;
    if (t < T) {
      const double c = 2 * M_PI / T;
      d.phi = omega * (t * t / (2 * T) + (std::cos(c * t) - 1) / (c * c * T));
      d.phidot = omega * (t / T - std::sin(c * t) / (c * T));
      d.phiddot = omega / T * (1 - std::cos(c * t));
    } else {
      d.phi = omega * T / 2 + omega * (t - T);
      d.phidot = omega;
    }
    return d;
  };
}

}  // namespace

// T9: bar of length L spinning about z through its root at omega. Steady radial displacement
// U(x) = rho omega^2 (x L^2 - x^3/3) / (2E), tip rho omega^2 L^3 / (3E) (code_aster V3.04.104).
// One 2-interface superelement of an 8-element consistent-mass bar (bending stiff enough that the
// spin-up hardly bends it); spin-up over 1 s, transients removed by stiffness-proportional
// damping; the tip radius is read at t = 1.2 s. Tolerance 0.2 % (measured 0.05 % with either inertia:
// the 8-element discretisation of the cubic U(x) and what is left of the transient). A radial bar's centripetal field is
// linear along the bar, so the simplified and full inertia both reproduce it.
TEST(FlexibleDynamics, T9_RotatingRadialBar) {
  const double L = 1.0, omega = 100.0;
  test::BeamSection sec;
  sec.Iy = sec.Iz = 1e-7;
  const double exact = sec.rho * omega * omega * L * L * L / (3 * sec.E);
  for (auto inertia : {InertiaModel::Simplified, InertiaModel::Full}) {
    auto fe = test::straight_beam(L, 8, sec);
    const se::Superelement s = test::craig_bampton(fe, {0, 8}, 4, 0, "bar");
    ModelBuilder mb;
    const auto sei = mb.add_superelement(s);
    const auto g = mb.add_ground("axis", Pose{});
    HingeOptions ho;
    ho.drive = ramp(omega, 1.0);
    const auto h = mb.add_hinge("spin", g, Vector3d::UnitZ(), ho);
    const auto tip = mb.add_node("tip", Pose{Matrix3d::Identity(), Vector3d(L, 0, 0)});
    FlexibleBodyOptions fo;
    fo.inertia = inertia;
    fo.stiffness_damping = 2e-4;
    mb.add_flexible_body("bar", sei, {mb.hinge_child(h), tip}, Pose{Matrix3d::Identity(), Vector3d(L / 2, 0, 0)}, fo);
    const Model model = mb.build();
    ASSERT_EQ(model.num_dofs, 6);  // the tip node only: the root follows the drive
    State st = initial_state(model);
    Data data(model);
    IntegratorSettings is;
    is.t_end = 1.2;
    is.h_initial = 1e-4;
    is.rho_inf = 0.5;
    is.tol_position = is.tol_angle = 1e-5;
    test::Recorder rec;
    simulate(model, st, data, is, &rec);
    double peak_torque = 0;
    for (const auto& smp : rec.samples) peak_torque = std::max(peak_torque, std::abs(smp.hinges[0].drive_torque));
    const double u_tip = st.p_WN.back().norm() - L;
    std::printf("T9 %s inertia: tip %.5e m, exact %.5e m (%.2f %%)\n", inertia == InertiaModel::Full ? "full" : "simplified", u_tip,
                exact, 100 * (u_tip / exact - 1));
    EXPECT_NEAR(u_tip, exact, 0.002 * exact);
    // The drive torque (I w' during the spin-up, 18 N m peak) is ~0 at constant rate.
    EXPECT_NEAR(peak_torque, 0.09 * omega * 2, 0.05 * 18.0);  // I = m L^2 / 3 = 0.09, max w' = 2 w / T
    EXPECT_LT(std::abs(data.hinges[0].joint_torque), 5e-3 * peak_torque);
  }
}

// T10: a cantilever (clamped root, 4-element beam, one superelement) under a tip force ramped in
// 0.5 s and held (damped), with the floating frame on FE node 1 or node 3. The interface
// trajectories differ by O(deformation^2): doubling the load multiplies the largest difference by ~4.
TEST(FlexibleDynamics, T10_FrameNodeIndependence) {
  auto run = [](int frame_node, double F) {
    test::BeamSection sec;
    auto fe = test::straight_beam(1.0, 4, sec);
    const se::Superelement s = test::craig_bampton(fe, {0, 4}, frame_node, 0, "beam");
    ModelBuilder mb;
    const auto sei = mb.add_superelement(s);
    const auto root = mb.add_ground("root", Pose{});
    const auto tip = mb.add_node("tip", Pose{Matrix3d::Identity(), Vector3d(1, 0, 0)});
    FlexibleBodyOptions fo;
    fo.inertia = InertiaModel::Full;
    fo.stiffness_damping = 1e-3;
    mb.add_flexible_body("beam", sei, {root, tip}, Pose{Matrix3d::Identity(), fe.pts[static_cast<std::size_t>(frame_node)]}, fo);
    NodeLoad load{"F", tip, Vector3d(0, -F, 0), Vector3d::Zero(), false, [](double t) {
                    return t < 0.5 ? 0.5 * (1 - std::cos(M_PI * t / 0.5)) : 1.0;
                  }};
    mb.add_load(load);
    const Model model = mb.build();
    State st = initial_state(model);
    Data data(model);
    IntegratorSettings is;
    is.t_end = 1.0;
    is.h_initial = 1e-3;
    is.output_interval = 0.01;
    is.tol_position = 1e-8;
    test::Recorder rec;
    simulate(model, st, data, is, &rec);
    std::vector<Vector3d> tip_path;
    for (const auto& smp : rec.samples) tip_path.push_back(smp.nodes[1].p);
    return tip_path;
  };
  const double EI = 7e10 * 2e-9;
  double diff[2], defl[2];
  int k = 0;
  for (double F : {0.03 * 3 * EI, 0.06 * 3 * EI}) {  // static tip deflection 3 % and 6 % of L
    const auto a = run(1, F), b = run(3, F);
    ASSERT_EQ(a.size(), b.size());
    double d = 0;
    for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
    diff[k] = d;
    defl[k] = std::abs(a.back().y());
    ++k;
  }
  std::printf("T10: deflection %.4f / %.4f m, frame-node difference %.3e / %.3e m, ratio %.2f\n", defl[0], defl[1], diff[0], diff[1],
              diff[1] / diff[0]);
  EXPECT_NEAR(defl[0], 0.03, 0.003);
  // O(deformation^2): (defl / L)^2 = 9e-4; measured diff / defl = 7.4e-4 (and 1.6e-3 at twice the load).
  EXPECT_LT(diff[0], 2e-3 * defl[0]);
  EXPECT_NEAR(diff[1] / diff[0], 4.0, 0.6);
}

// T11: energy conservation with the full inertia, no damping, rho_inf = 1 (average acceleration).
// (a) The free-floating L-frame (3 interfaces, point masses) spinning at 2.3 rad/s with an elastic
//     perturbation, over 10 periods of its lowest elastic mode (2.1 Hz): total energy drift
//     <= 0.1 % (formulation.md T11), with 2.5 % of it elastic.
TEST(FlexibleDynamics, T11_EnergyConservationFreeBody) {
  auto fe = test::l_frame();
  fe.section.E = 7e9;
  fe.point_masses.assign(9, 0.2);
  const se::Superelement s = test::craig_bampton(fe, {0, 8, 6}, 3, 0, "lframe");
  ModelBuilder mb;
  const auto sei = mb.add_superelement(s);
  std::vector<NodeIndex> nodes;
  for (int j = 0; j < 3; ++j) nodes.push_back(mb.add_node("n" + std::to_string(j), interface_pose(s, j, Pose{})));
  FlexibleBodyOptions fo;
  fo.inertia = InertiaModel::Full;
  mb.add_flexible_body("frame", sei, nodes, Pose{}, fo);
  const Model model = mb.build();
  State st = initial_state(model);
  set_rigid_velocity(model, st, Vector3d(0.1, 0, 0), Vector3d(0.3, 1.0, 2.0));
  st.v.segment<3>(6) += Vector3d(0, 0, 0.05);  // an elastic kick at interface 2
  Data data(model);
  IntegratorSettings is;
  is.t_end = 10 / 2.1;
  is.rho_inf = 1.0;
  is.tol_position = is.tol_angle = 1e-5;
  is.output_interval = 0.05;
  test::Recorder rec;
  simulate(model, st, data, is, &rec);
  ASSERT_GT(rec.samples.size(), 50u);
  const double E0 = rec.samples.front().energy.total();
  double drift = 0, elastic = 0;
  for (const auto& smp : rec.samples) {
    drift = std::max(drift, std::abs(smp.energy.total() - E0));
    elastic = std::max(elastic, smp.energy.elastic);
  }
  std::printf("T11 free body: energy %.4f J, largest drift %.2e (%.3f %%), largest elastic energy %.4f J\n", E0, drift, 100 * drift / E0, elastic);
  EXPECT_GT(elastic, 0.01 * E0);  // the body does deform
  EXPECT_LT(drift, 1e-3 * E0);
}

// (b) A chain of two flexible links (0.25 m each, aluminium) swinging from 30 deg off the
//     vertical under gravity, over 10 swing periods (12 s): total energy drift <= 0.1 % of the
//     largest kinetic energy.
TEST(FlexibleDynamics, T11_EnergyConservationPendulumChain) {
  test::ChainOptions o;
  o.bodies = 2;
  o.elements = 2;
  o.length = 0.25;
  o.inertia = InertiaModel::Full;
  o.gravity = 9.81 * Vector3d(std::cos(M_PI / 6), -std::sin(M_PI / 6), 0);  // chain starts 30 deg off the vertical
  const Model model = test::pendulum_chain(o);
  State st = initial_state(model);
  Data data(model);
  IntegratorSettings is;
  is.t_end = 12.0;
  is.rho_inf = 1.0;
  is.tol_position = is.tol_angle = 1e-4;
  is.output_interval = 0.05;
  test::Recorder rec;
  simulate(model, st, data, is, &rec);
  ASSERT_GT(rec.samples.size(), 50u);
  const double E0 = rec.samples.front().energy.total();
  double drift = 0, kinetic = 0;
  for (const auto& smp : rec.samples) {
    drift = std::max(drift, std::abs(smp.energy.total() - E0));
    kinetic = std::max(kinetic, smp.energy.kinetic);
  }
  std::printf("T11 chain: largest drift %.2e J, %.3f %% of the largest kinetic energy %.4f J\n", drift, 100 * drift / kinetic, kinetic);
  EXPECT_GT(kinetic, 0.01);  // the chain swings (0.044 J)
  EXPECT_LT(drift, 1e-3 * kinetic);
}
