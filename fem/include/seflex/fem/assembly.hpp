#pragma once
// Global stiffness and mass matrices of a finalized model on all g-set dofs (dof_map.hpp).
//
//   K = sum_e L_e^T K_e L_e,  M = WTMASS * sum_e L_e^T M_e L_e
// where K_e, M_e are the element matrices in basic (element_*.hpp) and L_e gathers the element's
// dofs and rotates each grid's blocks from basic to its displacement (CD) system.
//
// Storage: column-major Eigen::SparseMatrix<double>, compressed, BOTH triangles stored (the
// matrices are symmetric). The sparsity pattern comes from the element connectivity (every grid
// couples with every grid it shares an element with, 6 x 6 blocks, plus each node's own block) and
// values are scattered into it: no triplet list. With `prune_zeros` (default) the entries that are
// exactly zero are removed afterwards (e.g. membrane-bending coupling of a flat plate in a basic
// plane, the rotational diagonal of a lumped mass, a dof no element stiffens).
//
// Elements: CBAR/CBEAM, CROD/CONROD, CQUAD4, CTRIA3, CONM2, CELAS1/2, CHEXA/CPENTA/CTETRA/CPYRAM. RBE2 and SPCs are
// constraints (constraints.hpp). Cards in Model::unsupported are ignored here. DMIG matrices the
// case control selects (K2GG, M2GG) are added afterwards (dmig.hpp).
#include <Eigen/SparseCore>
#include <optional>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/element_common.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

struct AssemblyOptions {
  MassKind mass = MassKind::Lumped;  ///< PARAM COUPMASS > 0 -> Coupled (Nastran default lumped)
  double wtmass = 1.0;               ///< PARAM WTMASS: multiplies every mass term
  double k6rot = 100.0;              ///< PARAM K6ROT: drilling stiffness factor of CQUAD4/CTRIA3
  bool prune_zeros = true;           ///< drop exact zeros from K and M after assembly
  /// PARAM QUAD4TYP MIN4T (MYSTRAN's parameter; absent: seflex's MITC4/MITC3, Nastran-like): CQUAD4
  /// bending + transverse shear by MIN4T, CTRIA3's by MIN3, PLOAD2 their work-equivalent load
  /// (forces and corner moments). Shear factors (MYSTRAN's PARAMs and defaults): CTRIA3 PARAM CBMIN3
  /// (2.0), the four MIN3 sub-triangles of a CQUAD4 PARAM CBMIN4T (3.6; with it MYSTRAN 12.0's
  /// AQ3U2S004 eigenvalues are reproduced to 7 digits, with 2.0 they are 0.6-4 % off).
  std::optional<MystranPlate> mystran_plate;
};

/// Options from the model's PARAMs (COUPMASS, WTMASS, K6ROT, QUAD4TYP, CBMIN3, CBMIN4T); defaults as above
/// when absent. Throws InputError for a non-numeric or non-positive WTMASS, or a negative K6ROT.
AssemblyOptions assembly_options(const Model& model);

struct GlobalMatrices {
  DofMap dofs;
  Eigen::SparseMatrix<double> K;  ///< n x n, n = dofs.size()
  Eigen::SparseMatrix<double> M;  ///< n x n, WTMASS applied
  /// M without the external superelements' MAA (SEBULK EXTOP4, Model::external_parts): the mass the
  /// bulk data's GRAV and RFORCE act on (an external part's loads are its own). 0 x 0 when the model
  /// has no external superelement (then that mass is M itself): use load_mass().
  Eigen::SparseMatrix<double> M_bulk;
  /// The g-set mass GRAV and RFORCE load (fem::load_vector): M_bulk, or M without external superelements.
  const Eigen::SparseMatrix<double>& load_mass() const { return M_bulk.rows() > 0 ? M_bulk : M; }
};

/// Assemble K and M of a finalized model. Throws InputError (naming the card) for elements with
/// undefined references or impossible geometry.
GlobalMatrices assemble(const Model& model, const AssemblyOptions& options);

/// Axes of each grid's displacement system (columns, in basic); empty optional = basic.
/// Used by assembly, constraints and loads to rotate between basic and CD components.
std::vector<std::optional<Eigen::Matrix3d>> grid_cd_axes(const Model& model);

}  // namespace seflex::fem
