#pragma once
// Direct matrix input (DMIG) selected by the case control K2GG / M2GG, added to the assembled
// g-set matrices before constraints, as Nastran does:
//
//   K_gg += CK2 * sum(K2GG matrices),   M_gg += CM2 * sum(M2GG matrices)
//
// - Terms are at grid components (1-6, in the grid's displacement system CD, like every g-set dof)
//   or scalar points (component 0 or blank).
// - The matrices must be symmetric DMIGs (IFO = 6), as Nastran requires for K2GG/M2GG. Each column
//   entry may give either triangle; a term given at (i, j) and at (j, i), or twice, is an error.
// - PARAM WTMASS does NOT scale M2GG (Nastran QRG, M2GG remark: "M2GG input is not affected by
//   PARAM,WTMASS"); PARAM CK2 and CM2 (default 1.0) scale K2GG and M2GG.
// - Selection: the global case control, or the first SUBCASE (subcases inherit the global K2GG and
//   M2GG); subcases selecting different matrices are an error (seflex assembles one K and one M).
#include <Eigen/SparseCore>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

/// Names of the DMIG matrices selected by K2GG and M2GG. Throws InputError if subcases disagree.
struct DirectMatrixSelection {
  std::vector<std::string> k2gg, m2gg;
};
DirectMatrixSelection direct_matrix_selection(const Model& model);

/// The g-set matrix (n x n, both triangles stored) of the symmetric DMIGs named, summed and scaled
/// by `scale`. Throws InputError naming the DMIG card for a missing matrix, a form other than 6,
/// a term given twice (or in both triangles), or a dof that does not exist.
Eigen::SparseMatrix<double> dmig_matrix(const Model& model, const DofMap& dofs, const std::vector<std::string>& names,
                                        double scale);

/// The g-set stiffness (mass = false) or mass of the model's external superelements (SEBULK EXTOP4,
/// Model::external_parts: their KAA or MAA at their assembled dofs; not scaled by CK2/CM2 or WTMASS:
/// the matrices are physical, as Nastran wrote them). Throws InputError naming the SEBULK for a dof
/// the model lacks.
Eigen::SparseMatrix<double> external_part_matrix(const Model& model, const DofMap& dofs, bool mass);

/// Add the K2GG and M2GG selections and the external superelements' matrices to assembled K and M
/// (both triangles stored). No-op when there are none. With external superelements, `M_bulk` (if not
/// null) is set to M without their MAA: the elements' mass plus M2GG (GlobalMatrices::M_bulk). Called
/// by fem::assemble.
void add_direct_matrices(const Model& model, const DofMap& dofs, Eigen::SparseMatrix<double>& K,
                         Eigen::SparseMatrix<double>& M, Eigen::SparseMatrix<double>* M_bulk = nullptr);

}  // namespace seflex::fem
