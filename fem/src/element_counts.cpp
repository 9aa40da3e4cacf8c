// Elements counted by card name (see element_counts.hpp).
#include "seflex/fem/element_counts.hpp"

#include <map>

namespace seflex::fem {

std::vector<std::pair<std::string, std::size_t>> element_counts(const Model& m) {
  std::map<std::string, std::size_t> n;
  for (const auto& b : m.bars) ++n[b.is_beam ? "CBEAM" : "CBAR"];
  for (const auto& r : m.rods) ++n[rod_card(r)];
  for (const auto& s : m.shells) ++n[shell_card(s)];
  for (const auto& q : m.shells8) ++n[quadratic_shell_card(q)];
  n["CSHEAR"] += m.shear_panels.size();
  n["CBEND"] += m.bends.size();
  n["CONM2"] += m.conm2.size();
  for (const auto& s : m.springs) ++n[s.scalar_points ? "CELAS3/CELAS4" : s.inline_property ? "CELAS2" : "CELAS1"];
  n["RBE2"] += m.rbe2.size();
  n["RBAR"] += m.rbars.size();
  n["RBE3"] += m.rbe3.size();
  for (const auto& r : m.rigid_bodies) ++n[rigid_body_card(r)];
  for (const auto& r : m.rigid_rods) ++n[rigid_rod_card(r)];
  for (const auto& b : m.bushes) ++n[bush_card(b)];
  n["CMASS1-4"] += m.scalar_masses.size();
  n["CONM1"] += m.conm1.size();
  for (const auto& s : m.solids) ++n[s.card()];
  n["GENEL"] += m.genels.size();
  static const char* order[] = {"CBAR",  "CBEAM",  "CROD",  "CONROD", "CTUBE",  "CBEND",  "CQUAD4", "CTRIA3", "CQUAD8", "CTRIA6",
                                "CSHEAR", "CONM2", "CELAS1", "CELAS2", "RBE2",   "RBAR",   "RBE3",   "RBE1",
                                "CRIGD1", "CRIGD2", "CRIGD3", "RROD",  "CRIGDR", "CBUSH", "CBUSH1D",  "CELAS3/CELAS4",
                                "CMASS1-4", "CONM1", "CHEXA", "CPENTA", "CTETRA", "CPYRAM", "GENEL"};
  std::vector<std::pair<std::string, std::size_t>> out;
  for (const char* name : order)
    if (const auto it = n.find(name); it != n.end() && it->second > 0) out.emplace_back(name, it->second);
  return out;
}

std::size_t element_count(const Model& model) {
  std::size_t total = 0;
  for (const auto& [name, n] : element_counts(model)) total += n;
  return total;
}

}  // namespace seflex::fem
