// seflex buckling DECK: linear buckling (SOL 105) of a Nastran deck: the static preload subcase, then
// the load factors of the METHOD (EIGRL) subcase, printed like Nastran's eigenvalue table of SOL 105;
// optionally the load factors as CSV and the buckling mode shapes as a ParaView .vtu.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>

#include "seflex/solutions/buckling.hpp"
#include "command.hpp"
#include "model_args.hpp"
#include "seflex/io/model_reader.hpp"
#include "seflex/io/results_csv.hpp"
#include "seflex/io/vtk_modes.hpp"
#include "seflex/solutions/card_usage.hpp"
#include "usage_warnings.hpp"

namespace {

namespace linalg = seflex::linalg;
namespace solutions = seflex::solutions;

void print_table(const seflex::solutions::BucklingSolution& s) {
  std::printf("\n%58s\n", "R E A L   E I G E N V A L U E S");
  std::printf("   (eigenvalue = buckling load factor: the preload times it is the critical load)\n");
  std::printf("   MODE   EXTRACTION    EIGENVALUE     GENERALIZED\n");
  std::printf("    NO.      ORDER                      STIFFNESS\n");
  for (Eigen::Index k = 0; k < s.load_factors.size(); ++k)
    std::printf("%7d %9d   %13.6E %14.6E\n", static_cast<int>(k + 1), static_cast<int>(k + 1), s.load_factors(k),
                s.generalized_stiffness(k));
}

int run_buckling(seflex::app::Args& args) {
  using seflex::app::UsageError;
  seflex::solutions::BucklingOptions o;
  constexpr int kAbsent = std::numeric_limits<int>::min();
  if (const int count = args.integer("count", kAbsent); count != kAbsent) {
    if (count < 1) throw UsageError("option --count must be at least 1");
    o.count = count;
  }
  const std::string solver = args.value_or("eigensolver", std::string(linalg::to_string(o.backend)));
  const auto backend = linalg::parse_eigen_backend(solver);
  if (!backend)
    throw UsageError("option --eigensolver expects " + std::string(linalg::eigen_backend_names()) + ", got '" + solver +
                     "'");
  o.backend = *backend;
  const auto csv = args.value("csv");
  const auto vtk = args.value("vtk");
  const bool force = args.flag("force");
  o.ignore_unknown_cards = args.flag("ignore-unknown");
  const seflex::io::ModelReadOptions model_options = seflex::app::model_read_options(args);
  const std::string deck = args.positional("DECK");
  args.finish();
  if (vtk && std::filesystem::path(*vtk).extension() != ".vtu")
    throw UsageError("--vtk expects a file name ending in .vtu");
  if (csv) seflex::io::check_writable(*csv, force);
  if (vtk) seflex::io::check_writable(*vtk, force);

  const auto t0 = std::chrono::steady_clock::now();
  const seflex::fem::Model model = seflex::io::read_model(deck, model_options);
  seflex::app::check_and_print_card_usage(
      model, solutions::check_card_usage(model, solutions::Solution::Buckling, solutions::buckling_case_list(model),
                                         solutions::kInterfaceNone, o.ignore_unknown_cards));
  const seflex::solutions::BucklingSolution s = seflex::solutions::solve_buckling(model, o);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::printf("linear buckling of %s: preload %s", deck.c_str(), solutions::case_name(s.preload).c_str());
  if (s.preload.load) std::printf(" (LOAD %d)", *s.preload.load);
  std::printf(", load factors of %s (METHOD %d", solutions::case_name(s.buckling).c_str(), *s.buckling.method);
  if (s.buckling.spc) std::printf(", SPC %d", *s.buckling.spc);
  std::printf(")\n  %zu grids, %ld free dofs, %ld load factors; eigensolver %s, alpha %.3E, %.2f s\n",
              model.grids.size(), static_cast<long>(s.n_free), static_cast<long>(s.load_factors.size()),
              std::string(linalg::to_string(s.stats.backend_used)).c_str(), s.alpha, seconds);
  if (s.load_factors.size() == 0)
    std::printf("  no positive load factor in the range asked for (the preload may only stiffen the structure)\n");
  print_table(s);
  std::fflush(stdout);

  if (csv) {
    Eigen::MatrixXd rows(s.load_factors.size(), 2);
    for (Eigen::Index k = 0; k < rows.rows(); ++k) rows.row(k) << static_cast<double>(k + 1), s.load_factors(k);
    seflex::io::write_csv(*csv, {"mode", "load_factor"}, rows, force);
    std::printf("\nwrote %s\n", csv->c_str());
  }
  if (vtk) {
    solutions::NormalModes r;
    r.selection = s.buckling;
    r.dofs = s.dofs;
    r.n_free = s.n_free;
    r.normalization = solutions::ModeNormalization::Max;
    r.eigenvalues = s.load_factors;
    r.shapes_g = s.shapes_g;
    r.generalized_stiffness = s.generalized_stiffness;
    r.generalized_mass = Eigen::VectorXd::Zero(s.load_factors.size());
    seflex::io::write_mode_shapes_vtu(*vtk, model, r, force);
    std::printf("wrote %s (field \"eigenvalue\" = load factor; \"frequency_hz\" has no meaning here)\n", vtk->c_str());
  }
  return seflex::app::kOk;
}

}  // namespace

SEFLEX_COMMAND(buckling,
               "DECK [--count N] [--csv FILE] [--vtk FILE.vtu] [--eigensolver block|spectra|arpack|dense] [--force] [--ignore-unknown] "
               "[--symbol NAME=DIR]...",
               "linear buckling (SOL 105): static preload subcase (LOAD), load factors of the METHOD (EIGRL) subcase, "
               "Nastran-style table, CSV of load factors, buckling modes for ParaView",
               run_buckling);
