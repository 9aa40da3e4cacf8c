// Fuzzes the scene reader and model builder (scene/scene.hpp): YAML syntax (yaml-cpp), keys, values,
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
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_support.hpp"
#include "seflex/io/nastran.hpp"
#include "seflex/scene/scene.hpp"
#include "seflex/io/superelement_file.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"

namespace {

/// Reduce examples/scenes/link.bdf (interface grids 1 and 5, frame grid 3, 3 fixed-interface modes:
/// the double-pendulum link) and save it in the scratch folder. Aborts if that fails.
void write_link_superelement(const std::string& name) {
  try {
    const seflex::fem::Model model = seflex::io::read_nastran(std::filesystem::path(SEFLEX_SOURCE_DIR) / "examples/scenes/link.bdf");
    seflex::reduction::SuperelementOptions o;
    o.interface_ids = {1, 5};
    o.frame_node = 3;
    o.modes.modes = 3;
    o.name = "link";
    seflex::io::SaveOptions save;
    save.overwrite = true;
    seflex::io::save_superelement(seflex::reduction::reduce_to_superelement(model, o), seflex::fuzz::scratch_dir() / name, save);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "seflex fuzz: cannot make %s: %s\n", name.c_str(), e.what());
    std::abort();
  }
}

/// True if `p` lies in the scratch folder (lexically: no "..", same parent).
bool in_scratch(const std::filesystem::path& p) {
  const std::filesystem::path n = p.lexically_normal();
  return n.parent_path() == seflex::fuzz::scratch_dir();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  write_link_superelement("link.se");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  seflex::fuzz::run([&] {
    const seflex::scene::SceneDescription d = seflex::scene::parse_scene(text, seflex::fuzz::scratch_dir() / "scene.yaml");
    for (const auto& b : d.bodies)
      if (!in_scratch(b.superelement)) return;
    seflex::scene::build_scene(d);
  });
  return 0;
}
