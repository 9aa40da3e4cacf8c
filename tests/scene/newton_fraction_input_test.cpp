// integrator.newton.error_fraction (docs/scenes.md): read into the settings; a value outside
// [0, 1) or not a number is refused naming scene.yaml:LINE and the key.
#include <gtest/gtest.h>

#include "scene_fixture.hpp"
#include "seflex/scene/scene.hpp"

namespace seflex {
namespace {

std::string scene_text(const std::string& newton) {
  return "title: one link\n"
         "bodies:\n"
         "  - name: a\n"
         "    superelement: link.se\n"
         "hinges:\n"
         "  - {name: H1, parent: ground, child: a.1, axis: [0, 0, 1]}\n"
         "integrator:\n"
         "  t_end: 1.0\n"
         "  newton: " + newton + "\n";
}

struct Outcome {
  std::string error = "(no error)";
  double fraction = -1.0;
};

Outcome read(const std::string& newton) {
  test::TempDir dir;
  test::write_link(dir, "link.se");
  const auto path = dir.write("scene.yaml", scene_text(newton));
  Outcome o;
  try {
    o.fraction = scene::read_scene(path).integrator.newton_error_fraction;
  } catch (const InputError& e) {
    o.error = e.what();
  }
  return o;
}

TEST(NewtonFractionInput, ReadIntoTheSettings) {
  EXPECT_EQ(read("{error_fraction: 0.01}").fraction, 0.01);
  EXPECT_EQ(read("{error_fraction: 0}").fraction, 0.0);  // off: residual and increment tests only
  EXPECT_EQ(read("{max_iterations: 20}").fraction, mbd::IntegratorSettings{}.newton_error_fraction);
}

TEST(NewtonFractionInput, BadValuesNameLineAndKey) {
  const auto one = read("{error_fraction: 1.0}").error;
  EXPECT_NE(one.find("scene.yaml:9: integrator.newton.error_fraction: expected a fraction of the local error tolerance in [0, 1)"),
            std::string::npos) << one;
  const auto neg = read("{error_fraction: -0.1}").error;
  EXPECT_NE(neg.find("scene.yaml:9: integrator.newton.error_fraction: expected a number >= 0"), std::string::npos) << neg;
  const auto word = read("{error_fraction: small}").error;
  EXPECT_NE(word.find("scene.yaml:9: integrator.newton.error_fraction: expected a number, got 'small'"), std::string::npos) << word;
}

}  // namespace
}  // namespace seflex
