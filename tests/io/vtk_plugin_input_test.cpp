// The VTK writer is a plugin (libseflex_vtk.so, io/vtk_plugin/) loaded at the first .vtu written:
// a missing or foreign plugin stops `seflex run` and `seflex modes` with exit 1 and a message naming
// the file tried and SEFLEX_VTK_PLUGIN, after everything else was written; a run with --no-animation
// and a modes run without --vtk never load it. Without SEFLEX_VTK_PLUGIN the command finds the
// plugin of its build (beside it), which CI's sanitizer stage thereby loads into an ASan executable.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "scene_fixture.hpp"

namespace seflex::test {
namespace {

/// SEFLEX_VTK_PLUGIN set for the commands started while this object lives.
class PluginVariable {
 public:
  explicit PluginVariable(const std::string& value) { ::setenv("SEFLEX_VTK_PLUGIN", value.c_str(), 1); }
  ~PluginVariable() { ::unsetenv("SEFLEX_VTK_PLUGIN"); }
  PluginVariable(const PluginVariable&) = delete;
  PluginVariable& operator=(const PluginVariable&) = delete;
};

const char* kScene = R"(bodies:
  - {name: link, superelement: link.se}
hinges:
  - {name: H1, parent: ground, child: link.1, axis: [0, 0, 1]}
loads:
  gravity: [0, -9.81, 0]
integrator: {t_end: 0.05, step: 1.0e-3}
output:
  interval: 0.01
  animation: {interval: 0.01}
)";

/// A one-link pendulum scene with an animation, in `dir`.
std::filesystem::path pendulum_scene(const TempDir& dir) {
  write_link(dir, "link.se", 2);
  return dir.write("scene.yaml", kScene);
}

std::filesystem::path bar_deck() {
  return validation_dir() / "mystran_cbar_cantilever_and_freefree_modes" / "BAR-CC-GIV.DAT";
}

std::string not_installed(const std::filesystem::path& tried) {
  return "error: the VTK writer (libseflex_vtk.so) is not installed: looked for " + tried.string() +
         "; set SEFLEX_VTK_PLUGIN to its path\n";
}

TEST(VtkPlugin, RunWithoutThePluginStopsAfterWritingTheRest) {
  TempDir dir;
  const auto scene = pendulum_scene(dir);
  const auto missing = dir / "no-plugin.so";
  PluginVariable var(missing.string());
  const auto r = run_seflex("run " + q(scene) + " -o " + q(dir / "out"));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find(not_installed(missing)), std::string::npos) << r.err;
  // The first sample's row is on disk, and the summary and the events say why the run stopped.
  const Csv h = read_csv(dir / "out" / "history.csv");
  ASSERT_GE(h.rows.size(), 1u);
  EXPECT_EQ(h.column("t").front(), 0.0);
  EXPECT_NE(read_file(dir / "out" / "summary.json").find("\"status\": \"failed\""), std::string::npos);
  const std::string events = read_file(dir / "out" / "events.csv");
  EXPECT_NE(events.find(",error,run,"), std::string::npos) << events;
  EXPECT_NE(events.find(missing.string()), std::string::npos) << events;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "animation.pvd"));
}

TEST(VtkPlugin, RunWithoutAnimationNeverLoadsIt) {
  TempDir dir;
  const auto scene = pendulum_scene(dir);
  PluginVariable var((dir / "no-plugin.so").string());
  const auto r = run_seflex("run " + q(scene) + " -o " + q(dir / "out") + " --no-animation");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(read_csv(dir / "out" / "history.csv").column("t").back(), 0.05, 1e-12);
}

TEST(VtkPlugin, RunWithThePluginOfTheBuildWritesTheSeries) {
  TempDir dir;
  const auto scene = pendulum_scene(dir);
  const auto r = run_seflex("run " + q(scene) + " -o " + q(dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "animation" / "animation_000005.vtu"));
  EXPECT_NE(read_file(dir / "out" / "animation.pvd").find("animation/animation_000005.vtu"), std::string::npos);
}

TEST(VtkPlugin, ModesWithoutThePluginWritesTheCsvThenStops) {
  TempDir dir;
  const auto missing = dir / "no-plugin.so";
  PluginVariable var(missing.string());
  const auto r = run_seflex("modes " + q(bar_deck()) + " --csv modes.csv --vtk modes.vtu", dir.path());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find(not_installed(missing)), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "modes.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "modes.vtu"));
  // Without --vtk the plugin is not needed.
  EXPECT_EQ(run_seflex("modes " + q(bar_deck()) + " --csv again.csv", dir.path()).exit_code, 0);
}

TEST(VtkPlugin, AForeignLibraryIsRefused) {
  Dl_info info{};
  ASSERT_NE(dladdr(reinterpret_cast<void*>(static_cast<double (*)(double)>(&std::cos)), &info), 0);
  ASSERT_NE(info.dli_fname, nullptr);
  const std::string libm = info.dli_fname;  // a shared library that is not a seflex plugin
  TempDir dir;
  PluginVariable var(libm);
  const auto r = run_seflex("modes " + q(bar_deck()) + " --vtk modes.vtu", dir.path());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("error: the VTK writer " + libm + " has no entry point seflex_vtk_plugin: not a seflex plugin\n"),
            std::string::npos)
      << r.err;
}

TEST(VtkPlugin, ModesWithThePluginOfTheBuildWritesTheShapes) {
  TempDir dir;
  const auto r = run_seflex("modes " + q(bar_deck()) + " --vtk modes.vtu", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read_file(dir / "modes.vtu").find("Name=\"mode_01_displacement\""), std::string::npos);
}

}  // namespace
}  // namespace seflex::test
