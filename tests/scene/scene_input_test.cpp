// Bad scene files: every message names scene.yaml:LINE, the key path and what was expected (unknown
// keys with a "did you mean" hint); seflex run exits 3 without writing results. Also run under
// ASan/UBSan.
#include <gtest/gtest.h>

#include "scene_fixture.hpp"
#include "seflex/scene/scene.hpp"

namespace seflex {
namespace {

const char* kGood = R"(title: two links
bodies:
  - name: a
    superelement: link.se
  - name: b
    superelement: link.se
    placement: {position: [1, 0, 0]}
hinges:
  - {name: H1, parent: ground, child: a.1, axis: [0, 0, 1]}
  - {name: H2, parent: a.5, child: b.1, axis: [0, 0, 1]}
springs:
  - {hinge: H2, torque_at_0: 1.0}
integrator:
  t_end: 1.0
)";

/// Replace line `line` (1-based) of kGood by `text` (several lines allowed) and build the scene.
std::string scene_error(const std::string& text) {
  test::TempDir dir;
  test::write_link(dir, "link.se");
  const auto path = dir.write("scene.yaml", text);
  try {
    scene::build_scene(scene::read_scene(path));
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string edit(int line, const std::string& replacement) {
  std::istringstream in(kGood);
  std::string out, l;
  for (int i = 1; std::getline(in, l); ++i) out += (i == line ? replacement : l) + "\n";
  return out;
}

void expect_parts(const std::string& msg, const std::vector<std::string>& parts) {
  for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << msg << "\n  lacks: " << p;
}

TEST(SceneInput, GoodSceneBuilds) { EXPECT_EQ(scene_error(kGood), "(no error)"); }

TEST(SceneInput, UnknownKeysSuggestTheNearestName) {
  expect_parts(scene_error(edit(9, "  - {name: H1, parent: ground, chld: a.1, axis: [0, 0, 1]}")),
               {"scene.yaml:9: hinges[0].chld: unknown key (did you mean 'child'?)"});
  expect_parts(scene_error(edit(14, "  t_ned: 1.0")), {"scene.yaml:14: integrator.t_ned: unknown key (did you mean 't_end'?)"});
  expect_parts(scene_error(edit(1, "titel: x")), {"scene.yaml:1: titel: unknown key (did you mean 'title'?)"});
  expect_parts(scene_error(edit(6, "    superelement: link.se\n    fidelty: rigid")),
               {"scene.yaml:7: bodies[1].fidelty: unknown key (did you mean 'fidelity'?)"});
}

TEST(SceneInput, BadValuesNameLineKeyAndExpectation) {
  expect_parts(scene_error(edit(14, "  t_end: soon")), {"scene.yaml:14: integrator.t_end: expected a number, got 'soon'"});
  expect_parts(scene_error(edit(14, "  t_end: -1")), {"scene.yaml:14: integrator.t_end: expected a number > 0"});
  expect_parts(scene_error(edit(9, "  - {name: H1, parent: ground, child: a.1, axis: [0, 1]}")),
               {"scene.yaml:9: hinges[0].axis: expected a vector [x, y, z] of 3 numbers"});
  expect_parts(scene_error(edit(9, "  - {name: H1, parent: ground, child: a.1, axis: [0, 0, 0]}")),
               {"scene.yaml:9: hinges[0].axis: expected a nonzero vector"});
  expect_parts(scene_error(edit(4, "    superelement: link.se\n    fidelity: elastic")),
               {"scene.yaml:5: bodies[0].fidelity: expected flexible or rigid, got 'elastic'"});
  expect_parts(scene_error(edit(13, "integrator:\n  method: euler")),
               {"scene.yaml:14: integrator.method: expected generalized-alpha, radau5 or rk4, got 'euler'"});
  expect_parts(scene_error(edit(14, "  t_end: 1.0\n  radau: {max_iterations: 1}")),
               {"scene.yaml:15: integrator.radau.max_iterations: expected a number >= 2"});
  expect_parts(scene_error(edit(14, "  t_end: 1.0\n  radau: {jacobian_theta: 1.5}")),
               {"scene.yaml:15: integrator.radau.jacobian_theta: expected a contraction rate in [0, 1)"});
  expect_parts(scene_error(edit(14, "  rho_inf: 0.5")), {"integrator.t_end: missing (expected the end time [s])"});
}

TEST(SceneInput, BadReferencesNameTheItem) {
  expect_parts(scene_error(edit(10, "  - {name: H2, parent: a.5, child: bb.1, axis: [0, 0, 1]}")),
               {"scene.yaml:10: hinges[1].child: body 'bb' is not defined (did you mean 'b'?)"});
  expect_parts(scene_error(edit(10, "  - {name: H2, parent: a.5, child: b, axis: [0, 0, 1]}")),
               {"scene.yaml:10: hinges[1].child: expected 'body.node'"});
  expect_parts(scene_error(edit(10, "  - {name: H2, parent: a.5, child: b.3, axis: [0, 0, 1]}")),
               {"scene.yaml:10: hinges[1].child: grid 3 is not an interface node of body 'b' (its interface grids: 1, 5)"});
  expect_parts(scene_error(edit(12, "  - {hinge: H3, torque_at_0: 1.0}")),
               {"scene.yaml:12: springs[0].hinge: hinge 'H3' is not defined (did you mean 'H1'?)"});
  expect_parts(scene_error(edit(12, "  - {hinge: H2}")), {"scene.yaml:12: springs[0].torque_at_0: missing"});
  expect_parts(scene_error(edit(6, "    superelement: missing.se")), {"scene.yaml:6: bodies[1].superelement: ", "missing.se", "cannot open"});
}

TEST(SceneInput, HingeNodesMustCoincide) {
  expect_parts(scene_error(edit(7, "    placement: {position: [1.01, 0, 0]}")),
               {"scene.yaml:10: hinges[1].child: b.1 is at (1.01, 0, 0) but a.5 at (1, 0, 0)", "must coincide within 1e-6 m"});
  expect_parts(scene_error(edit(10, "  - {name: H2, parent: a.5, child: a.1, axis: [0, 0, 1]}")),
               {"scene.yaml:10: hinges[1].child: a.1 is already the child of hinge 'H1'"});
}

TEST(SceneInput, DuplicatesAndSyntax) {
  expect_parts(scene_error(edit(6, "    superelement: link.se\n    superelement: link.se")),
               {"scene.yaml:7: bodies[1].superelement: key given twice"});
  expect_parts(scene_error(edit(5, "  - name: a")), {"scene.yaml:5: bodies[1].name: body 'a' is defined twice"});
  expect_parts(scene_error(edit(9, "  - {name: H1, parent: ground, child: a.1, axis: [0, 0, 1]")), {"scene.yaml:", "not valid YAML"});
  expect_parts(scene_error(edit(12, "  - {hinge: H2, torque_at_0: 1.0}\n  - {hinge: H2, torque_at_0: 2.0}")),
               {"scene.yaml:13: springs[1]: a force element named 'spring.H2' exists already"});
}

TEST(SceneInput, CommandLineExitsThreeWithoutResults) {
  test::TempDir dir;
  test::write_link(dir, "link.se");
  const auto path = dir.write("scene.yaml", edit(14, "  t_end: soon"));
  const auto r = test::run_seflex("run " + test::q(path) + " -o " + test::q(dir / "out"));
  EXPECT_EQ(r.exit_code, 3);
  expect_parts(r.err, {"scene.yaml:14: integrator.t_end: expected a number, got 'soon'"});
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "history.csv"));
  const auto bad_option = test::run_seflex("run " + test::q(path) + " -o " + test::q(dir / "out") + " --inertia heavy");
  EXPECT_EQ(bad_option.exit_code, 2);
  expect_parts(bad_option.err, {"--inertia expects simplified or full, got 'heavy'"});
}

}  // namespace
}  // namespace seflex
