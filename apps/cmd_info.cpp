// seflex info DECK: what a Nastran deck holds - files read, counts of grids, elements and cards,
// unsupported cards with their first location, and the rigid-body mass properties the way Nastran's
// grid point weight generator reports them. seflex info BODY.se: a superelement file
// (info_superelement.cpp).
#include <cstdio>
#include <limits>
#include <optional>
#include <string>

#include "seflex/solutions/buckling.hpp"
#include "command.hpp"
#include "info_superelement.hpp"
#include "seflex/fem/element_counts.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/fem/mass_properties.hpp"
#include "seflex/fem/model.hpp"
#include "model_args.hpp"
#include "usage_warnings.hpp"
#include "seflex/io/model_reader.hpp"
#include "seflex/solutions/card_usage.hpp"

namespace {

void row(const std::string& name, std::size_t n, int indent = 2) {
  std::printf("%*s%-*s %10zu\n", indent, "", 26 - indent, name.c_str(), n);
}

void print_model(const seflex::fem::Model& m) {
  std::printf("\nmodel\n");
  row("grids", m.grids.size());
  row("scalar points", m.spoints.size());
  row("coordinate systems", m.coords.size());
  row("elements", seflex::fem::element_count(m));
  for (const auto& [name, n] : seflex::fem::element_counts(m)) row(name, n, 4);
  row("properties", m.bar_props.size() + m.rod_props.size() + m.shell_props.size() + m.composite_props.size() +
                         m.spring_props.size() + m.bush_props.size() + m.mass_props.size() + m.solid_props.size() +
                         m.shear_props.size() + m.bend_props.size());
  row("materials", m.mat1.size() + m.mat2.size() + m.mat8.size() + m.mat9.size());
  row("SPC entries", m.spcs.size());
  row("MPC equations", m.mpcs.size());
  row("loads (FORCE*, MOMENT*)", m.point_loads.size());
  if (const std::size_t n = m.pressure_loads.size() + m.face_loads.size() + m.gravity_loads.size() +
                            m.rotational_loads.size() + m.grid_pressure_loads.size() + m.scalar_loads.size())
    row("pressure, inertia loads", n);
  if (const std::size_t n = m.bar_line_loads.size()) row("bar loads (PLOAD1)", n);
  if (const std::size_t n = m.enforced_motions.size()) row("enforced motion (SPCD)", n);
  if (const std::size_t n = m.grid_temperatures.size() + m.default_temperatures.size() + m.bar_temperatures.size())
    row("temperature cards", n);
  row("eigenvalue methods", m.eigen_methods.size());
  row("DMIG matrices", m.dmigs.size());
  if (!m.parts.empty()) {
    std::printf("\npart superelements (BEGIN SUPER), merged into the model above and solved in full\n");
    for (const auto& p : m.parts) {
      std::printf("  part %-6d %s: %zu grids (%zu joined to other superelements), %zu elements%s", p.seid,
                  seflex::fem::where(m, p.begin).str().c_str(), p.grids, p.boundary_grids, p.elements,
                  p.moved ? ", moved by SELOC" : "");
      if (p.grid_offset || p.element_offset || p.property_offset || p.material_offset)
        std::printf("; ids + %lld (grids), + %lld (elements), + %lld (properties), + %lld (materials)", p.grid_offset,
                    p.element_offset, p.property_offset, p.material_offset);
      std::printf("\n");
    }
  }

  std::printf("\ncards read, by type\n");
  for (const auto& [name, n] : m.card_counts) row(name, n);

  if (m.unsupported.empty()) {
    std::printf("\nunsupported cards: none\n");
  } else {
    std::printf("\nunsupported cards (read but not used by seflex)\n");
    for (const auto& u : m.unsupported)
      std::printf("  %-24s %10zu   first at %s\n", u.name.c_str(), u.count, seflex::fem::where(m, u.first).str().c_str());
  }
}

/// What the deck's own solution (its SOL) would use, refuse, approximate and ignore.
void print_card_usage(const seflex::fem::Model& m) {
  namespace solutions = seflex::solutions;
  const solutions::Solution sol = solutions::solution_of_deck(m);
  std::vector<solutions::CaseSelection> cases;
  if (sol == solutions::Solution::Statics) cases = solutions::select_cases(m);
  else if (sol == solutions::Solution::NormalModes) cases = {solutions::select_case(m)};
  else if (sol == solutions::Solution::Buckling) {
    try {  // the preload and METHOD subcases `seflex buckling` runs
      const auto [preload, buckle] = seflex::solutions::buckling_cases(m);
      cases = {preload};
      if (buckle.subcase_id != preload.subcase_id) cases.push_back(buckle);
    } catch (const seflex::InputError& e) {
      std::printf("\nbuckling (SOL 105) cannot run: %s\n", e.what());
      cases = solutions::select_cases(m);
    }
  }
  const solutions::CardUsage usage = solutions::check_card_usage(m, sol, cases);
  if (sol == solutions::Solution::Info)
    std::printf("\ncard use (no SOL seflex runs in the executive control: cards seflex does not model are listed)\n");
  else
    std::printf("\ncard use by %s, the deck's SOL%s\n", solutions::solution_name(sol),
                sol == solutions::Solution::Buckling ? " (run it with: seflex buckling DECK)" : "");
  if (usage.uses.empty()) {
    std::printf("  every card is used\n");
    return;
  }
  const std::pair<solutions::CardUse::Kind, const char*> groups[] = {
      {solutions::CardUse::Kind::Refused, "refused (the solution stops with an error)"},
      {solutions::CardUse::Kind::Approximated, "read with an approximation (warning)"},
      {solutions::CardUse::Kind::Caution, "computed as written, with a consequence to check (warning)"},
      {solutions::CardUse::Kind::Unused, "not used (warning)"}};
  for (const auto& [kind, title] : groups) {
    if (usage.count(kind) == 0) continue;
    std::printf("  %s\n", title);
    for (const auto& u : usage.uses)
      if (u.kind == kind) std::printf("    %s\n", solutions::describe(m, u).c_str());
  }
}

void print_matrix(const Eigen::MatrixXd& a, int indent) {
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    std::printf("%*s", indent, "");
    for (Eigen::Index j = 0; j < a.cols(); ++j) std::printf(" %14.6E", a(i, j));
    std::printf("\n");
  }
}

void print_mass_properties(const seflex::fem::Model& m, std::optional<int> reference_grid) {
  const seflex::fem::MassProperties mp = seflex::fem::mass_properties(m, reference_grid);
  std::printf("\nmass properties (grid point weight generator)\n");
  if (mp.reference_grid > 0)
    std::printf("  reference point           grid %d at (%g, %g, %g)\n", mp.reference_grid, mp.reference.x(),
                mp.reference.y(), mp.reference.z());
  else
    std::printf("  reference point           basic origin\n");
  std::printf("  PARAM WTMASS              %g (not applied here: masses in the deck's units, as Nastran's GPWG prints them)\n",
              mp.wtmass);
  std::printf("  rigid-body mass matrix M0 about the reference point, basic axes\n");
  print_matrix(mp.M0, 3);
  if (!(mp.mass > 0.0)) {
    std::printf("  total mass                0 (the model has no mass)\n");
    return;
  }
  std::printf("  total mass                %.6E\n", mp.mass);
  std::printf("  centre of gravity         %.6E %.6E %.6E (basic)\n", mp.cg.x(), mp.cg.y(), mp.cg.z());
  std::printf("  inertia about the CG, basic axes (I11 = sum m (y^2 + z^2), products with a minus sign)\n");
  print_matrix(mp.I_cg, 3);
  std::printf("  principal moments         %.6E %.6E %.6E\n", mp.principal_moments.x(), mp.principal_moments.y(),
              mp.principal_moments.z());
  std::printf("  principal axes (columns, basic)\n");
  print_matrix(mp.principal_axes, 3);
}

int run_info(seflex::app::Args& args) {
  const seflex::io::ModelReadOptions model_options = seflex::app::model_read_options(args);
  const std::string deck = args.positional("DECK");
  constexpr int kUnset = std::numeric_limits<int>::min();
  const int grdpnt = args.integer("grdpnt", kUnset);
  args.finish();
  if (seflex::app::is_superelement_file(deck)) {
    if (grdpnt != kUnset || model_options.properties || !model_options.parameters.empty() || !model_options.symbols.empty())
      throw seflex::app::UsageError(deck + " is a superelement file; --grdpnt, --properties, --set and --symbol apply to a model");
    seflex::app::print_superelement_info(deck);
    std::fflush(stdout);
    return seflex::app::kOk;
  }
  const seflex::fem::Model m = seflex::io::read_model(deck, model_options);
  seflex::app::print_read_warnings(m);
  std::printf("deck        %s\n", deck.c_str());
  std::printf("files read  %zu\n", m.files.size());
  for (const auto& f : m.files) std::printf("  %s\n", f.c_str());
  const auto& cc = m.case_control;
  if (cc.sol) std::printf("solution    SOL %s\n", cc.sol->c_str());
  if (!cc.title.empty()) std::printf("title       %s\n", cc.title.c_str());
  if (!cc.subtitle.empty()) std::printf("subtitle    %s\n", cc.subtitle.c_str());
  print_model(m);
  print_card_usage(m);
  std::fflush(stdout);
  std::optional<int> reference;
  if (grdpnt != kUnset) {
    if (grdpnt < 0 || (grdpnt > 0 && !m.grid_index.count(grdpnt)))
      throw seflex::app::UsageError("--grdpnt " + std::to_string(grdpnt) + ": expected 0 (basic origin) or a GRID id of the deck");
    reference = grdpnt;
  }
  print_mass_properties(m, reference);
  std::fflush(stdout);
  return seflex::app::kOk;
}

}  // namespace

SEFLEX_COMMAND(info, "DECK [--grdpnt G] [--symbol NAME=DIR]... | BODY.se",
               "counts of grids, elements and cards, unsupported cards, and mass properties (like Nastran's GPWG; "
               "reference point PARAM GRDPNT or --grdpnt) of a Nastran deck; of a superelement file: provenance, "
               "interfaces, modes, mass properties, inertia invariants, mesh part and truncation report",
               run_info);
