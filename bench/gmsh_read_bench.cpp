// gmsh reader benchmark (issue 4): meshes/panel.geo at a refinement (default 102: about 1.0M dofs)
// read through io::read_model; then the same model written as a Nastran deck (seflex convert) and
// read back. Prints the median of RUNS runs of each step and the peak resident memory.
//   build/bench/gmsh_read_bench [REFINE] [RUNS]      (from the repository root)
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
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

}  // namespace

int main(int argc, char** argv) {
  const int refine = argc > 1 ? std::atoi(argv[1]) : 102;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 3;
  const std::filesystem::path geo = "meshes/panel.geo";
  if (!std::filesystem::exists(geo) || refine < 1 || runs < 1) {
    std::fprintf(stderr, "usage (from the repository root): gmsh_read_bench [REFINE >= 1] [RUNS >= 1]\n");
    return 2;
  }
  seflex::io::ModelReadOptions o;
  o.parameters.push_back({"refine", static_cast<double>(refine)});

  std::size_t nodes = 0;
  const double t_mesh = median_seconds(runs, [&] { nodes = seflex::io::gmsh::load_gmsh_mesh(geo, o.parameters).node_tags.size(); });
  seflex::fem::Model model;
  const double t_read = median_seconds(runs, [&] { model = seflex::io::read_model(geo, o); });
  seflex::fem::GlobalMatrices g;
  const double t_assemble = median_seconds(runs, [&] { g = seflex::fem::assemble(model, seflex::fem::assembly_options(model)); });
  const std::filesystem::path deck = std::filesystem::temp_directory_path() / "seflex_gmsh_read_bench.bdf";
  const double t_write = median_seconds(runs, [&] { seflex::io::write_nastran_file(model, deck, true); });
  const auto deck_mb = static_cast<double>(std::filesystem::file_size(deck)) / 1e6;
  seflex::fem::Model back;
  const double t_back = median_seconds(runs, [&] { back = seflex::io::read_model(deck); });
  std::filesystem::remove(deck);
  struct rusage ru {};
  getrusage(RUSAGE_SELF, &ru);

  std::printf("# gmsh reader benchmark: meshes/panel.geo --set refine=%d, %d runs (medians)\n", refine, runs);
  std::printf("grids %zu (gmsh nodes %zu), CQUAD4 %zu, CBAR %zu, CONM2 %zu, dofs %zu, K nonzeros %ld\n", model.grids.size(), nodes,
              model.shells.size(), model.bars.size(), model.conm2.size(), 6 * model.grids.size(), static_cast<long>(g.K.nonZeros()));
  std::printf("%-52s %8.3f s\n", "gmsh: parse .geo, mesh, extract (load_gmsh_mesh)", t_mesh);
  std::printf("%-52s %8.3f s\n", "read_model (the above + model + finalize)", t_read);
  std::printf("%-52s %8.3f s\n", "fem::assemble K and M", t_assemble);
  std::printf("%-52s %8.3f s  (%.1f MB)\n", "write_nastran_file (seflex convert)", t_write, deck_mb);
  std::printf("%-52s %8.3f s\n", "read_model of the written deck", t_back);
  std::printf("peak RSS %.0f MB\n", static_cast<double>(ru.ru_maxrss) / 1024.0);
  std::printf("# command: build/bench/gmsh_read_bench %d %d\n", refine, runs);
  return 0;
}
