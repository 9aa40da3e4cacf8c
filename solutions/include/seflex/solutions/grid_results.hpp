#pragma once
// Grid results in the basic system: g-set vectors (each grid's components in its displacement
// system CD, fem/dof_map.hpp) turned into per-grid rows T1 T2 T3 R1 R2 R3 along the basic axes,
// and resultants of nodal force vectors.
#include <Eigen/Core>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::solutions {

/// n_grids x 6, row i = grid i of Model::grids: (t, r)_basic = (A_cd t_cd, A_cd r_cd).
using GridTable = Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>;

/// Per-grid basic components of a g-set vector v_g (size dofs.size()); scalar points are skipped.
GridTable grid_vectors_basic(const fem::Model& model, const fem::DofMap& dofs, const Eigen::Ref<const Eigen::VectorXd>& v_g);

/// Resultant of a g-set vector of nodal forces and moments, in basic, about the basic origin:
/// (F, M) with F = sum f_i, M = sum (x_i x f_i + m_i). Scalar points carry no resultant.
Eigen::Matrix<double, 6, 1> resultant_basic(const fem::Model& model, const fem::DofMap& dofs,
                                            const Eigen::Ref<const Eigen::VectorXd>& f_g);

}  // namespace seflex::solutions
