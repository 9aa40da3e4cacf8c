// seflex info DECK: what a Nastran deck holds - files read, counts of grids, elements and cards,
// unsupported cards with their first location.
#include <cstdio>
#include <iostream>
#include <string>

#include "command.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/io/nastran.hpp"

namespace {

void row(const std::string& name, std::size_t n, int indent = 2) {
  std::printf("%*s%-*s %10zu\n", indent, "", 26 - indent, name.c_str(), n);
}

void print_model(const seflex::fem::Model& m) {
  std::size_t cbar = 0, cbeam = 0, crod = 0, conrod = 0, quad = 0, tria = 0, celas1 = 0, celas2 = 0;
  for (const auto& b : m.bars) (b.is_beam ? cbeam : cbar)++;
  for (const auto& r : m.rods) (r.inline_property ? conrod : crod)++;
  for (const auto& s : m.shells) (s.nnode == 4 ? quad : tria)++;
  for (const auto& s : m.springs) (s.inline_property ? celas2 : celas1)++;
  const std::size_t elements = m.bars.size() + m.rods.size() + m.shells.size() + m.conm2.size() + m.springs.size() + m.rbe2.size();
  std::printf("\nmodel\n");
  row("grids", m.grids.size());
  row("scalar points", m.spoints.size());
  row("coordinate systems", m.coords.size());
  row("elements", elements);
  const std::pair<const char*, std::size_t> kinds[] = {{"CBAR", cbar},     {"CBEAM", cbeam},   {"CROD", crod},
                                                       {"CONROD", conrod}, {"CQUAD4", quad},   {"CTRIA3", tria},
                                                       {"CONM2", m.conm2.size()}, {"CELAS1", celas1}, {"CELAS2", celas2},
                                                       {"RBE2", m.rbe2.size()}};
  for (const auto& [name, n] : kinds)
    if (n) row(name, n, 4);
  row("properties", m.bar_props.size() + m.rod_props.size() + m.shell_props.size() + m.spring_props.size());
  row("materials", m.mat1.size());
  row("SPC entries", m.spcs.size());
  row("loads (FORCE, MOMENT)", m.point_loads.size());
  row("eigenvalue methods", m.eigen_methods.size());
  row("DMIG matrices", m.dmigs.size());

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

int run_info(seflex::app::Args& args) {
  const std::string deck = args.positional("DECK");
  args.finish();
  const seflex::fem::Model m = seflex::io::read_nastran(deck);
  std::printf("deck        %s\n", deck.c_str());
  std::printf("files read  %zu\n", m.files.size());
  for (const auto& f : m.files) std::printf("  %s\n", f.c_str());
  const auto& cc = m.case_control;
  if (cc.sol) std::printf("solution    SOL %s\n", cc.sol->c_str());
  if (!cc.title.empty()) std::printf("title       %s\n", cc.title.c_str());
  if (!cc.subtitle.empty()) std::printf("subtitle    %s\n", cc.subtitle.c_str());
  print_model(m);
  std::fflush(stdout);
  return seflex::app::kOk;
}

}  // namespace

SEFLEX_COMMAND(info, "DECK", "counts of grids, elements and cards, unsupported cards, mass properties of a Nastran deck",
               run_info);
