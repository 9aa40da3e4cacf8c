#pragma once
// Differential (geometric, stress) stiffness K_sigma of a finalized model for a static stress state,
// on all g-set dofs (dof_map.hpp), the matrix of linear buckling (Nastran SOL 105):
//
//   (K + lambda K_sigma) phi = 0,     K_sigma = sum_e L_e^T K_sigma,e(s_e(u)) L_e,
//
// where s_e(u) is the element's stress state recovered from the g-set displacements u (each grid's
// CD components; element forces = element stiffness times element displacements):
// - CROD/CONROD: axial force N; K_sigma,e = (N/L) [I -I; -I I] on the translations (element_rod.hpp);
// - CBAR/CBEAM: axial force N; Hermite beam geometric stiffness (element_bar.hpp);
// - CQUAD4/CTRIA3: membrane stress resultants (Nxx, Nyy, Nxy) at the Gauss points; the consistent
//   membrane-stress form on the in-plane and out-of-plane translations (element_shell_*.hpp).
// K_sigma is the Hessian of the stress term int S : E_nl of the Green-Lagrange strain with the
// stress held fixed; it is symmetric and indefinite in general.
// Not included: CELAS springs and CONM2 (no stress), DMIG; rigid elements and MPCs (RBE2, RBAR,
// RBE3) get no differential stiffness, as in Nastran SOL 105 where rigid elements are enforced as
// linear constraints (docs/buckling.md); thermal strain of the preload (u must be mechanical).
//
// Storage as assemble(): column-major, both triangles, pattern from the element connectivity.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

/// K_sigma (n x n, n = dofs.size()) of the elements of a finalized model for the g-set displacements
/// u_g (size n, each grid's CD system). Throws InputError (naming the card) for elements with
/// undefined references or impossible geometry, InvariantError if u_g has the wrong size.
Eigen::SparseMatrix<double> assemble_geometric_stiffness(const Model& model, const DofMap& dofs,
                                                         const Eigen::Ref<const Eigen::VectorXd>& u_g);

}  // namespace seflex::fem
