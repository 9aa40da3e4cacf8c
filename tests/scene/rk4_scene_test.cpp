// `integrator.method: rk4` and `radau5` in a scene: the explicit foil and the fifth-order implicit
// method run through seflex run. A rigid link released horizontally latches at -60 deg at the fall
// time of a uniform rod, t = int_0^60deg dtheta / sqrt(3 g sin(theta) / L) (energy; quadrature with
// theta = u^2); a flexible link at a step far above the explicit stability limit stops with exit 4,
// a "failed" summary and the results computed until then; radau5 with the multiplier formulations
// is refused before the run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>
#include <numbers>

#include "scene_fixture.hpp"

namespace seflex::test {
namespace {

const char* kScene = R"(bodies:
  - {name: link, superelement: link.se, fidelity: FIDELITY}
hinges:
  - {name: H1, parent: ground, child: link.1, axis: [0, 0, 1]}
locks:
  - {hinge: H1, angle_deg: -60, stiffness: 100}
loads:
  gravity: [0, -9.81, 0]
integrator: {method: METHOD, t_end: 1.0, step: STEP, tolerance: {position: 1.0e-8, angle: 1.0e-8}}
output: {interval: 0.01}
)";

std::string scene_text(const std::string& fidelity, const std::string& step, const std::string& method = "rk4") {
  std::string s = kScene;
  s.replace(s.find("METHOD"), 6, method);
  s.replace(s.find("FIDELITY"), 8, fidelity);
  s.replace(s.find("STEP"), 4, step);
  return s;
}

/// Lock time of the rigid link's scene run with `method` (events.csv), and the fall time of the
/// uniform rod by Simpson's rule on 2000 intervals.
std::pair<double, double> rigid_link_lock_time(const std::string& method) {
  TempDir dir;
  write_link(dir, "link.se", 2);
  const auto scene = dir.write("scene.yaml", scene_text("rigid", "1.0e-3", method));
  const auto r = run_seflex("run " + q(scene) + " -o " + q(dir / "out") + " --no-animation");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::string events = read_file(dir / "out" / "events.csv");
  const auto at = events.find(",lock,lock.H1,");
  EXPECT_NE(at, std::string::npos) << events;
  if (at == std::string::npos) return {0.0, 1.0};
  const double t_lock = std::stod(events.substr(events.rfind('\n', at) + 1));
  // What set the steps (summary.json "steps_set_by"): the lock's crossing cut one accepted step
  // (radau5: its root on the collocation polynomial) or two (rk4: the first cut, by a straight line
  // through the angles, ends just short of it).
  const std::string summary = read_file(dir / "out" / "summary.json");
  const std::string key = "\"lock_crossing\": ";
  const auto at_key = summary.find(key);
  EXPECT_NE(summary.find("\"steps_set_by\": {"), std::string::npos) << summary;
  EXPECT_NE(at_key, std::string::npos) << summary;
  if (at_key != std::string::npos) {
    const int cut = std::stoi(summary.substr(at_key + key.size()));
    EXPECT_EQ(cut, method == "radau5" ? 1 : 2) << summary;
    EXPECT_NE(read_file(dir / "out" / "summary.txt").find("lock_crossing " + std::to_string(cut)), std::string::npos);
  }
  const int n = 2000;
  const double theta = std::numbers::pi / 3, b = std::sqrt(theta), h = b / n, g = 9.81, L = 1.0;
  auto f = [&](double u) { return u == 0.0 ? 2.0 / std::sqrt(3.0 * g / L) : 2.0 * u / std::sqrt(3.0 * g * std::sin(u * u) / L); };
  double s = f(0) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(i * h);
  return {t_lock, s * h / 3.0};
}

TEST(RunRk4, RigidLinkLatchesAtTheFallTime) {
  const auto [t_lock, t_ref] = rigid_link_lock_time("rk4");
  // measured (2026-11-28): 3.4e-10 relative (RK4 at 1 ms and the located event; Simpson's rule on 2000
  // intervals for the reference); tolerance 1e-9
  EXPECT_NEAR(t_lock, t_ref, 1e-9 * t_ref) << "rk4 lock time " << t_lock << " s, analytic " << t_ref << " s";
}

// The same with Radau IIA-5, adaptive at local error 1e-8 (its steps do not land on the output times;
// the crossing comes from its collocation polynomial).
TEST(RunRadau5, RigidLinkLatchesAtTheFallTime) {
  const auto [t_lock, t_ref] = rigid_link_lock_time("radau5");
  std::printf("radau5 lock time %.12f s, analytic %.12f s (relative %.2e)\n", t_lock, t_ref, std::abs(t_lock / t_ref - 1));
  // measured (2026-12-06): 3.8e-11 relative; tolerance 1e-9
  EXPECT_NEAR(t_lock, t_ref, 1e-9 * t_ref) << "radau5 lock time " << t_lock << " s, analytic " << t_ref << " s";
}

TEST(RunRadau5, MultiplierFormulationsRefuseIt) {
  TempDir dir;
  write_link(dir, "link.se", 2);
  const auto scene = dir.write("scene.yaml", scene_text("flexible", "1.0e-3", "radau5"));
  for (const char* formulation : {"ffrf-lm", "rigid-lm"}) {
    const auto r = run_seflex("run " + q(scene) + " -o " + q(dir / "out") + " --no-animation --formulation " + formulation);
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(std::string("integrator.method radau5: the formulation ") + formulation +
                         " integrates with generalized-alpha only"),
              std::string::npos)
        << r.err;
  }
}

TEST(RunRk4, StepAboveTheStabilityLimitFailsCleanly) {
  TempDir dir;
  write_link(dir, "link.se", 2);
  const auto scene = dir.write("scene.yaml", scene_text("flexible", "5.0e-3"));
  const auto r = run_seflex("run " + q(scene) + " -o " + q(dir / "out") + " --no-animation");
  EXPECT_EQ(r.exit_code, 4) << r.out << r.err;
  EXPECT_NE(r.err.find("stability limit"), std::string::npos) << r.err;
  EXPECT_NE(read_file(dir / "out" / "summary.json").find("\"status\": \"failed\""), std::string::npos);
  EXPECT_GE(read_csv(dir / "out" / "history.csv").rows.size(), 1u);
}

}  // namespace
}  // namespace seflex::test
