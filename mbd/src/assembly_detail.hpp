#pragma once
// Internal helpers of the assembly (not installed): scatter into clique blocks and the per-element
// contributions, each in its own file.
#include <Eigen/Core>
#include <vector>

#include "seflex/mbd/assembly.hpp"

namespace seflex::mbd::detail {

/// vals[offsets[a + nc*b]] += G(a, b) for the nc x nc block G of one clique.
inline void scatter(std::vector<double>& vals, const std::vector<int>& offsets, const Eigen::MatrixXd& G) {
  const auto nc = G.rows();
  for (Eigen::Index b = 0; b < nc; ++b)
    for (Eigen::Index a = 0; a < nc; ++a) vals[static_cast<std::size_t>(offsets[static_cast<std::size_t>(a + nc * b)])] += G(a, b);
}

/// Flexible body b: wrenches on its nodes, residual of its modes, matrices on its clique.
void assemble_flexible(const Model& model, const State& s, Data& data, const AssemblyOptions& opt, int b);
/// Rigid body b: inertia wrench on its anchor node and its matrices.
void assemble_rigid(const Model& model, Data& data, const AssemblyOptions& opt, int b);
/// Node loads (world or follower).
void assemble_loads(const Model& model, const State& s, Data& data, const AssemblyOptions& opt);
/// Force elements on hinge angles.
void assemble_force_elements(const Model& model, const State& s, Data& data, const AssemblyOptions& opt);

}  // namespace seflex::mbd::detail
