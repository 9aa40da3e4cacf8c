#pragma once
// CONM2: concentrated mass with offset and inertia, 6 x 6 on the grid's dofs in basic.
//   M_grid = T^T [m I 0; 0 J] T,  T = rigid_link(d)  (u_cg = u_grid + theta x d),
// d the offset from the grid to the centre of gravity and J the inertia tensor about the CG, both
// in basic. Nastran's CONM2 inertia matrix is J = [I11 -I21 -I31; -I21 I22 -I32; -I31 -I32 I33]
// (I21, I31, I32 are products of inertia int x y dm etc.).
// CID = 0: offset and inertia in basic; CID = -1: X is the CG position in basic (offset = X - grid),
// inertia in basic; CID > 0: offset components and inertia in system CID's axes at the grid.
#include <Eigen/Core>

#include "seflex/fem/element_common.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

struct Conm2Element {
  Eigen::Vector3d x_grid = Eigen::Vector3d::Zero();  ///< grid position, basic
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  ///< grid -> CG, basic
  double m = 0;
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();       ///< inertia tensor about the CG, basic axes
};

Matrix6 conm2_mass(const Conm2Element& e);  ///< before WTMASS

/// Resolve a CONM2 of a finalized model; throws InputError for an undefined grid or system.
Conm2Element make_conm2_element(const Model& model, const Conm2& c);

}  // namespace seflex::fem
