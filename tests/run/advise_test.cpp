// seflex advise on a flexible pendulum released horizontally that latches at 60 deg below the
// horizontal. Whether a rigid link is good enough is known beforehand: the link's elastic sag
// changes the hinge angle by about the quasi-static ratio (w_p / w_1)^2 [rad], with w_p =
// sqrt(3 g / 2 L) the pendulum's rate scale and w_1 = 3.9266^2 sqrt(EI / (mu L^4)) the first
// pinned-free bending frequency (Blevins, Formulas for natural frequency and mode shape, table 8-1).
// Stiff aluminium link (EI = 140 N m^2): w_1 = 351 rad/s, (w_p/w_1)^2 = 0.007 deg -> rigid is within
// 0.1 deg. Soft link (E / 1000): w_1 = 11.1 rad/s, (w_p/w_1)^2 = 6.8 deg -> rigid is not.
// The horizon is the finest model's first lock; for the stiff link it is the rigid fall time to
// 60 deg, t = int_0^60deg dtheta / sqrt(3 g sin(theta) / L) (energy), by quadrature.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene_fixture.hpp"
#include "seflex/io/advise.hpp"
#include "seflex/io/scene.hpp"

namespace seflex::test {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

const char* kFall = R"(title: link falling from the horizontal until it latches at -60 deg
bodies:
  - {name: link, superelement: link.se}
hinges:
  - {name: H1, parent: ground, child: link.1, axis: [0, 0, 1]}
locks:
  - {hinge: H1, angle_deg: -60, stiffness: 100}
loads:
  gravity: [0, -9.81, 0]
integrator: {t_end: 3.0, step: 1.0e-3, tolerance: {position: 1.0e-6, angle: 1.0e-6}}
)";

/// Rigid uniform rod pinned at one end, released horizontally: time to turn by `theta`
/// (theta = u^2 removes the endpoint singularity; composite Simpson).
double fall_time(double theta, double L, double g) {
  const int n = 2000;
  const double b = std::sqrt(theta), h = b / n;
  auto f = [&](double u) { return u == 0.0 ? 2.0 / std::sqrt(3.0 * g / L) : 2.0 * u / std::sqrt(3.0 * g * std::sin(u * u) / L); };
  double s = f(0) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(i * h);
  return s * h / 3.0;
}

double quasi_static_ratio(double E) {
  const double L = 1.0, mu = 2700 * 1e-4, EI = E * 2e-9;
  const double w1 = 3.9266 * 3.9266 * std::sqrt(EI / (mu * std::pow(L, 4)));
  const double wp = std::sqrt(3 * 9.81 / (2 * L));
  return (wp / w1) * (wp / w1);
}

const io::AdviseRow& row(const io::AdviseReport& r, const std::string& name) {
  for (const auto& x : r.rows)
    if (x.name == name) return x;
  throw std::runtime_error("no variant " + name);
}

TEST(Advise, StiffLinkRigidIsEnough) {
  TempDir dir;
  write_link(dir, "link.se", 4);
  const auto scene = dir.write("scene.yaml", kFall);
  io::AdviseOptions o;
  o.tolerance = 0.1 * kDeg;
  const io::AdviseReport r = io::advise(io::read_scene(scene), o);
  ASSERT_TRUE(r.horizon_at_lock);
  EXPECT_EQ(r.horizon_lock, "lock.H1");
  EXPECT_NEAR(r.horizon, fall_time(60 * kDeg, 1.0, 9.81), 2e-3 * r.horizon);
  const io::AdviseRow& rigid = row(r, "rigid");
  ASSERT_TRUE(rigid.ran) << rigid.failure;
  const double estimate = quasi_static_ratio(7e10);
  EXPECT_LT(rigid.max_error, o.tolerance);
  EXPECT_GT(rigid.max_error, 0.1 * estimate);  // the sag is seen, of the predicted size
  EXPECT_LT(rigid.max_error, 10 * estimate);
  ASSERT_GE(r.recommended, 0);
  const io::AdviseRow& best = r.rows[static_cast<std::size_t>(r.recommended)];
  EXPECT_TRUE(best.within);
  EXPECT_LE(best.cpu_seconds, r.rows[0].cpu_seconds);
  EXPECT_EQ(best.name, "rigid");  // 1 dof against 12 + 4 modes: cheaper by far
}

TEST(Advise, SoftLinkNeedsFlexibility) {
  TempDir dir;
  write_link(dir, "link.se", 4, 7e7);
  const auto scene = dir.write("scene.yaml", kFall);
  io::AdviseOptions o;
  o.tolerance = 0.1 * kDeg;
  const io::AdviseReport r = io::advise(io::read_scene(scene), o);
  const io::AdviseRow& rigid = row(r, "rigid");
  ASSERT_TRUE(rigid.ran) << rigid.failure;
  const double estimate = quasi_static_ratio(7e7);
  EXPECT_GT(rigid.max_error, o.tolerance);
  EXPECT_GT(rigid.max_error, 0.1 * estimate);
  EXPECT_LT(rigid.max_error, 10 * estimate);
  ASSERT_GE(r.recommended, 0);
  const io::AdviseRow& best = r.rows[static_cast<std::size_t>(r.recommended)];
  EXPECT_NE(best.name, "rigid");
  EXPECT_TRUE(best.within);
  EXPECT_LE(best.max_error, o.tolerance);
  // The ladder converges: fewer modes never beat more modes by much on the same inertia model.
  EXPECT_LE(row(r, "flexible / full inertia / 2 modes").max_error, row(r, "flexible / full inertia / 0 modes").max_error * 1.5);
  // The other formulations of the same models: the classic floating frame on the finest model's
  // superelement captures the sag (its difference from AIC is the formulations' and the
  // integrators' error, a small fraction of the rigid error), and rigid bodies with multipliers
  // miss it exactly as AIC's rigid body does (the same rigid dynamics, two sets of coordinates).
  const io::AdviseRow& ffrf = row(r, "FFRF-LM / flexible / all modes");
  const io::AdviseRow& rigid_lm = row(r, "rigid-LM");
  ASSERT_TRUE(ffrf.ran) << ffrf.failure;
  ASSERT_TRUE(rigid_lm.ran) << rigid_lm.failure;
  std::printf("soft link: rigid %.4f deg, rigid-LM %.4f deg, FFRF-LM %.2e deg (%d coordinates + %d multipliers)\n",
              rigid.max_error / kDeg, rigid_lm.max_error / kDeg, ffrf.max_error / kDeg, ffrf.dofs, ffrf.multipliers);
  EXPECT_TRUE(ffrf.within);
  EXPECT_LT(ffrf.max_error, 0.02 * rigid.max_error);
  EXPECT_EQ(ffrf.multipliers, 6);            // one hinge to ground: 6 constraint equations
  EXPECT_EQ(ffrf.dofs, 6 + (12 + 4 - 6) + 1);  // frame, frame-clamped modes of the 12 interface dofs
                                               // and 4 internal modes, hinge angle
  EXPECT_NEAR(rigid_lm.max_error, rigid.max_error, 0.02 * rigid.max_error);
  EXPECT_FALSE(rigid_lm.within);
}

TEST(Advise, CommandLineTableAndBadOptions) {
  TempDir dir;
  write_link(dir, "link.se", 2);
  const auto scene = dir.write("scene.yaml", kFall);
  const auto r = run_seflex("advise " + q(scene) + " --tol 0.1 --t-end 0.2 --csv " + q(dir / "advise.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("recommended: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("horizon: 0.2 s"), std::string::npos) << r.out;
  const Csv csv = read_csv(dir / "advise.csv");
  EXPECT_EQ(csv.rows.size(), 7u);  // reference, 0 modes, simplified all/0 modes, rigid, FFRF-LM, rigid-LM
  double recommended = 0;
  for (double x : csv.column("recommended")) recommended += x;
  EXPECT_EQ(recommended, 1.0);
  EXPECT_EQ(run_seflex("advise " + q(scene)).exit_code, 2);               // --tol missing
  EXPECT_EQ(run_seflex("advise " + q(scene) + " --tol -1").exit_code, 2);  // not an angle > 0
  std::string other = kFall;
  for (auto at = other.find("H1"); at != std::string::npos; at = other.find("H1")) other.replace(at, 2, "HX");
  const auto alt = dir.write("alt.yaml", other);
  const auto bad = run_seflex("advise " + q(scene) + " --tol 0.1 --alternative " + q(alt));
  EXPECT_EQ(bad.exit_code, 3);
  EXPECT_NE(bad.err.find("no hinge 'H1'"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace seflex::test
