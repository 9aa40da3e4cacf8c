// seflex run --formulation: the floating frame (ffrf-lm) and rigid bodies with multipliers
// (rigid-lm) through the CLI, against AIC and against the analytic small-angle period.
#include <gtest/gtest.h>

#include <cmath>

#include "scene_fixture.hpp"
#include "seflex/io/superelement_file.hpp"
#include "seflex/superelement/inertia_invariants.hpp"

namespace seflex::test {
namespace {

const char* kScene = R"(title: pendulum released horizontally
bodies:
  - {name: link, superelement: link.se, fidelity: FIDELITY, inertia: full}
hinges:
  - {name: H1, parent: ground, child: link.1, axis: [0, 0, 1]}
loads:
  gravity: [0, -9.81, 0]
integrator:
  rho_inf: 0.8
  t_end: 0.6
  step: 1.0e-3
  tolerance: {position: 1.0e-9, angle: 1.0e-9}
output:
  interval: 0.01
)";

std::string scene_text(const std::string& fidelity) {
  std::string s = kScene;
  s.replace(s.find("FIDELITY"), 8, fidelity);
  return s;
}


}  // namespace

// The flexible 1 m aluminium link (4 beam elements, 6 frame-clamped modes, full inertia) swinging
// down: the floating frame and AIC agree on the hinge angle to the formulations' difference
// (tests/mbd/ffrf_flexible_test.cpp measures it converging at second order in h), here within
// 1e-3 deg (measured 5.5e-4) while the link swings through ~90 deg; rigid-lm on the rigid link
// agrees with AIC's rigid body (both exact rigid dynamics) to the integration error at the local
// tolerance 1e-9: within 1e-4 deg (measured 4e-5).
TEST(RunFormulation, FloatingFrameAndRigidMatchAic) {
  TempDir dir;
  write_link(dir, "link.se");
  const auto flex = dir.write("flex.yaml", scene_text("flexible"));
  const auto rigid = dir.write("rigid.yaml", scene_text("rigid"));
  auto phi = [&](const std::string& scene, const std::string& formulation, const std::string& out) {
    const auto r = run_seflex("run " + q(scene) + " -o " + q(dir / out) + " --no-animation --formulation " + formulation);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_csv(dir / out / "history.csv").column("H1.phi_deg");
  };
  const auto aic = phi(flex, "aic", "aic"), ffrf = phi(flex, "ffrf-lm", "ffrf");
  const auto aic_rigid = phi(rigid, "aic", "aic_rigid"), rigid_lm = phi(rigid, "rigid-lm", "rigid_lm");
  ASSERT_FALSE(aic.empty());
  EXPECT_LT(aic.back(), -60.0);  // it really swung
  const double d_ffrf = max_abs_difference(aic, ffrf), d_rigid = max_abs_difference(aic_rigid, rigid_lm);
  std::printf("max |phi_aic - phi_ffrf| = %.2e deg, |phi_aic_rigid - phi_rigid_lm| = %.2e deg\n", d_ffrf, d_rigid);
  EXPECT_LT(d_ffrf, 1e-3);
  EXPECT_LT(d_rigid, 1e-4);
  // summary.json names the formulation and its unknowns: FFRF-LM has the frame (6), the
  // frame-clamped modes of the 12 interface dofs (12 - 6) and the hinge angle; 6 multipliers for
  // the hinge to ground. AIC: the model's dofs, no multipliers.
  const std::string ffrf_summary = read_file(dir / "ffrf" / "summary.json");
  EXPECT_NE(ffrf_summary.find("\"formulation\": \"ffrf-lm\""), std::string::npos) << ffrf_summary;
  EXPECT_NE(ffrf_summary.find("\"dofs\": 13,"), std::string::npos) << ffrf_summary;
  EXPECT_NE(ffrf_summary.find("\"multipliers\": 6,"), std::string::npos) << ffrf_summary;
  const std::string aic_summary = read_file(dir / "aic" / "summary.json");
  EXPECT_NE(aic_summary.find("\"formulation\": \"aic\""), std::string::npos) << aic_summary;
  EXPECT_NE(aic_summary.find("\"multipliers\": 0,"), std::string::npos) << aic_summary;
}

// The floating-frame baseline runs from a superelement without its mesh part (`reduce --no-mesh`):
// its inertia comes from the invariants (docs/ffrf.md). The same link with 2 internal modes, from the
// file with the mesh (FFRF-LM sums over its 5 FE nodes there, the cheaper way for so small a mesh)
// and from the file without: the same motion to round-off and solver tolerance.
TEST(RunFormulation, FloatingFrameRunsWithoutTheMesh) {
  TempDir dir;
  se::Superelement s = write_link(dir, "link.se", 2);
  s.invariants = se::compute_inertia_invariants(s);
  io::drop_mesh(s);
  io::save_superelement(s, dir / "nomesh.se", io::SaveOptions{true});
  std::string text = scene_text("flexible");
  const auto with = dir.write("with.yaml", text);
  text.replace(text.find("link.se"), 7, "nomesh.se");
  const auto without = dir.write("without.yaml", text);
  auto phi = [&](const std::filesystem::path& scene, const std::string& out) {
    const auto r = run_seflex("run " + q(scene) + " -o " + q(dir / out) + " --no-animation --formulation ffrf-lm");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_csv(dir / out / "history.csv").column("H1.phi_deg");
  };
  const auto a = phi(with, "with"), b = phi(without, "without");
  ASSERT_FALSE(b.empty());
  EXPECT_LT(b.back(), -60.0);
  const double d = max_abs_difference(a, b);
  std::printf("FFRF-LM with and without the mesh part: max |phi difference| = %.2e deg\n", d);
  EXPECT_LT(d, 1e-12);  // the same arithmetic either way: measured 0 (2026-11-28)
}

TEST(RunFormulation, RejectsUnknownFormulation) {
  TempDir dir;
  write_link(dir, "link.se");
  const auto scene = dir.write("scene.yaml", scene_text("flexible"));
  const auto r = run_seflex("run " + q(scene) + " -o " + q(dir / "out") + " --formulation adams");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("aic, ffrf-lm or rigid-lm"), std::string::npos) << r.err;
}

}  // namespace seflex::test
