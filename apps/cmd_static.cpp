// seflex static DECK: linear statics (SOL 101) of a Nastran deck, every subcase (or --subcase ID);
// displacements of every grid to a CSV file (basic system, or each grid's displacement system with
// --system global as Nastran prints them), and a short summary per subcase (largest displacement,
// load and SPC-force resultants). Cards the deck holds that statics does not use are reported as
// warnings; cards it needs and seflex cannot use refuse the deck (solutions/card_usage.hpp).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>

#include "command.hpp"
#include "model_args.hpp"
#include "usage_warnings.hpp"
#include "seflex/io/model_reader.hpp"
#include "seflex/io/element_results_csv.hpp"
#include "seflex/io/results_csv.hpp"
#include "seflex/fem/element_results.hpp"
#include "seflex/solutions/card_usage.hpp"
#include "seflex/solutions/grid_results.hpp"
#include "seflex/solutions/statics.hpp"

namespace {

namespace solutions = seflex::solutions;

void print_resultant(const char* what, const Eigen::Matrix<double, 6, 1>& r) {
  std::printf("  %-22s %13.6E %13.6E %13.6E %13.6E %13.6E %13.6E\n", what, r(0), r(1), r(2), r(3), r(4), r(5));
}

/// Per-grid rows of a g-set vector: basic components, or each grid's CD components (global).
solutions::GridTable grid_rows(const seflex::fem::Model& model, const solutions::StaticSolution& s, bool global) {
  if (!global) return solutions::grid_vectors_basic(model, s.dofs, s.u_g);
  solutions::GridTable t(static_cast<Eigen::Index>(model.grids.size()), 6);
  for (Eigen::Index i = 0; i < t.rows(); ++i) t.row(i) = s.u_g.segment<6>(6 * i).transpose();
  return t;
}

void print_summary(const seflex::fem::Model& model, const solutions::StaticSolution& s, const solutions::GridTable& u,
                   const char* system) {
  std::printf("\n%s", s.selection.subcase_id ? ("subcase " + std::to_string(s.selection.subcase_id)).c_str() : "case");
  if (!s.selection.label.empty()) std::printf(" (%s)", s.selection.label.c_str());
  if (s.selection.load)
    std::printf(": LOAD %d", *s.selection.load);
  else if (!s.selection.temperature)
    std::printf(": no LOAD (enforced displacements only)");
  if (s.selection.temperature)
    std::printf("%s TEMPERATURE(LOAD) %d", s.selection.load ? "," : ":", *s.selection.temperature);
  if (s.selection.spc) std::printf(", SPC %d", *s.selection.spc);
  if (s.selection.mpc) std::printf(", MPC %d", *s.selection.mpc);
  std::printf("\n  %zu grids, %ld free dofs, backward error %.1E\n", model.grids.size(), static_cast<long>(s.n_free),
              s.backward_error);
  if (u.rows() > 0) {
    Eigen::Index t_max = 0, r_max = 0;
    for (Eigen::Index i = 0; i < u.rows(); ++i) {
      if (u.row(i).head<3>().norm() > u.row(t_max).head<3>().norm()) t_max = i;
      if (u.row(i).tail<3>().norm() > u.row(r_max).tail<3>().norm()) r_max = i;
    }
    const auto t = u.row(t_max), r = u.row(r_max);
    std::printf("  max |translation| %13.6E at grid %d (%.6E %.6E %.6E, %s)\n", t.head<3>().norm(),
                model.grids[static_cast<std::size_t>(t_max)].id, t(0), t(1), t(2), system);
    std::printf("  max |rotation|    %13.6E at grid %d (%.6E %.6E %.6E, %s)\n", r.tail<3>().norm(),
                model.grids[static_cast<std::size_t>(r_max)].id, r(3), r(4), r(5), system);
  }
  std::printf("  resultants (basic axes, about the origin)   FX            FY            FZ            MX            MY            MZ\n");
  const auto applied = solutions::resultant_basic(model, s.dofs, s.p_g);
  const auto reaction = solutions::resultant_basic(model, s.dofs, s.q_g);
  print_resultant("applied load", applied);
  print_resultant("SPC forces", reaction);
  print_resultant("sum", applied + reaction);
}

int run_static(seflex::app::Args& args) {
  using seflex::app::UsageError;
  solutions::StaticOptions o;
  constexpr int kAbsent = std::numeric_limits<int>::min();
  if (const int subcase = args.integer("subcase", kAbsent); subcase != kAbsent) o.subcase = subcase;
  auto out = args.value("-o");
  if (!out) out = args.value("output");
  const std::string system = args.value_or("system", "basic");
  if (system != "basic" && system != "global")
    throw UsageError("option --system expects basic or global (each grid's displacement system CD), got '" + system + "'");
  const bool global = system == "global";
  const bool force = args.flag("force");
  const auto element_csv = args.value("element-results");
  o.ignore_unknown_cards = args.flag("ignore-unknown");
  const seflex::io::ModelReadOptions model_options = seflex::app::model_read_options(args);
  const std::string deck = args.positional("DECK");
  args.finish();
  const std::filesystem::path csv = out ? std::filesystem::path(*out)
                                        : std::filesystem::path(std::filesystem::path(deck).stem().string() + "_displacements.csv");
  seflex::io::check_writable(csv, force);  // before the work, not after it
  if (element_csv) seflex::io::check_writable(*element_csv, force);

  const auto t0 = std::chrono::steady_clock::now();
  const seflex::fem::Model model = seflex::io::read_model(deck, model_options);
  const std::vector<solutions::CaseSelection> cases = solutions::select_cases(model, o.subcase);
  seflex::app::check_and_print_card_usage(
      model, solutions::check_card_usage(model, solutions::Solution::Statics, cases, solutions::kInterfaceNone,
                                         o.ignore_unknown_cards));
  const std::vector<solutions::StaticSolution> solutions = solutions::solve_statics(model, o);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const bool several = solutions.size() > 1;
  const Eigen::Index ng = static_cast<Eigen::Index>(model.grids.size()), c0 = several ? 2 : 1;
  Eigen::MatrixXd rows(ng * static_cast<Eigen::Index>(solutions.size()), c0 + 6);
  std::vector<solutions::GridTable> tables;
  for (std::size_t k = 0; k < solutions.size(); ++k) {
    tables.push_back(grid_rows(model, solutions[k], global));
    for (Eigen::Index i = 0; i < ng; ++i) {
      const Eigen::Index r = static_cast<Eigen::Index>(k) * ng + i;
      if (several) rows(r, 0) = solutions[k].selection.subcase_id;
      rows(r, c0 - 1) = model.grids[static_cast<std::size_t>(i)].id;
      rows.row(r).tail<6>() = tables.back().row(i);
    }
  }
  std::vector<std::string> header = {"grid", "t1", "t2", "t3", "r1", "r2", "r3"};
  if (several) header.insert(header.begin(), "subcase");
  seflex::io::write_csv(csv, header, rows, force);

  std::printf("linear statics of %s: %zu subcase%s, %.2f s\n", deck.c_str(), solutions.size(), several ? "s" : "", seconds);
  for (std::size_t k = 0; k < solutions.size(); ++k)
    print_summary(model, solutions[k], tables[k], global ? "global (CD)" : "basic");
  std::printf("\nwrote %s (%sgrid,t1,t2,t3,r1,r2,r3; %s)\n", csv.string().c_str(), several ? "subcase," : "",
              global ? "each grid's displacement system CD, as Nastran prints them" : "basic system");
  if (element_csv) {
    const seflex::fem::ElementResultMap map = seflex::fem::make_element_result_map(model);
    for (const auto& [card, n] : map.missing)
      std::fprintf(stderr, "warning: %d %s element%s: no element results in seflex\n", n, card.c_str(), n > 1 ? "s" : "");
    Eigen::MatrixXd results(map.rows, static_cast<Eigen::Index>(solutions.size()));
    std::vector<int> ids;
    for (std::size_t k = 0; k < solutions.size(); ++k) {
      results.col(static_cast<Eigen::Index>(k)) = map.apply(solutions[k].u_g);
      ids.push_back(solutions[k].selection.subcase_id);
    }
    seflex::io::write_element_results_csv(*element_csv, map, ids, results, force);
    std::printf("wrote %s (subcase,element,card,component,value: %zu elements; Nastran element force/stress "
                "conventions, element coordinate systems)\n",
                element_csv->c_str(), map.entries.size());
  }
  std::fflush(stdout);
  return seflex::app::kOk;
}

}  // namespace

SEFLEX_COMMAND(static, "DECK [-o results.csv] [--element-results FILE.csv] [--subcase ID] [--system basic|global] [--force] [--ignore-unknown] [--symbol NAME=DIR]...",
               "linear statics (SOL 101) of every subcase (or --subcase ID): grid displacements to CSV (basic system, "
               "or --system global: each grid's CD system as Nastran prints them), load and SPC-force resultants; --element-results: element forces and stresses "
               "(Nastran's conventions) to CSV",
               run_static);
