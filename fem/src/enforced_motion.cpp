// SPCD as a load set (see enforced_motion.hpp).
#include "seflex/fem/enforced_motion.hpp"

#include "model_lookup.hpp"
#include "seflex/fem/components.hpp"

namespace seflex::fem {
namespace {

void add_set(const Model& model, const DofMap& dofs, int sid, double scale, std::vector<std::pair<Eigen::Index, double>>& out) {
  for (const EnforcedMotion& e : model.enforced_motions) {
    if (e.sid != sid) continue;
    if (const auto sp = model.spoint_index.find(e.grid); sp != model.spoint_index.end() && (e.c == 0 || e.c == 1)) {
      out.emplace_back(dofs.spoint_dof(sp->second), scale * e.d);
      continue;
    }
    const std::uint32_t gi = detail::grid_index(model, e.grid, e.ref, "SPCD", e.sid, "3 (G)");
    if (e.c == 0) detail::fail(model, e.ref, "SPCD", e.sid, "4 (C)", "blank or 0 for a GRID; expected components 1-6");
    for (int c = 1; c <= 6; ++c)
      if (has_component(e.c, c)) out.emplace_back(dofs.grid_dof(gi, c), scale * e.d);
  }
}

}  // namespace

bool has_enforced_motion_set(const Model& model, int sid) {
  for (const EnforcedMotion& e : model.enforced_motions)
    if (e.sid == sid) return true;
  return false;
}

std::vector<std::pair<Eigen::Index, double>> enforced_motion_dofs(const Model& model, const DofMap& dofs, int sid) {
  std::vector<std::pair<Eigen::Index, double>> out;
  if (model.enforced_motions.empty()) return out;
  for (const LoadCombination& lc : model.load_combinations)
    if (lc.sid == sid) {
      for (const auto& [si, li] : lc.terms) add_set(model, dofs, li, lc.s * si, out);
      return out;
    }
  add_set(model, dofs, sid, 1.0, out);
  return out;
}

}  // namespace seflex::fem
