#pragma once
// CBEND / PBEND: curved beam along a circular arc of radius R and angle Theta from GA to GB, 12 x 12
// on (GA, GB) x (T1 T2 T3 R1 R2 R3), basic.
//
// Formulation: thin curved beam, exact by Castigliano (Roark's Formulas for Stress and Strain, ch. 9,
// the tables of circular arcs are its closed forms): the flexibility of GB relative to GA clamped,
//   C = int_0^Theta D(phi)^T F D(phi) R dphi,
// D(phi) the section resultants (axial N along the tangent t, shears along the radius r and the arc
// normal z, torsion about t, bending about r and about z) of a unit tip load at GB, F =
// diag(1/EA, 1/(K1 G A), 1/(K2 G A), 1/GJ, 1/(E I2), 1/(E I1)) (plane 1 = the plane of the bend:
// bending about z uses I1; K blank = rigid in shear, QRG PBEND remark 4), 16-point Gauss-Legendre
// over phi (the integrand is a trigonometric polynomial of degree 2: error below 1e-15 for any
// Theta < 2 pi). K_BB = C^-1 and K_e = T^T [S^T K_BB S, -S^T K_BB; -K_BB S, K_BB] with S the rigid
// map of GA's motion to GB: the six rigid-body modes are force-free by construction.
// Not modelled: the neutral-axis shift DELTAN of a thick bend (Winkler-Bach: MSC's default is a
// shift of about I1 / (A RB), an O(I1 / (A RB^2)) correction to the in-plane flexibility) and the
// centroid offsets RC, ZC (listed when given); the pipe format's flexibility factors (FSI) and
// pressure (listed): a pipe is a circular tube of mean radius RM and wall T, rigid in shear.
//
// Mass: lumped, (rho A + NSM) R Theta / 2 on the three translations of each end (also with COUPMASS).
#include <Eigen/Core>

#include "seflex/fem/element_common.hpp"
#include "seflex/fem/material.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

struct BendElement {
  Eigen::Vector3d x_A = Eigen::Vector3d::Zero(), x_B = Eigen::Vector3d::Zero();  ///< basic
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< centre of curvature, basic
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); ///< unit normal of the arc's plane: A -> B turns positively about it
  double radius = 0, angle = 0;                      ///< R, Theta (radians, in (0, 2 pi))
  double A = 0, I1 = 0, I2 = 0, J = 0, K1 = 0, K2 = 0, nsm = 0;
  IsotropicMaterial material;
};

NodeMatrix<2> bend_stiffness(const BendElement& e);
NodeMatrix<2> bend_mass(const BendElement& e);  ///< lumped, before WTMASS

/// Resolve a CBEND (PBEND, MAT1) of a finalized model: the arc from GEOM and the orientation.
/// Throws InputError naming the card and field for undefined references and for an orientation or
/// PBEND RB/THETAB that define no arc through GA and GB.
BendElement make_bend_element(const Model& model, const Bend& bend);

}  // namespace seflex::fem
