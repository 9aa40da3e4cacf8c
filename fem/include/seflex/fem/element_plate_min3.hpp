#pragma once
// MIN3: Tessler & Hughes' three-node Mindlin plate triangle, the bending + transverse shear part of
// CTRIA3 (and, four at a time, of CQUAD4's MIN4T) under PARAM QUAD4TYP MIN4T (MYSTRAN's elements;
// assembly.hpp MystranPlate).
//
// Formulation (A. Tessler & T.J.R. Hughes, "A three-node Mindlin plate element with improved
// transverse shear", CMAME 50 (1985) 71-101), in the plate's plane, dofs (w, theta_x, theta_y) per
// corner, beta = (theta_y, -theta_x) the rotation of the normal (u = z beta):
// - rotations linear in the area coordinates L_i; deflection anisoparametric (quadratic)
//     w = sum_i L_i w_i + sum_edges 4 L_i L_j c_ij,  c_ij = (beta_j - beta_i) . (x_j - x_i) / 8,
//   the choice that makes the tangential shear strain constant along every edge;
// - bending: kappa = (theta_y,x, -theta_x,y, theta_y,y - theta_x,x) (constant), K_b = A B_b^T D B_b;
// - transverse shear gamma = grad w + beta (linear), K_s = int B_s^T S B_s dA (edge-midpoint rule,
//   exact);
// - shear relaxation: K = K_b + phi^2 K_s, phi^2 = c psi / (1 + c psi), psi = (sum of K_b's rotation
//   diagonal) / (sum of K_s's rotation diagonal) (ibid.; MYSTRAN CALC_PHI_SQ), c = PARAM CBMIN3
//   (2.0) for a CTRIA3, CBMIN4T (3.6) for MIN4T's sub-triangles (element_plate_min4t.hpp). phi^2
//   -> 1 for thick and -> c psi for thin elements, which removes shear locking.
// Pressure: the work-equivalent load int q w dA of the same deflection field: q A / 3 on each w and
// corner MOMENTS from the edge terms (q A / 3 per edge times d c_ij / d theta).
#include <Eigen/Core>
#include <array>

#include "seflex/fem/plate_matrix.hpp"

namespace seflex::fem {

/// Bending + shear stiffness of MIN3, corners p (counter-clockwise about +z, any origin), bending
/// stiffness D (M = D kappa) and transverse shear stiffness S (Q = S gamma) in the same axes; cb
/// the shear factor (CBMIN3).
PlateMatrix3 min3_stiffness(const std::array<Eigen::Vector2d, 3>& p, const Eigen::Matrix3d& D, const Eigen::Matrix2d& S,
                            double cb);

/// Work-equivalent load of a uniform pressure q along +z on the MIN3 deflection field.
PlateVector3 min3_pressure_load(const std::array<Eigen::Vector2d, 3>& p, double q);

}  // namespace seflex::fem
