// Sparse factorisation backends on real plate stiffness matrices: CHOLMOD supernodal Cholesky vs
// Eigen SimplicialLDLT (both METIS-ordered), the measurement that chose the default
// (docs/benchmarks.md, docs/solvers.md).
//
//   bench/plate_modes_vs_calculix.py --sizes 40,129,408 --decks-only --only seflex --keep /tmp/plates
//   build/bench/factorization_backends [--repeat 3] [--skip-ldlt-above N] /tmp/plates/n40/plate.bdf ...
//
// For each deck: K_ff of the clamped plate (fem assembly and constraints), then per backend the
// first factorisation (ordering + symbolic + numeric), a refactorisation with new values (numeric
// only, as for a new shift), one solve with 1 right-hand side and one with 20; medians of --repeat runs.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/io/nastran.hpp"
#include "seflex/linalg/sparse_factorization.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <typename F>
double seconds(F&& f) {
  const auto t0 = Clock::now();
  f();
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace seflex;
  int repeat = 3;
  long skip_ldlt_above = 2'000'000;
  std::vector<std::string> decks;
  std::string command = "build/bench/factorization_backends";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    command += " " + a;
    if (a == "--repeat" && i + 1 < argc) {
      repeat = std::stoi(argv[++i]);
      command += std::string(" ") + argv[i];
    } else if (a == "--skip-ldlt-above" && i + 1 < argc) {
      skip_ldlt_above = std::stol(argv[++i]);
      command += std::string(" ") + argv[i];
    } else {
      decks.push_back(a);
    }
  }
  if (decks.empty()) {
    std::fprintf(stderr, "usage: factorization_backends [--repeat N] [--skip-ldlt-above DOFS] DECK...\n");
    return 2;
  }
  std::printf("command: %s\nmedians of %d runs\n\n", command.c_str(), repeat);
  std::printf("%10s %8s | %12s %10s %10s %10s %10s | %s\n", "dofs", "backend", "nnz(L)", "factor s", "refactor s",
              "solve1 s", "solve20 s", "deck");
  for (const std::string& deck : decks) {
    const fem::Model model = io::read_nastran(deck);
    const fem::GlobalMatrices g = fem::assemble(model, fem::assembly_options(model));
    const fem::ConstrainedSystem c = fem::apply_constraints(model, g, model.case_control.global.spc);
    const linalg::SparseMatrixd K = c.K_ff.triangularView<Eigen::Lower>();
    const linalg::SparseMatrixd K2 = 1.5 * K;
    const Eigen::MatrixXd B = Eigen::MatrixXd::Random(K.rows(), 20);
    for (auto backend : {linalg::FactorizationBackend::Cholmod, linalg::FactorizationBackend::EigenLdlt}) {
      if (backend == linalg::FactorizationBackend::EigenLdlt && K.rows() > skip_ldlt_above) continue;
      std::vector<double> tf, tr, t1, t20;
      double nnz = 0;
      for (int r = 0; r < repeat; ++r) {
        auto f = linalg::make_factorization(backend);
        tf.push_back(seconds([&] { f->factorize(K); }));
        tr.push_back(seconds([&] { f->factorize(K2); }));
        Eigen::MatrixXd x1 = B.col(0), x20 = B;
        t1.push_back(seconds([&] { f->solve_in_place(x1); }));
        t20.push_back(seconds([&] { f->solve_in_place(x20); }));
        nnz = f->stats().factor_nonzeros;
      }
      std::printf("%10ld %8s | %12.4g %10.3f %10.3f %10.4f %10.4f | %s\n", static_cast<long>(K.rows()),
                  std::string(linalg::to_string(backend)).c_str(), nnz, median(tf), median(tr), median(t1), median(t20),
                  deck.c_str());
      std::fflush(stdout);
    }
  }
  return 0;
}
