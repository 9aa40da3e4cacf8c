#pragma once
// CROD / CONROD: axial and torsional rod between two grids, 12 x 12 on (GA, GB) x 6 dofs, basic.
//   K = EA/L (n n^T) on the translations and GJ/L (n n^T) on the rotations, with the pattern
//   [1 -1; -1 1] between the ends; n is the unit axis from GA to GB.
// Mass: lumped (Nastran default) (rho A + NSM) L / 2 on the translations of each end; coupled
// (COUPMASS > 0) (rho A + NSM) L / 6 [2 1; 1 2] on each of the three translations (the rod carries
// the mass of its length in every direction); no rotary inertia either way.
#include <Eigen/Core>

#include "seflex/fem/element_common.hpp"
#include "seflex/fem/material.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

struct RodElement {
  Eigen::Vector3d x_A = Eigen::Vector3d::Zero(), x_B = Eigen::Vector3d::Zero();  ///< basic
  double A = 0, J = 0, nsm = 0;
  IsotropicMaterial material;
};

NodeMatrix<2> rod_stiffness(const RodElement& e);
NodeMatrix<2> rod_mass(const RodElement& e, MassKind kind);  ///< before WTMASS

/// Equivalent grid loads (12, basic) of a free thermal expansion alpha dT of the rod: the axial
/// force E A alpha dT pushing the ends apart.
Eigen::Matrix<double, 12, 1> rod_thermal_load(const RodElement& e, double alpha, double dT);

/// Resolve a CROD (PROD) or CONROD of a finalized model; throws InputError for undefined
/// references or a zero length.
RodElement make_rod_element(const Model& model, const Rod& rod);

/// Axial force N (tension positive) of the rod for grid displacements u (12, basic):
///   N = EA/L n . (u_B - u_A).
double rod_axial_force(const RodElement& e, const Eigen::Matrix<double, 12, 1>& u_basic);

/// Differential (geometric, stress) stiffness (12 x 12, basic) of the rod under axial force N
/// (tension positive): the Hessian of N int (1/2) u'.u' ds (the nonlinear part of the Green-Lagrange
/// axial strain), K_sigma = (N / L) [I -I; -I I] on the translations, nothing on the rotations.
/// Implemented in element_rod_kg.cpp.
NodeMatrix<2> rod_geometric_stiffness(const RodElement& e, double N);

}  // namespace seflex::fem
