#pragma once
// Geometric-stiffness invariants of a Craig-Bampton superelement (superelement/stiffening_invariants.hpp,
// docs/geometric-stiffening.md), computed by reduce_to_superelement:
//   1. the d'Alembert loads of the 12 unit rigid-body accelerations of the frame (inertia_load_cases),
//   2. their static responses with the interface held (CraigBamptonOptions::interior_loads: one block
//      solve with the factor of K_ii the constraint modes use),
//   3. K_sigma of each response and of each constraint mode (fem::assemble_geometric_stiffness), projected
//      on the basis: G = B^T K_sigma B.
// Cost: (12 + 6N) assemblies of K_sigma and products with the n_g x n basis, O((12 + 6N) n_g n^2).
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/superelement/stiffening_invariants.hpp"

namespace seflex::reduction {

/// -M_gg D (g x 12, each grid's CD components) with D the unit rigid-body acceleration fields about
/// p_frame (basic): columns 0..5 the rigid modes E0 (translation, then rotation about p_frame), 6..11
/// the centrifugal fields S_s (X - p_frame) on the translations (s = xx, yy, zz, xy, xz, yz; S_xy =
/// e_x e_y^T + e_y e_x^T). Scalar points get no load.
Eigen::MatrixXd inertia_load_cases(const fem::Model& model, const fem::DofMap& dofs,
                                   const Eigen::SparseMatrix<double>& M_gg, const Eigen::Vector3d& p_frame);

/// The invariants for the f-set basis B_f (n_f x n: the first n_b columns the constraint modes, in the
/// order of q) mapped to the g-set by T_gf, and the f-set static responses of the 12 inertia load cases
/// (n_f x 12, zero on the boundary). Throws InputError (naming the card) when an element's stress
/// cannot be recovered (fem::assemble_geometric_stiffness).
/// A share of the work (distributed reduce): with parts > 1 only the cases k with k % parts == part
/// are computed (k = c for inertia[c], 12 + j for interface[j]); the others are left n x n zero, so
/// that the sum over part = 0..parts-1 is the whole.
se::StiffeningInvariants compute_stiffening_invariants(const fem::Model& model, const fem::DofMap& dofs,
                                                       const Eigen::SparseMatrix<double>& T_gf,
                                                       const Eigen::MatrixXd& B_f, Eigen::Index n_b,
                                                       const Eigen::MatrixXd& inertia_responses_f, int part = 0,
                                                       int parts = 1);

}  // namespace seflex::reduction
