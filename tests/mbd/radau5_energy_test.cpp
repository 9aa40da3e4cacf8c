// Energy drift of Radau IIA-5 (mbd/solvers/radau5.hpp) on an undamped free-flying flexible body: no
// hinges, no locks, no gravity, no damping. Radau IIA is dissipative (algebraically stable), so at
// constant steps its energy error is its local error accumulated: it must shrink as h^5 on a motion
// the steps resolve.
//
// What the energy error is measured against: the total (kinetic + elastic) energy of the converged
// motion is not constant to round-off in the AIC formulation with full inertia. On this body it moves
// by 5.24e-5 of E(0) within 1 s (1.25e-5 J, 8 % of the largest elastic energy; formulation.md's T11 bounds the
// same drift by 0.1 %, tests/mbd/flexible_dynamics_test.cpp), and generalized-alpha with rho_inf = 1 at
// 0.1 ms steps gives the same energy history (to 1.6e-8 of E(0)): that part is the equations', not
// the integrator's. The integrator's energy error is therefore E_h(t) - E_ref(t) against the same
// integrator at 0.5 ms (whose own error is 4^-5 of the 2 ms run's), checked below against the
// generalized-alpha history as well.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "mbd_models.hpp"
#include "seflex/mbd/solvers/integrator.hpp"
#include "seflex/mbd/solvers/radau5.hpp"
#include "test_support.hpp"

namespace seflex::test {
namespace {

using namespace seflex::mbd;
using Eigen::Vector3d;

constexpr double kEnd = 1.0;       // [s]
constexpr double kSampled = 8e-3;  // energies compared every 8 ms

/// A free 1 m beam (4 elements, interfaces at both ends, frame at the middle, 2 fixed-interface
/// modes), full inertia, tumbling at 2.3 rad/s about an oblique axis with a transverse velocity at
/// one end: the centrifugal loads and that kick set it vibrating while it tumbles. E = 2e6 Pa: the
/// axial mode at 13 Hz (h omega = 0.7 at 8 ms) and the bending modes below are resolved by the steps.
struct FreeBeam {
  Model model;
  int kicked = -1;  // first dof of the kicked end
};

FreeBeam free_beam() {
  BeamSection sec;
  sec.E = 2e6;
  sec.G = sec.E / 2.6;
  auto fe = straight_beam(1.0, 4, sec);
  const se::Superelement s = craig_bampton(fe, {0, 4}, 2, 2, "beam");
  ModelBuilder mb;
  const auto sei = mb.add_superelement(s);
  const NodeIndex a = mb.add_node("a", Pose{Eigen::Matrix3d::Identity(), Vector3d(0, 0, 0)});
  const NodeIndex b = mb.add_node("b", Pose{Eigen::Matrix3d::Identity(), Vector3d(1, 0, 0)});
  FlexibleBodyOptions fo;
  fo.inertia = InertiaModel::Full;
  mb.add_flexible_body("beam", sei, {a, b}, Pose{Eigen::Matrix3d::Identity(), Vector3d(0.5, 0, 0)}, fo);
  FreeBeam fb{mb.build(), -1};
  fb.kicked = fb.model.nodes[static_cast<std::size_t>(b.value)].dof;
  return fb;
}

State start(const FreeBeam& fb) {
  State s = initial_state(fb.model);
  set_rigid_velocity(fb.model, s, Vector3d(0.1, 0.0, 0.0), Vector3d(0.5, 1.0, 2.0));
  s.v.segment<3>(fb.kicked) += Vector3d(0.0, 0.05, -0.03);
  return s;
}

struct History {
  std::vector<double> energy;  // every kSampled
  double largest_elastic = 0.0;
};

/// Radau IIA-5 at constant steps h, a sample at every step's end (not from the cubic dense output).
History radau_history(double h) {
  const FreeBeam fb = free_beam();
  State s = start(fb);
  Data data(fb.model);
  IntegratorSettings st;
  st.t_end = kEnd;
  st.h_initial = h;
  st.adaptive = false;
  st.output_interval = 0.0;
  // Newton converged far below the integration error (as radau5_test.cpp's order test).
  st.tol_position = st.tol_angle = 1e-12;
  st.radau.newton_max_iterations = 30;
  Recorder rec;
  const RunStats rs = simulate_radau5(fb.model, s, data, st, &rec);
  EXPECT_EQ(rs.steps, std::lround(kEnd / h)) << "h = " << h;
  History out;
  const auto every = static_cast<std::size_t>(std::lround(kSampled / h));
  for (std::size_t k = 0; k < rec.samples.size(); k += every) out.energy.push_back(rec.samples[k].energy.total());
  for (const Sample& q : rec.samples) out.largest_elastic = std::max(out.largest_elastic, q.energy.elastic);
  return out;
}

TEST(Radau5Energy, DriftOfAFreeFlyingFlexibleBodyShrinksAsH5) {
  const History ref = radau_history(5e-4);
  const double e0 = ref.energy.front();
  const double formulation = max_abs_difference(ref.energy, std::vector<double>(ref.energy.size(), e0)) / e0;

  // The converged energy history, by a second method: generalized-alpha without numerical damping.
  const FreeBeam fb = free_beam();
  State s = start(fb);
  Data data(fb.model);
  IntegratorSettings st;
  st.t_end = kEnd;
  st.rho_inf = 1.0;
  st.h_initial = 1e-4;
  st.adaptive = false;
  st.output_interval = kSampled;
  Recorder rec;
  simulate(fb.model, s, data, st, &rec);
  std::vector<double> ga;
  for (const Sample& q : rec.samples) ga.push_back(q.energy.total());
  const double methods = max_abs_difference(ga, ref.energy) / e0;
  std::printf("converged motion: energy %.6f J, moves by %.3e of it (largest elastic energy %.3e J); generalized-alpha at "
              "0.1 ms: the same history to %.3e\n",
              e0, formulation, ref.largest_elastic, methods);
  // Measured: 5.24e-5 of E(0), elastic energy up to 1.50e-4 J (6.3e-4 of E(0)); the two methods agree
  // to 1.6e-8.
  EXPECT_GT(ref.largest_elastic, 1e-4 * e0);  // the body does deform
  EXPECT_LT(formulation, 1e-3);               // formulation.md T11's bound
  EXPECT_LT(methods, 1e-7);                   // the history is the equations', not an integrator's

  std::vector<double> err;
  for (double h : {8e-3, 4e-3, 2e-3}) {
    const History run = radau_history(h);
    err.push_back(max_abs_difference(run.energy, ref.energy) / e0);
    std::printf("h %.0e: largest energy error %.3e of E(0)\n", h, err.back());
  }
  const double s1 = std::log2(err[0] / err[1]), s2 = std::log2(err[1] / err[2]);
  std::printf("slopes: 8 -> 4 ms %.2f, 4 -> 2 ms %.2f\n", s1, s2);
  // Measured: 9.26e-7, 2.98e-8, 9.30e-10 of E(0); slopes 4.96 and 5.00.
  EXPECT_NEAR(s1, 5.0, 0.3);
  EXPECT_NEAR(s2, 5.0, 0.3);
  EXPECT_LT(err[0], 2e-6);  // over 125 steps of 8 ms, 1 s of tumbling
}

}  // namespace
}  // namespace seflex::test
