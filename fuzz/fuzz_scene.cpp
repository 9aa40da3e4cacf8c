// Fuzzes the scene reader and model builder (io/scene.hpp): YAML syntax (yaml-cpp), keys, values,
// references between bodies, hinges, springs, dampers, cables, locks, drives, loads, integrator and
// output settings (parse_scene), then build_scene: loading the superelement files, placing bodies,
// merging interface nodes, building the mbd::Model. The scene is never run.
// The input is the scene text, read as scratch/scene.yaml; the scratch folder holds link.se (the
// double-pendulum link of examples/scenes, reduced once at start-up: interface 1,5, frame 3,
// 3 modes), so `superelement: link.se` resolves. Scenes naming a superelement file outside the
// scratch folder are parsed but not built (no files of the machine are read).
// Accepted outcomes: builds, or InputError. Seeds: examples/**/*.yaml, bench/study/*.yaml;
// dictionary fuzz/dict/scene.dict.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.hpp"
#include "seflex/io/scene.hpp"

namespace {

/// True if `p` lies in the scratch folder (lexically: no "..", same parent).
bool in_scratch(const std::filesystem::path& p) {
  const std::filesystem::path n = p.lexically_normal();
  return n.parent_path() == seflex::fuzz::scratch_dir();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  seflex::fuzz::write_link_superelement("link.se");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  seflex::fuzz::run([&] {
    const seflex::io::SceneDescription d = seflex::io::parse_scene(text, seflex::fuzz::scratch_dir() / "scene.yaml");
    for (const auto& b : d.bodies)
      if (!in_scratch(b.superelement)) return;
    seflex::io::build_scene(d);
  });
  return 0;
}
