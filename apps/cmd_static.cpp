// seflex static DECK: linear statics (SOL 101) of a Nastran deck; displacements of every grid in
// the basic system to a CSV file, and a short summary (largest displacement, load and SPC-force
// resultants).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>

#include "command.hpp"
#include "model_args.hpp"
#include "seflex/io/model_reader.hpp"
#include "seflex/io/results_csv.hpp"
#include "seflex/reduction/grid_results.hpp"
#include "seflex/reduction/statics.hpp"

namespace {

void print_resultant(const char* what, const Eigen::Matrix<double, 6, 1>& r) {
  std::printf("  %-22s %13.6E %13.6E %13.6E %13.6E %13.6E %13.6E\n", what, r(0), r(1), r(2), r(3), r(4), r(5));
}

int run_static(seflex::app::Args& args) {
  using seflex::app::UsageError;
  seflex::reduction::StaticOptions o;
  constexpr int kAbsent = std::numeric_limits<int>::min();
  if (const int subcase = args.integer("subcase", kAbsent); subcase != kAbsent) o.subcase = subcase;
  auto out = args.value("-o");
  if (!out) out = args.value("output");
  const bool force = args.flag("force");
  const seflex::io::ModelReadOptions model_options = seflex::app::model_read_options(args);
  const std::string deck = args.positional("DECK");
  args.finish();
  const std::filesystem::path csv = out ? std::filesystem::path(*out)
                                        : std::filesystem::path(std::filesystem::path(deck).stem().string() + "_displacements.csv");
  seflex::io::check_writable(csv, force);  // before the work, not after it

  const auto t0 = std::chrono::steady_clock::now();
  const seflex::fem::Model model = seflex::io::read_model(deck, model_options);
  const seflex::reduction::StaticSolution s = seflex::reduction::solve_static(model, o);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const seflex::reduction::GridTable u = seflex::reduction::grid_vectors_basic(model, s.dofs, s.u_g);
  Eigen::MatrixXd rows(u.rows(), 7);
  Eigen::Index t_max = 0, r_max = 0;
  for (Eigen::Index i = 0; i < u.rows(); ++i) {
    rows(i, 0) = model.grids[static_cast<std::size_t>(i)].id;
    rows.row(i).tail<6>() = u.row(i);
    if (u.row(i).head<3>().norm() > u.row(t_max).head<3>().norm()) t_max = i;
    if (u.row(i).tail<3>().norm() > u.row(r_max).tail<3>().norm()) r_max = i;
  }
  seflex::io::write_csv(csv, {"grid", "t1", "t2", "t3", "r1", "r2", "r3"}, rows, force);

  std::printf("linear statics of %s", deck.c_str());
  if (s.selection.subcase_id) std::printf(", subcase %d", s.selection.subcase_id);
  std::printf(", LOAD %d", *s.selection.load);
  if (s.selection.spc) std::printf(", SPC %d", *s.selection.spc);
  std::printf("\n  %zu grids, %ld free dofs, backward error %.1E, %.2f s\n", model.grids.size(), static_cast<long>(s.n_free),
              s.backward_error, seconds);
  if (u.rows() > 0) {
    const auto t = u.row(t_max), r = u.row(r_max);
    std::printf("  max |translation| %13.6E at grid %d (%.6E %.6E %.6E, basic)\n", t.head<3>().norm(),
                model.grids[static_cast<std::size_t>(t_max)].id, t(0), t(1), t(2));
    std::printf("  max |rotation|    %13.6E at grid %d (%.6E %.6E %.6E, basic)\n", r.tail<3>().norm(),
                model.grids[static_cast<std::size_t>(r_max)].id, r(3), r(4), r(5));
  }
  std::printf("\n  resultants (basic axes, about the origin)   FX            FY            FZ            MX            MY            MZ\n");
  const auto applied = seflex::reduction::resultant_basic(model, s.dofs, s.p_g);
  const auto reaction = seflex::reduction::resultant_basic(model, s.dofs, s.q_g);
  print_resultant("applied load", applied);
  print_resultant("SPC forces", reaction);
  print_resultant("sum", applied + reaction);
  std::printf("\nwrote %s (grid,t1,t2,t3,r1,r2,r3; basic system)\n", csv.string().c_str());
  std::fflush(stdout);
  return seflex::app::kOk;
}

}  // namespace

SEFLEX_COMMAND(static, "DECK [-o results.csv] [--subcase ID] [--force]",
               "linear statics (SOL 101): grid displacements in the basic system to CSV, load and SPC-force resultants",
               run_static);
