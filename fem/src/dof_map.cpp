#include "seflex/fem/dof_map.hpp"

#include "seflex/common/error.hpp"

namespace seflex::fem {

DofMap make_dof_map(const Model& model) {
  DofMap m;
  m.n_grids = static_cast<Eigen::Index>(model.grids.size());
  m.n_spoints = static_cast<Eigen::Index>(model.spoints.size());
  return m;
}

std::optional<Eigen::Index> find_dof(const Model& model, const DofMap& dofs, int point_id, int component) {
  if (const auto g = model.grid_index.find(point_id); g != model.grid_index.end()) {
    if (component < 1 || component > 6) return std::nullopt;
    return dofs.grid_dof(g->second, component);
  }
  if (const auto s = model.spoint_index.find(point_id); s != model.spoint_index.end()) {
    if (component != 0 && component != 1) return std::nullopt;
    return dofs.spoint_dof(s->second);
  }
  return std::nullopt;
}

DofLabel dof_label(const Model& model, const DofMap& dofs, Eigen::Index dof) {
  SEFLEX_DEMAND(dof >= 0 && dof < dofs.size(), "dof out of range");
  DofLabel l;
  if (dof < 6 * dofs.n_grids) {
    l.point_id = model.grids[static_cast<std::size_t>(dof / 6)].id;
    l.component = static_cast<int>(dof % 6) + 1;
  } else {
    l.point_id = model.spoints[static_cast<std::size_t>(dof - 6 * dofs.n_grids)].id;
    l.scalar_point = true;
  }
  return l;
}

}  // namespace seflex::fem
