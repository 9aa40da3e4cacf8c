// seflex reduce MODEL --interface ... -o body.se: Craig-Bampton reduction of a Nastran model to an
// absolute-interface-coordinate superelement file, with a summary of what the reduction keeps.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "distributed_run.hpp"
#include "command.hpp"
#include "info_superelement.hpp"
#include "model_args.hpp"
#include "usage_warnings.hpp"
#include "seflex/solutions/card_usage.hpp"
#include "seflex/common/error.hpp"
#include "seflex/io/model_reader.hpp"
#include "seflex/io/results_csv.hpp"
#include "seflex/io/provenance.hpp"
#include "seflex/io/superelement_file.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"

namespace {

using seflex::app::UsageError;
namespace red = seflex::reduction;
namespace linalg = seflex::linalg;
namespace solutions = seflex::solutions;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// "aset" | "bset" | "suport" -> the grids of those cards; otherwise a comma-separated list whose
/// items are grid ids or names of node sets (gmsh physical groups), in that order: "1,3,4",
/// "hinge1,hinge2", "hinges,7".
std::vector<int> interface_ids(const seflex::fem::Model& model, const std::string& spec) {
  const std::string l = lower(spec);
  if (l == "aset") return red::interface_nodes_from_cards(model, red::InterfaceCards::Aset);
  if (l == "bset") return red::interface_nodes_from_cards(model, red::InterfaceCards::Bset);
  if (l == "suport" || l == "support") return red::interface_nodes_from_cards(model, red::InterfaceCards::Suport);
  std::vector<int> ids;
  std::size_t pos = 0;
  while (pos <= spec.size()) {
    const std::size_t comma = std::min(spec.find(',', pos), spec.size());
    std::string item = spec.substr(pos, comma - pos);
    item.erase(std::remove(item.begin(), item.end(), ' '), item.end());
    pos = comma + 1;
    if (item.empty())
      throw UsageError("option --interface: '" + spec +
                       "': expected grid ids or node set names separated by commas "
                       "(e.g. 1,3,4), or aset, bset or suport");
    if (item.find_first_not_of("0123456789") == std::string::npos && item.size() <= 9) {
      ids.push_back(std::stoi(item));
    } else {
      const std::vector<int> set = red::interface_nodes_from_set(model, item);
      ids.insert(ids.end(), set.begin(), set.end());
    }
  }
  return ids;
}

/// --stresses: "all" (every element with results: an empty list) or element ids and ranges separated by
/// commas ("101,205,300:399").
std::vector<int> stress_element_ids(const std::string& spec) {
  if (lower(spec) == "all") return {};
  std::vector<int> ids;
  std::size_t pos = 0;
  const auto bad = [&]() {
    return UsageError("option --stresses: '" + spec + "': expected all, or element ids and ranges separated by commas (e.g. 101,205,300:399)");
  };
  const auto number = [&](const std::string& t) {
    if (t.empty() || t.size() > 9 || t.find_first_not_of("0123456789") != std::string::npos) throw bad();
    return std::stoi(t);
  };
  while (pos <= spec.size()) {
    const std::size_t comma = std::min(spec.find(',', pos), spec.size());
    std::string item = spec.substr(pos, comma - pos);
    item.erase(std::remove(item.begin(), item.end(), ' '), item.end());
    pos = comma + 1;
    const std::size_t colon = item.find(':');
    if (colon == std::string::npos) {
      ids.push_back(number(item));
      continue;
    }
    const int a = number(item.substr(0, colon)), b = number(item.substr(colon + 1));
    if (b < a || b - a > 10000000) throw bad();
    for (int id = a; id <= b; ++id) ids.push_back(id);
  }
  return ids;
}

/// --frame: a grid id, or the name of a node set holding one grid.
int frame_id(const seflex::fem::Model& model, const std::string& spec) {
  if (!spec.empty() && spec.size() <= 9 && spec.find_first_not_of("0123456789") == std::string::npos)
    return std::stoi(spec);
  const std::vector<int> set = red::interface_nodes_from_set(model, spec);
  if (set.size() != 1)
    throw seflex::InputError(
        seflex::SourceRef{model.files.empty() ? std::string() : model.files[0], 0},
        "node set '" + spec + "' holds " + std::to_string(set.size()) + " nodes; expected one for --frame");
  return set.front();
}

void print_vector(const char* label, const Eigen::Vector3d& v) {
  std::printf("  %-30s %14.6E %14.6E %14.6E\n", label, v.x(), v.y(), v.z());
}

void print_summary(const seflex::se::Superelement& s, const red::SuperelementInfo& info,
                   const seflex::fem::Model& model) {
  const auto& st = info.stats;
  std::printf("\nmodel\n  %zu grids, %ld free dofs (f-set), %ld dependent (rigid elements, RBE3, MPC), %ld removed by "
              "AUTOSPC, SPC set %s, MPC set %s\n",
              model.grids.size(), static_cast<long>(st.n_free), static_cast<long>(info.dependent_dofs),
              static_cast<long>(info.autospc_dofs), info.spc_set ? std::to_string(info.spc_set).c_str() : "none",
              info.mpc_set ? std::to_string(info.mpc_set).c_str() : "none");
  std::printf("\ninterface: %d nodes, %d dofs (basic axes)\n", s.num_interfaces(), 6 * s.num_interfaces());
  std::printf("  %8s %14s %14s %14s   (position from the frame node)\n", "grid", "x", "y", "z");
  for (const auto& n : s.interfaces)
    std::printf("  %8d %14.6E %14.6E %14.6E\n", n.id, n.p_BoN_B.x(), n.p_BoN_B.y(), n.p_BoN_B.z());
  std::printf("\nframe node %d at (%.6g, %.6g, %.6g) in basic%s\n", s.frame_node_id, s.p_OBo.x(), s.p_OBo.y(),
              s.p_OBo.z(), info.frame_chosen ? ", chosen as the free grid nearest the centre of mass" : "");
  std::printf("\nmass properties of the full model (body axes = basic axes, WTMASS applied)\n");
  std::printf("  %-30s %14.6E\n", "mass", s.mass);
  print_vector("centre of mass from frame node", s.p_BoCm_B);
  std::printf("  inertia about the centre of mass\n");
  for (int r = 0; r < 3; ++r) print_vector("", s.I_Cm_B.row(r).transpose());
}

void print_modes(const seflex::se::Superelement& s, const red::CraigBamptonOptions& o) {
  std::printf("\nfixed-interface modes: %d kept", s.num_modes);
  if (o.modes && *o.modes > s.num_modes) std::printf(" (%d asked; the interior has no more)", *o.modes);
  if (o.fmax_hz) std::printf(" (all up to %g Hz)", *o.fmax_hz);
  std::printf("\n");
  for (int k = 0; k < s.num_modes; ++k) std::printf("  %4d %14.6f Hz\n", k + 1, s.mode_frequencies_hz(k));
  seflex::app::print_truncation(s.truncation, "none (all interior modes kept)");
}

void print_free_free(const seflex::se::Superelement& s, int elastic, const Eigen::VectorXd* full) {
  const Eigen::VectorXd lambda = red::reduced_eigenvalues(s, 6 + elastic);
  std::printf("\nreduced model: n = %d (6 x %d interface dofs + %d modes); free-free frequencies\n", s.size(),
              s.num_interfaces(), s.num_modes);
  if (full) std::printf("  %4s %16s %16s %12s\n", "mode", "reduced (Hz)", "full FE (Hz)", "rel. error");
  for (Eigen::Index k = 0; k < lambda.size(); ++k) {
    const double f = red::eigenvalue_to_hz(lambda(k));
    std::printf("  %4ld %16.6f", static_cast<long>(k + 1), f);
    if (full && k < full->size()) {
      const double g = red::eigenvalue_to_hz((*full)(k));
      // Rigid-body modes come out at round-off frequencies, sqrt(eps) times the model's highest
      // frequency: up to ~1e-5 of the highest one shown (1.4e-6 for the yoke); 1e-4 leaves a margin.
      if (g > 1e-4 * red::eigenvalue_to_hz(lambda(lambda.size() - 1)))
        std::printf(" %16.6f %12.3E", g, (f - g) / g);
      else
        std::printf(" %16.6f %12s", g, "(rigid)");
    }
    std::printf("\n");
  }
}

/// The command on one rank: `session` is null for a serial run, else the distributed session
/// (--backend slepc: MUMPS factor of K_ii, SLEPc eigensolver, stdout and the file from rank 0 only).
int reduce(seflex::app::Args& args, seflex::parallel::Session* session) {
  constexpr int kAbsent = std::numeric_limits<int>::min();
  if (session != nullptr && args.value("eigensolver"))
    throw UsageError("option --eigensolver selects a serial solver; --backend slepc uses MUMPS and SLEPc");
  std::optional<std::string> out = args.value("-o");
  if (!out) out = args.value("output");
  const auto spec = args.value("interface");
  const int modes = args.integer("modes", kAbsent);
  const double fmax = args.number("fmax", std::numeric_limits<double>::quiet_NaN());
  const auto frame = args.value("frame");
  const auto name = args.value("name");
  const int compare = args.integer("compare", kAbsent);
  const std::string solver = args.value_or("eigensolver", "spectra");
  const bool no_mesh = args.flag("no-mesh");
  const bool no_stiffening = args.flag("no-stiffening");
  const bool force = args.flag("force");
  const bool ignore_unknown = args.flag("ignore-unknown");
  const auto stresses = args.value("stresses");
  const seflex::io::ModelReadOptions model_options = seflex::app::model_read_options(args);
  const std::string model_path = args.positional("MODEL");
  args.finish();

  if (!spec) throw UsageError("missing --interface (grid ids like 1,3,4; aset, bset, suport; or a node set name)");
  if (!out) throw UsageError("missing -o FILE (the superelement file to write)");
  if (modes != kAbsent && !std::isnan(fmax)) throw UsageError("give either --modes or --fmax, not both");
  if (modes != kAbsent && modes < 0) throw UsageError("option --modes expects a number >= 0");
  if (!std::isnan(fmax) && !(fmax > 0 && std::isfinite(fmax)))
    throw UsageError("option --fmax expects a frequency > 0 (Hz)");
  if (compare != kAbsent && compare < 1) throw UsageError("option --compare expects a number of elastic modes >= 1");
  const auto backend = linalg::parse_eigen_backend(solver);
  if (!backend) throw UsageError("option --eigensolver expects " + std::string(linalg::eigen_backend_names()) + ", got '" + solver + "'");
  const bool writer = seflex::app::writes_files(session);
  if (writer && !force && std::filesystem::exists(*out))  // before the work, not after it
    throw seflex::InputError(seflex::SourceRef{*out, 0},
                             "exists already; refusing to overwrite it (use --force to replace it)");

  const auto t0 = std::chrono::steady_clock::now();
  seflex::fem::Model model = seflex::io::read_model(model_path, model_options);
  red::SuperelementOptions o;
  o.interface_ids = interface_ids(model, *spec);
  const std::string spec_lower = lower(*spec);
  o.interface_cards = spec_lower == "aset" ? solutions::kInterfaceAset
                      : spec_lower == "bset" ? solutions::kInterfaceBset
                      : (spec_lower == "suport" || spec_lower == "support") ? solutions::kInterfaceSuport
                                                                            : solutions::kInterfaceNone;
  const solutions::CardUsage usage = solutions::check_card_usage(
      model, solutions::Solution::CraigBampton, {solutions::select_case(model)}, o.interface_cards, ignore_unknown);
  seflex::app::check_and_print_card_usage(model, usage);
  o.ignore_unknown_cards = ignore_unknown;
  if (frame) o.frame_node = frame_id(model, *frame);
  if (!std::isnan(fmax))
    o.modes.fmax_hz = fmax;
  else
    o.modes.modes = modes == kAbsent ? 0 : modes;
  o.modes.backend = *backend;
  std::string assembly;  // how a distributed run assembled (the summary line)
#ifdef SEFLEX_HAVE_MPI
  std::shared_ptr<seflex::parallel::PartitionedSystem> partitioned;
  if (session != nullptr) {
    const seflex::parallel::Backend& plugin = seflex::app::parallel_backend();
    o.modes.factorization_maker = plugin.make_mumps_factorization;
    o.modes.external = plugin.slepc_eigenproblem;
    // The geometric-stiffness projections shared out over the ranks, then summed on every rank.
    o.stiffening_rank = session->rank();
    o.stiffening_ranks = session->size();
    o.sum_stiffening = plugin.sum_over_ranks;
    // Elements partitioned by METIS, each rank assembling its own, unless constraints need the whole model.
    if (const auto refusal = plugin.partition_refusal(model, solutions::select_case(model).mpc)) {
      assembly = "replicated on every rank (" + *refusal + ")";
    } else {
      assembly = "partitioned by METIS over " + std::to_string(session->size()) + " ranks";
      o.assemble = [&](const seflex::fem::ConstraintOptions& co) {
        seflex::fem::GlobalMatrices whole;
        partitioned = plugin.assemble_partitioned(model, co, &whole);
        assembly += " (rank 0: " + std::to_string(partitioned->local_elements) + " of " +
                    std::to_string(partitioned->total_elements) + " elements, " +
                    std::to_string(partitioned->row_begin[1]) + " of " + std::to_string(partitioned->n_free()) + " rows)";
        return whole;
      };
      o.basis = [&](const std::vector<Eigen::Index>& boundary, const red::CraigBamptonOptions& cbo) {
        red::CraigBamptonBasis b = plugin.craig_bampton_partitioned(*partitioned, boundary, cbo);
        partitioned.reset();  // the distributed K and M are not needed any more
        return b;
      };
    }
  }
#endif
  if (session != nullptr) seflex::app::checkpoint(*session);  // every rank read the model (or stop them all)
  o.name = name ? *name : std::filesystem::path(model_path).stem().string();
  o.full_mesh = true;  // the inertia invariants are computed from the mesh part before --no-mesh drops it
  o.stiffening = !no_stiffening;
  if (stresses) o.stress_elements = stress_element_ids(*stresses);
  const auto t1 = std::chrono::steady_clock::now();
  red::SuperelementInfo info;
  seflex::se::StressModes stress;
  seflex::se::Superelement s = red::reduce_to_superelement(model, o, &info, &stress);
  const auto t2 = std::chrono::steady_clock::now();
  seflex::io::record_source(s, model, model_path);  // the rest of the provenance is the library's
  const std::size_t mesh_nodes = s.fe_node_ids.size(), mesh_cells = s.cells.size();
  if (no_mesh) seflex::io::drop_mesh(s);

  std::printf("seflex reduce %s -> %s (body '%s')\n", model_path.c_str(), out->c_str(), s.name.c_str());
  print_summary(s, info, model);
  if (!assembly.empty()) std::printf("  assembly: %s\n", assembly.c_str());
  if (!o.modes.fmax_hz && o.modes.modes == 0 && modes == kAbsent)
    std::printf("\nno fixed-interface modes (constraint modes only; add some with --modes N or --fmax HZ)\n");
  print_modes(s, o.modes);
  std::fflush(stdout);
  Eigen::VectorXd full;
  if (compare != kAbsent) full = red::full_model_eigenvalues(model, 6 + compare, *backend);
  print_free_free(s, compare != kAbsent ? compare : 10, compare != kAbsent ? &full : nullptr);
  std::fflush(stdout);
  if (writer) seflex::io::save_superelement(s, *out, seflex::io::SaveOptions{force, &stress});
  const auto t3 = std::chrono::steady_clock::now();
  const auto sec = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  if (writer)
    std::printf("\nwrote %s (%.1f MB)\n", out->c_str(),
                static_cast<double>(std::filesystem::file_size(*out)) / (1024.0 * 1024.0));
  if (s.invariants.present())
    std::printf("  inertia invariants: stored (full inertia without the mesh)\n");
  else
    std::printf("  inertia invariants: not computed (full inertia will need the mesh part)\n");
  if (s.stiffening.present())
    std::printf("  geometric-stiffness invariants: stored (%d inertia load cases, %zu constraint modes; %.2f s)\n",
                seflex::se::StiffeningInvariants::kInertiaCases, s.stiffening.interface.size(), info.seconds_stiffening);
  else
    std::printf("  geometric-stiffness invariants: not computed (--no-stiffening: no stress stiffening in the run)\n");
  for (const auto& [card, count] : info.stress_missing) {
    if (card.rfind("unknown element id ", 0) == 0)
      std::fprintf(stderr, "warning: --stresses: element %s is not in the model\n", card.substr(19).c_str());
    else
      std::fprintf(stderr, "warning: --stresses: %d %s element%s: no element results in seflex (left out of the stress modes)\n",
                   count, card.c_str(), count > 1 ? "s" : "");
  }
  if (stress.present())
    std::printf("  stress modes: %zu element%s, %ld result rows x %d basis vectors (element forces and stresses)\n",
                stress.element_ids.size(), stress.element_ids.size() > 1 ? "s" : "", static_cast<long>(stress.S.rows()), s.size());
  else if (stresses)
    std::printf("  stress modes: none (no selected element has element results)\n");
  if (no_mesh)
    std::printf("  mesh part: left out (--no-mesh; %zu FE nodes, %zu cells not written: no animation or recovery)\n",
                mesh_nodes, mesh_cells);
  else
    std::printf("  mesh part: %zu FE nodes, %zu cells\n", mesh_nodes, mesh_cells);
  const auto& st = info.stats;
  std::printf("time: read %.2f s, reduce %.2f s, summary and write %.2f s\n", sec(t0, t1), sec(t1, t2), sec(t2, t3));
  std::printf("work: K_ii %ld dofs, factor %.3g nonzeros; ", static_cast<long>(st.n_interior),
              st.interior_factorization.factor_nonzeros);
  if (st.block_solves > 0)
    std::printf("fixed-interface modes by block Lanczos on that factor: %d block solves, basis %ld\n", st.block_solves,
                static_cast<long>(st.krylov_basis));
  else
    std::printf("fixed-interface modes by %d eigensolver run(s), %ld solves\n", st.eigen_solutions,
                st.eigen.operator_applications);
  return seflex::app::kOk;
}

int run_reduce(seflex::app::Args& args) {
  if (seflex::app::distributed_backend_requested(args.value_or("backend", "serial"))) {
#ifdef SEFLEX_HAVE_MPI
    return seflex::app::run_distributed("reduce", [&](seflex::parallel::Session& s) { return reduce(args, &s); });
#endif
  }
  return reduce(args, nullptr);
}

}  // namespace

SEFLEX_COMMAND(reduce,
               "MODEL --interface IDS|SETS|aset|bset|suport [--modes N | --fmax HZ] [--frame NODE|SET] [--name NAME] "
               "[--compare K] [--eigensolver block|spectra|arpack|dense] [--backend serial|slepc] [--no-mesh] [--no-stiffening] [--stresses all|IDS] -o FILE.se [--force] "
               "[--properties FILE] [--set NAME=VALUE]... [--symbol NAME=DIR]... [--ignore-unknown]",
               "Craig-Bampton reduction to an absolute-interface-coordinate superelement: constraint modes of all six "
               "dofs of the interface grids plus fixed-interface modes; prints mass properties, the truncation report "
               "and the reduced model's free-free frequencies (--compare K: against the full model's); --no-mesh writes the "
               "dynamics only (reduced matrices and inertia invariants, no FE mesh, recovery or FE mass); --no-stiffening leaves out "
               "the geometric-stiffness invariants (docs/geometric-stiffening.md); --stresses all|IDS stores the element "
               "results of those elements per basis vector (stress modes, docs/stresses.md)",
               run_reduce);
