// Interface node sets from ASET/BSET/SUPORT cards and named node sets (craig_bampton_superelement.hpp).
#include <string>
#include <unordered_map>

#include "seflex/common/error.hpp"
#include "seflex/fem/components.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"

namespace seflex::reduction {

std::vector<int> interface_nodes_from_cards(const fem::Model& model, InterfaceCards cards) {
  const std::vector<fem::DofSetEntry>& entries = cards == InterfaceCards::Aset   ? model.aset
                                                 : cards == InterfaceCards::Bset ? model.bset
                                                                                 : model.suport;
  const char* name = cards == InterfaceCards::Aset   ? "ASET/ASET1"
                     : cards == InterfaceCards::Bset ? "BSET/BSET1"
                                                     : "SUPORT";
  const std::string deck = model.files.empty() ? std::string("<model>") : model.files[0];
  if (entries.empty())
    throw InputError(deck + ": no " + std::string(name) + " card; expected the interface grids on " + name +
                     " cards (or give the interface node ids)");
  std::vector<int> ids;
  std::unordered_map<int, std::size_t> first;  // grid -> index into entries of its first mention
  std::unordered_map<int, fem::ComponentMask> mask;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const fem::DofSetEntry& e = entries[k];
    if (!model.grid_index.count(e.grid))
      throw InputError(fem::where(model, e.ref), std::string(name) + " point " + std::to_string(e.grid) +
                                                     " is not a GRID; expected interface grids with six dofs");
    if (first.emplace(e.grid, k).second) ids.push_back(e.grid);
    mask[e.grid] |= e.c;
  }
  for (int id : ids)
    if (mask[id] != 0x3F) {
      const fem::DofSetEntry& e = entries[first[id]];
      throw InputError(fem::where(model, e.ref),
                       std::string(name) + " grid " + std::to_string(id) + " names components " +
                           fem::component_string(mask[id]) +
                           "; expected 123456: a superelement interface node carries all six dofs");
    }
  return ids;
}

std::vector<int> interface_nodes_from_set(const fem::Model& model, const std::string& name) {
  const auto it = model.node_sets.find(name);
  if (it != model.node_sets.end()) return it->second;
  const std::string deck = model.files.empty() ? std::string("<model>") : model.files[0];
  std::string known;
  for (const auto& [n, ids] : model.node_sets) known += (known.empty() ? "" : ", ") + n;
  throw InputError(deck + ": no node set named '" + name + "'; expected " +
                   (known.empty()
                        ? std::string("node ids (e.g. 1,3,4), aset, bset or suport (the model has no named node sets)")
                        : "one of: " + known));
}

}  // namespace seflex::reduction
