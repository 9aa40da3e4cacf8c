// Speed of the FE core on square CQUAD4 plates: fem::assemble (K and lumped M into the connectivity
// pattern), fem::apply_constraints (simply supported edges) and fem::mass_properties (grid point
// weight generator, element by element). Prints medians over repeated runs, matrix sizes, the peak
// resident memory, and the command line.
//
//   build/bench/fem_assembly_bench [N1 N2 ...] [--runs R]     (plate of N x N CQUAD4; default 40 130 408)
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/fem/mass_properties.hpp"

using namespace seflex;

namespace {

fem::Model plate(int n) {
  fem::Model m;
  m.files.push_back("plate");
  const double a = 1.0;
  m.grids.reserve(static_cast<std::size_t>((n + 1) * (n + 1)));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      fem::Grid g;
      g.id = 1 + i + (n + 1) * j;
      g.x = Eigen::Vector3d(a * i / n, a * j / n, 0.0);
      m.grids.push_back(g);
    }
  fem::Mat1 mat;
  mat.id = 1;
  mat.E = 7e10;
  mat.nu = 0.3;
  mat.G = mat.E / 2.6;
  mat.rho = 2700;
  m.mat1.push_back(mat);
  fem::ShellProperty p;
  p.id = 1;
  p.mid1 = p.mid2 = p.mid3 = 1;
  p.t = 0.002;
  m.shell_props.push_back(p);
  m.shells.reserve(static_cast<std::size_t>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      fem::Shell s;
      s.id = 1 + i + n * j;
      s.pid = 1;
      const int g0 = 1 + i + (n + 1) * j;
      s.g = {g0, g0 + 1, g0 + n + 2, g0 + n + 1};
      m.shells.push_back(s);
    }
  for (int k = 0; k <= n; ++k)  // simply supported: w = 0 on the edges
    for (int g : {1 + k, 1 + k + (n + 1) * n, 1 + (n + 1) * k, 1 + n + (n + 1) * k}) {
      fem::SpcEntry e;
      e.sid = 1;
      e.grid = g;
      e.c = 0b000100;
      m.spcs.push_back(e);
    }
  fem::finalize(m);
  return m;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

long peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes;
  int runs = 3;
  std::string cmd = argv[0];
  for (int i = 1; i < argc; ++i) {
    cmd += std::string(" ") + argv[i];
    const std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) {
      cmd += std::string(" ") + argv[i + 1];
      runs = std::atoi(argv[++i]);
    } else {
      sizes.push_back(std::atoi(argv[i]));
    }
  }
  if (sizes.empty()) sizes = {40, 130, 408};
  std::printf("command: %s\n", cmd.c_str());
  std::printf("%8s %10s %10s %12s %12s %12s %12s %12s %10s\n", "N", "grids", "dofs", "nnz(K)", "assemble_s",
              "constrain_s", "massprop_s", "per_elem_us", "peakMB");
  for (int n : sizes) {
    const fem::Model m = plate(n);
    std::vector<double> ta, tc, tm;
    long nnz = 0;
    for (int r = 0; r < runs; ++r) {
      auto t0 = std::chrono::steady_clock::now();
      const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
      ta.push_back(seconds_since(t0));
      nnz = static_cast<long>(g.K.nonZeros());
      t0 = std::chrono::steady_clock::now();
      const fem::ConstrainedSystem c = fem::apply_constraints(m, g, 1);
      tc.push_back(seconds_since(t0));
      t0 = std::chrono::steady_clock::now();
      const fem::MassProperties mp = fem::mass_properties(m);
      tm.push_back(seconds_since(t0));
      if (!(std::abs(mp.mass - 2700 * 0.002) < 1e-9) || c.n_free() <= 0) {
        std::fprintf(stderr, "wrong result\n");
        return 1;
      }
    }
    const double elems = static_cast<double>(n) * n;
    std::printf("%8d %10zu %10ld %12ld %12.3f %12.3f %12.3f %12.2f %10ld\n", n, m.grids.size(),
                6L * static_cast<long>(m.grids.size()), nnz, median(ta), median(tc), median(tm), 1e6 * median(ta) / elems,
                peak_rss_mb());
  }
  return 0;
}
