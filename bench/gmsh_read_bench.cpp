// gmsh reader benchmark: meshes/panel.geo at a refinement (default 102: about 1.0M dofs), meshed by
// the gmsh library and saved as .msh in every format it writes; each file read by seflex's own MSH
// reader (io::gmsh::read_msh, what seflex reads a .msh with) and by the gmsh library (what it read
// one with before: libgmsh's own reader and the extraction through its API), side by side in one
// run. Then the whole model: io::read_model of the binary 4.1 file and of the .geo (meshed on the
// fly), K and M assembled, the model written as a Nastran deck and read back. Prints the median of
// RUNS runs of each step and the peak resident memory.
//   build/bench/gmsh_read_bench [REFINE] [RUNS]      (from the repository root)
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "seflex/fem/assembly.hpp"
#include "seflex/io/gmsh_mesh.hpp"
#include "seflex/io/model_reader.hpp"
#include "seflex/io/nastran_writer.hpp"

namespace {

double median_seconds(int runs, const std::function<void()>& f) {
  std::vector<double> t;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

std::size_t elements(const seflex::io::gmsh::MeshData& m) {
  std::size_t n = 0;
  for (const auto& g : m.groups)
    for (const auto& b : g.blocks) n += b.count();
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  namespace gmsh = seflex::io::gmsh;
  const int refine = argc > 1 ? std::atoi(argv[1]) : 102;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 3;
  const std::filesystem::path geo = "meshes/panel.geo";
  if (!std::filesystem::exists(geo) || refine < 1 || runs < 1) {
    std::fprintf(stderr, "usage (from the repository root): gmsh_read_bench [REFINE >= 1] [RUNS >= 1]\n");
    return 2;
  }
  seflex::io::ModelReadOptions o;
  o.parameters.push_back({"refine", static_cast<double>(refine)});
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "seflex_gmsh_read_bench";
  std::filesystem::create_directories(dir);

  std::printf("# gmsh reader benchmark: meshes/panel.geo --set refine=%d, %d runs (medians)\n", refine, runs);
  std::printf("%-22s %9s %10s %10s %8s %8s\n", "file", "MB", "seflex [s]", "libgmsh [s]", "ratio", "same");
  struct Format {
    const char* name;
    double version;
    bool binary;
  };
  std::filesystem::path msh41_binary;
  for (const Format f : {Format{"msh41_binary", 4.1, true}, Format{"msh41", 4.1, false}, Format{"msh22_binary", 2.2, true},
                         Format{"msh22", 2.2, false}}) {
    const std::filesystem::path path = dir / (std::string(f.name) + ".msh");
    gmsh::library::write_msh(geo, o.parameters, path, f.version, f.binary);
    if (f.binary && f.version > 4) msh41_binary = path;
    gmsh::MeshData ours, theirs;
    const double t_ours = median_seconds(runs, [&] { ours = gmsh::read_msh(path); });
    const double t_theirs = median_seconds(runs, [&] { theirs = gmsh::library::read(path, {}); });
    // The same nodes and elements (the library keeps format 2's copies of an element for each more
    // group of its entity: the panel's points in two groups, so more elements there).
    const bool same = ours.node_tags.size() == theirs.node_tags.size() && ours.groups.size() == theirs.groups.size() &&
                      (f.version < 3 || elements(ours) == elements(theirs));
    std::printf("%-22s %9.1f %10.3f %10.3f %8.1f %8s\n", path.filename().c_str(),
                static_cast<double>(std::filesystem::file_size(path)) / 1e6, t_ours, t_theirs, t_theirs / t_ours, same ? "yes" : "NO");
  }

  seflex::io::ModelReadOptions props;
  props.properties = "meshes/panel.props.bdf";
  seflex::fem::Model model;
  const double t_msh = median_seconds(runs, [&] { model = seflex::io::read_model(msh41_binary, props); });
  const double t_geo = median_seconds(runs, [&] { model = seflex::io::read_model(geo, o); });
  seflex::fem::GlobalMatrices g;
  const double t_assemble = median_seconds(runs, [&] { g = seflex::fem::assemble(model, seflex::fem::assembly_options(model)); });
  const std::filesystem::path deck = dir / "panel.bdf";
  const double t_write = median_seconds(runs, [&] { seflex::io::write_nastran_file(model, deck, true); });
  const auto deck_mb = static_cast<double>(std::filesystem::file_size(deck)) / 1e6;
  seflex::fem::Model back;
  const double t_back = median_seconds(runs, [&] { back = seflex::io::read_model(deck); });
  std::filesystem::remove_all(dir);
  struct rusage ru {};
  getrusage(RUSAGE_SELF, &ru);

  std::printf("grids %zu, CQUAD4 %zu, CBAR %zu, CONM2 %zu, dofs %zu, K nonzeros %ld\n", model.grids.size(), model.shells.size(),
              model.bars.size(), model.conm2.size(), 6 * model.grids.size(), static_cast<long>(g.K.nonZeros()));
  std::printf("%-52s %8.3f s\n", "read_model of msh41_binary.msh (+ model, finalize)", t_msh);
  std::printf("%-52s %8.3f s\n", "read_model of the .geo (gmsh meshes it)", t_geo);
  std::printf("%-52s %8.3f s\n", "fem::assemble K and M", t_assemble);
  std::printf("%-52s %8.3f s  (%.1f MB)\n", "write_nastran_file (seflex convert)", t_write, deck_mb);
  std::printf("%-52s %8.3f s\n", "read_model of the written deck", t_back);
  std::printf("peak RSS %.0f MB\n", static_cast<double>(ru.ru_maxrss) / 1024.0);
  std::printf("# command: build/bench/gmsh_read_bench %d %d\n", refine, runs);
  return 0;
}
