// seflex modes DECK: normal modes of a Nastran deck (SOL 103), printed like Nastran's REAL
// EIGENVALUES table; optionally the eigenvalues as CSV and the mode shapes as a ParaView .vtu.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>

#include "command.hpp"
#include "distributed_run.hpp"
#include "model_args.hpp"
#include "usage_warnings.hpp"
#include "seflex/solutions/card_usage.hpp"
#include "seflex/io/model_reader.hpp"
#include "seflex/io/results_csv.hpp"
#include "seflex/io/vtk_modes.hpp"
#include "seflex/solutions/normal_modes.hpp"

namespace {

using seflex::linalg::EigenBackend;
using seflex::linalg::FactorizationBackend;

const char* normalization_name(seflex::solutions::ModeNormalization n) {
  switch (n) {
    case seflex::solutions::ModeNormalization::Mass: return "MASS";
    case seflex::solutions::ModeNormalization::Max: return "MAX";
    case seflex::solutions::ModeNormalization::Point: return "POINT";
  }
  return "?";
}

int session_size([[maybe_unused]] const seflex::parallel::Session* session) {
#ifdef SEFLEX_HAVE_MPI
  if (session != nullptr) return session->size();
#endif
  return 1;
}

void print_table(const seflex::solutions::NormalModes& r) {
  const Eigen::VectorXd rad = r.radians(), hz = r.cycles();
  std::printf("\n%58s\n", "R E A L   E I G E N V A L U E S");
  if (r.guyan)
    std::printf("   (Guyan reduction: eigenvalues of the %ld-dof a-set %s; %ld omitted dofs condensed statically,\n"
                "    as Nastran does; the mode shapes' omitted dofs are recovered statically)\n",
                static_cast<long>(r.guyan->a_dofs), r.guyan->from_aset ? "of the ASET/ASET1 cards" : "left by OMIT/OMIT1",
                static_cast<long>(r.guyan->o_dofs));
  std::printf("   MODE   EXTRACTION    EIGENVALUE       RADIANS        CYCLES      GENERALIZED    GENERALIZED\n");
  std::printf("    NO.      ORDER                                                    MASS         STIFFNESS\n");
  for (Eigen::Index k = 0; k < r.eigenvalues.size(); ++k)
    std::printf("%7d %9d   %13.6E %13.6E %13.6E %14.6E %14.6E\n", static_cast<int>(k + 1), static_cast<int>(k + 1),
                r.eigenvalues(k), rad(k), hz(k), r.generalized_mass(k), r.generalized_stiffness(k));
}

/// The command on one rank: `session` is null for a serial run, else the distributed session
/// (--backend slepc: SLEPc eigensolver, stdout and files from rank 0 only).
int modes(seflex::app::Args& args, seflex::parallel::Session* session) {
  using seflex::app::UsageError;
  seflex::solutions::ModesOptions o;
  constexpr int kAbsent = std::numeric_limits<int>::min();
  if (session != nullptr) {
    for (const char* serial_only : {"eigensolver", "block-size", "factorization"})
      if (args.value(serial_only))
        throw UsageError(std::string("option --") + serial_only + " selects a serial solver; --backend slepc uses "
                         "SLEPc's Krylov-Schur on a MUMPS factorisation");
#ifdef SEFLEX_HAVE_MPI
    o.external = seflex::app::parallel_backend().slepc_eigenproblem;
#endif
  }
  if (const int count = args.integer("count", kAbsent); count != kAbsent) {
    if (count < 1) throw UsageError("option --count must be at least 1");
    o.count = count;
  }
  const std::string solver = args.value_or("eigensolver", std::string(seflex::linalg::to_string(o.backend)));
  const auto backend = seflex::linalg::parse_eigen_backend(solver);
  if (!backend) throw UsageError("option --eigensolver expects " + std::string(seflex::linalg::eigen_backend_names()) + ", got '" + solver + "'");
  o.backend = *backend;
  if (const int block = args.integer("block-size", kAbsent); block != kAbsent) {
    if (block < 1) throw UsageError("option --block-size must be at least 1");
    o.block_size = block;
  }
  const std::string fact = args.value_or("factorization", std::string(seflex::linalg::to_string(o.factorization)));
  const auto factorization = seflex::linalg::parse_factorization_backend(fact);
  if (!factorization) throw UsageError("option --factorization expects cholmod or ldlt, got '" + fact + "'");
  o.factorization = *factorization;
  if (const int subcase = args.integer("subcase", kAbsent); subcase != kAbsent) o.subcase = subcase;
  const auto csv = args.value("csv");
  const auto vtk = args.value("vtk");
  const bool force = args.flag("force");
  o.ignore_unknown_cards = args.flag("ignore-unknown");
  const seflex::io::ModelReadOptions model_options = seflex::app::model_read_options(args);
  const std::string deck = args.positional("DECK");
  args.finish();
  if (vtk && std::filesystem::path(*vtk).extension() != ".vtu") throw UsageError("--vtk expects a file name ending in .vtu");
  const bool writer = seflex::app::writes_files(session);
  if (csv && writer) seflex::io::check_writable(*csv, force);  // before the work, not after it
  if (vtk && writer) seflex::io::check_writable(*vtk, force);

  const auto t0 = std::chrono::steady_clock::now();
  seflex::fem::Model model = seflex::io::read_model(deck, model_options);
  seflex::app::check_and_print_card_usage(
      model, seflex::solutions::check_card_usage(model, seflex::solutions::Solution::NormalModes,
                                                 {seflex::solutions::select_case(model, o.subcase)},
                                                 seflex::solutions::kInterfaceNone, o.ignore_unknown_cards));
  if (session != nullptr) seflex::app::checkpoint(*session);  // every rank read the deck (or stop them all)
  const auto t1 = std::chrono::steady_clock::now();
  seflex::solutions::NormalModes r;
  std::string assembly;  // how a distributed run assembled (the summary line)
#ifdef SEFLEX_HAVE_MPI
  if (session != nullptr) {
    // Elements partitioned by METIS, each rank assembling its own, unless constraints need the whole model.
    const seflex::parallel::Backend& plugin = seflex::app::parallel_backend();
    const auto refusal = plugin.partition_refusal(model, seflex::solutions::select_case(model, o.subcase).mpc);
    if (!refusal) {
      seflex::parallel::PartitionStats p;
      r = plugin.solve_normal_modes_partitioned(model, o, &p);
      assembly = "partitioned by METIS over " + std::to_string(session->size()) + " ranks (rank 0: " +
                 std::to_string(p.local_elements) + " of " + std::to_string(p.total_elements) + " elements, " +
                 std::to_string(p.local_rows) + " of " + std::to_string(p.total_rows) + " rows), " +
                 std::to_string(p.seconds_assembly).substr(0, std::to_string(p.seconds_assembly).find('.') + 3) + " s";
    } else {
      assembly = "replicated on every rank (" + *refusal + ")";
    }
  }
#endif
  if (assembly.empty() || assembly.rfind("replicated", 0) == 0) r = seflex::solutions::solve_normal_modes(model, o);
  const auto t2 = std::chrono::steady_clock::now();
  const auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };

  std::printf("normal modes of %s", deck.c_str());
  if (r.selection.subcase_id) std::printf(", subcase %d", r.selection.subcase_id);
  if (r.selection.method) std::printf(", METHOD %d", *r.selection.method);
  if (r.selection.spc) std::printf(", SPC %d", *r.selection.spc);
  if (r.selection.mpc) std::printf(", MPC %d", *r.selection.mpc);
  std::printf("\n  %zu grids, %ld free dofs, %ld modes, normalisation %s\n", model.grids.size(), static_cast<long>(r.n_free),
              static_cast<long>(r.eigenvalues.size()), normalization_name(r.normalization));
  if (r.guyan)
    std::printf("  Guyan reduction to the a-set: %ld a-set dofs (%s), %ld omitted dofs condensed statically\n",
                static_cast<long>(r.guyan->a_dofs), r.guyan->from_aset ? "ASET/ASET1" : "all but OMIT/OMIT1",
                static_cast<long>(r.guyan->o_dofs));
  const bool slepc = r.stats.backend_used == seflex::linalg::EigenBackend::Slepc;
  const std::string on = slepc ? "mumps (" + std::to_string(session_size(session)) + " MPI ranks)"
                               : std::string(to_string(o.factorization));
  std::printf("  eigensolver %s on %s, shift %.6E, %ld solved columns, %d %s runs%s\n",
              std::string(to_string(r.stats.backend_used)).c_str(), on.c_str(),
              r.stats.shift, r.stats.operator_applications, r.stats.lanczos_runs, slepc ? "Krylov-Schur" : "Lanczos",
              r.stats.missed_modes_recovered ? (", " + std::to_string(r.stats.missed_modes_recovered) + " recovered by the completeness check").c_str() : "");
  if (!assembly.empty()) std::printf("  assembly: %s\n", assembly.c_str());
  const auto& st = r.stats;
  std::printf("  time: read %.2f s, solve %.2f s (factorisation %.2f, shift calibration %.2f, Lanczos %.2f, "
              "completeness check %.2f, Rayleigh-Ritz %.2f; nnz(L) %.3g)\n",
              seconds(t0, t1), seconds(t1, t2), st.seconds_factorization, st.seconds_calibration, st.seconds_lanczos,
              st.seconds_check, st.seconds_postprocess, st.factorization.factor_nonzeros);
  if (!slepc)  // MUMPS inside SLEPc's solver does not split its time
    std::printf("  factorisation: ordering %.2f s, symbolic %.2f s, numeric %.2f s; %d solves of %ld columns in %.2f s\n",
                st.factorization.seconds_ordering, st.factorization.seconds_symbolic, st.factorization.seconds_numeric,
                st.factorization.solve_calls, st.factorization.solve_columns, st.factorization.seconds_solve);
  print_table(r);
  std::fflush(stdout);

  if (csv && writer) {
    Eigen::MatrixXd rows(r.eigenvalues.size(), 3);
    for (Eigen::Index k = 0; k < rows.rows(); ++k) rows.row(k) << static_cast<double>(k + 1), r.eigenvalues(k), r.cycles()(k);
    seflex::io::write_csv(*csv, {"mode", "eigenvalue", "frequency_hz"}, rows, force);
    std::printf("\nwrote %s\n", csv->c_str());
  }
  if (vtk && writer) {
    seflex::io::write_mode_shapes_vtu(*vtk, model, r, force);
    std::printf("wrote %s\n", vtk->c_str());
  }
  return seflex::app::kOk;
}

int run_modes(seflex::app::Args& args) {
  if (seflex::app::distributed_backend_requested(args.value_or("backend", "serial"))) {
#ifdef SEFLEX_HAVE_MPI
    return seflex::app::run_distributed("modes", [&](seflex::parallel::Session& s) { return modes(args, &s); });
#endif
  }
  return modes(args, nullptr);
}

}  // namespace

SEFLEX_COMMAND(modes, "DECK [--count N] [--csv FILE] [--vtk FILE.vtu] [--eigensolver block|spectra|arpack|dense] "
                      "[--block-size B] [--factorization cholmod|ldlt] [--subcase ID] [--force] [--backend serial|slepc] [--ignore-unknown] "
                      "[--symbol NAME=DIR]...",
               "normal modes (SOL 103): Nastran-style eigenvalue table, CSV of frequencies, mode shapes for ParaView",
               run_modes);
