#pragma once
// Internal helpers of the assembly (not installed): scatter into clique blocks and the per-element
// contributions, each in its own file.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "seflex/mbd/assembly/assembly.hpp"

namespace seflex::mbd::detail {

/// vals[offsets[a + nc*b]] += G(a, b) for the nc x nc block G of one clique.
inline void scatter(std::vector<double>& vals, const std::vector<int>& offsets, const Eigen::MatrixXd& G) {
  const auto nc = G.rows();
  for (Eigen::Index b = 0; b < nc; ++b)
    for (Eigen::Index a = 0; a < nc; ++a) vals[static_cast<std::size_t>(offsets[static_cast<std::size_t>(a + nc * b)])] += G(a, b);
}

/// vals += J^T X J scattered into the clique (X: rows() x rows() in node space). With `right`,
/// vals += J^T X J_right (J_right: same dofs, other columns, e.g. the convective Jacobians G).
/// Y: the caller's scratch for the column-mapped blocks (reused: keep one per element).
void scatter_mapped(std::vector<double>& vals, const std::vector<int>& offsets, int nc, const ElementMap& map,
                    const Eigen::MatrixXd& X, std::vector<Eigen::MatrixXd>& Y, const ElementMap* right = nullptr);
/// One element's share of the iteration matrix cK K T + cC C + cM M (AssemblyOptions::iteration) in
/// node space: X = cK K + cC C + cM M (in the axes of the map's columns: world, or body axes with
/// the columns rotated, flexible_body.cpp), and what the maps add beyond J^T X J: K's columns of
/// the Free nodes' rotation dofs times T (cK K (J T - J), with `triples` per node block as
/// Data::node_rotation_triples) and the convective term cC M G of the node tree (G per node block).
struct NodeSpaceIteration {
  const Eigen::MatrixXd* X = nullptr;
  const Eigen::MatrixXd* K = nullptr;  ///< null: no rotation columns to correct
  double cK = 1.0;
  const std::vector<Eigen::Matrix3d>* T = nullptr;
  const std::vector<const std::vector<std::array<int, 2>>*>* triples = nullptr;
  const Eigen::MatrixXd* M = nullptr;  ///< null: no convective term
  double cC = 0.0;
  const std::vector<const std::vector<Vector6d>*>* G = nullptr;  ///< per node block; null entries: G = 0
};
/// vals += J^T (X J + cK K (J T - J) + cC M G) scattered into the clique: one mapping per element.
void scatter_iteration(std::vector<double>& vals, const std::vector<int>& offsets, int nc, const ElementMap& map,
                       const NodeSpaceIteration& share, std::vector<Eigen::MatrixXd>& Y);
/// The map of the convective Jacobians G (no identity blocks, no modal columns); false if all G
/// vanish (every node Free).
bool convective_map(const ElementMap& map, const std::vector<const std::vector<Vector6d>*>& G, ElementMap& out);
/// out (clique-sized) += |J^T f|.
void add_mapped_abs(Eigen::VectorXd& out, const ElementMap& map, const Eigen::VectorXd& f);

/// Flexible body b: wrenches on its nodes, residual of its modes, matrices on its clique.
void assemble_flexible(const Model& model, const State& s, Data& data, const AssemblyOptions& opt, int b);
/// Rigid body b: inertia wrench on its anchor node and its matrices.
void assemble_rigid(const Model& model, Data& data, const AssemblyOptions& opt, int b);
/// Node loads (world or follower).
void assemble_loads(const Model& model, const State& s, Data& data, const AssemblyOptions& opt);
/// Force elements on hinge angles.
void assemble_force_elements(const Model& model, const State& s, Data& data, const AssemblyOptions& opt);

}  // namespace seflex::mbd::detail
