#pragma once
// Global (g-set) degrees of freedom of a finalized model.
//
// Numbering: GRID i (its index in Model::grids) owns dofs 6 i .. 6 i + 5, components T1 T2 T3 R1 R2 R3
// in the grid's displacement (CD) system; then SPOINT k (index in Model::spoints) owns dof
// 6 n_grids + k. Nodes are numbered the same way: node n < n_grids is a grid, the others are scalar
// points.
#include <Eigen/Core>
#include <cstdint>
#include <optional>

#include "seflex/fem/model.hpp"

namespace seflex::fem {

struct DofMap {
  Eigen::Index n_grids = 0, n_spoints = 0;

  Eigen::Index size() const { return 6 * n_grids + n_spoints; }
  Eigen::Index n_nodes() const { return n_grids + n_spoints; }
  /// Dof of component c (1..6) of the grid with index `grid_index`.
  Eigen::Index grid_dof(Eigen::Index grid_index, int component) const { return 6 * grid_index + component - 1; }
  /// Dof of the scalar point with index `spoint_index`.
  Eigen::Index spoint_dof(Eigen::Index spoint_index) const { return 6 * n_grids + spoint_index; }
  /// First dof and dof count of node n (grid or scalar point).
  Eigen::Index node_first_dof(Eigen::Index n) const { return n < n_grids ? 6 * n : 6 * n_grids + (n - n_grids); }
  int node_dof_count(Eigen::Index n) const { return n < n_grids ? 6 : 1; }
  /// Node owning dof d.
  Eigen::Index node_of_dof(Eigen::Index d) const { return d < 6 * n_grids ? d / 6 : n_grids + (d - 6 * n_grids); }
};

DofMap make_dof_map(const Model& model);

/// Dof of a GRID id with component 1..6, or of an SPOINT id with component 0 or 1; nullopt if the
/// id is neither or the component does not exist.
std::optional<Eigen::Index> find_dof(const Model& model, const DofMap& dofs, int point_id, int component);

/// The user's name of a dof: point id and component (1..6 for grids, 0 for scalar points).
struct DofLabel {
  int point_id = 0;
  int component = 0;
  bool scalar_point = false;
};
DofLabel dof_label(const Model& model, const DofMap& dofs, Eigen::Index dof);

}  // namespace seflex::fem
