#pragma once
// CONM1: a 6 x 6 symmetric mass matrix on grid G, its rows and columns the translations and
// rotations along and about the axes of system CID (0 = basic) at the grid (MSC Nastran QRG CONM1).
//   M_basic = T M_cid T^T,  T = blockdiag(A, A),  A the CID axes (columns) in basic.
#include <Eigen/Core>

#include "seflex/fem/element_common.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

/// 6 x 6 mass on the grid's dofs in basic, before WTMASS. Throws InputError for an undefined grid or
/// system, or a matrix that is not positive semi-definite.
Matrix6 conm1_mass(const Model& model, const Conm1& c);

}  // namespace seflex::fem
