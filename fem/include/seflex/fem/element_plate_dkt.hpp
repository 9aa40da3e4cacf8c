#pragma once
// DKT: the discrete Kirchhoff triangle (Batoz, Bathe & Ho, "A study of three-node triangular plate
// bending elements", IJNME 15 (1980) 1771-1812), the bending part of CTRIA3 when the section has no
// transverse shear flexibility (PSHELL MID3 blank, PCOMP/PCOMPG plies whose MAT8 leaves G1Z and G2Z
// blank: ShellSection::shear_flexible false). A function of the triangle's local corner coordinates
// and the bending stiffness only, so that other triangles (CTRIAR) can use it.
//
// Formulation, in the plate's plane, dofs (w, theta_x, theta_y) per corner (as MIN3,
// element_plate_min3.hpp), beta = (theta_y, -theta_x) the rotation of the normal (u = z beta), so
// that Kirchhoff's constraint is beta = -grad w and the curvatures are
// kappa = (beta_x,x, beta_y,y, beta_x,y + beta_y,x) = (theta_y,x, -theta_x,y, theta_y,y - theta_x,x):
// - beta is quadratic (the 6-node triangle: corners and edge midpoints);
// - at the corners beta is the corner's rotation (Kirchhoff at the corners: beta_i = -grad w_i);
// - at the midpoint of edge i-j (length l, unit tangent s from i to j, normal n) the tangential
//   component is -dw/ds of the cubic (Hermite) deflection of the edge, whose end slopes are
//   dw/ds = -s . beta at the corners, and the normal component is the mean of the corners':
//     s . beta_ij = -3 (w_j - w_i) / (2 l) - s . (beta_i + beta_j) / 4,
//     n . beta_ij = n . (beta_i + beta_j) / 2;
// - so kappa is linear in the area coordinates and K = int B^T D B dA is exact with the three
//   edge-midpoint points (weights A/3).
// The element passes the constant-curvature patch test on any triangle (a quadratic w gives the exact
// linear beta), has the three rigid plate modes (w, theta_x, theta_y of a rigid plane) as its only
// zero-energy modes, and converges as h^2 in energy and frequency. There is no transverse shear, so no
// shear locking: D may be any symmetric bending stiffness (isotropic, orthotropic, laminated).
#include <Eigen/Core>
#include <array>

#include "seflex/fem/plate_matrix.hpp"

namespace seflex::fem {

/// The DKT's curvature-displacement relation kappa(L) = sum_i L_i C_i q of a triangle: C_i the 3 x 9
/// curvature matrix at corner i (kappa is linear in the area coordinates L).
struct DktCurvature {
  std::array<Eigen::Matrix<double, 3, 9>, 3> at_corner;
  double area = 0;
  /// Curvature matrix (3 x 9) at area coordinates L (L_1 + L_2 + L_3 = 1).
  Eigen::Matrix<double, 3, 9> at(const Eigen::Vector3d& L) const {
    return L[0] * at_corner[0] + L[1] * at_corner[1] + L[2] * at_corner[2];
  }
  /// The curvature matrix averaged over the triangle (at the centroid): int B dA = A mean().
  Eigen::Matrix<double, 3, 9> mean() const { return (at_corner[0] + at_corner[1] + at_corner[2]) / 3.0; }
};

/// The curvatures of the DKT with corners p (counter-clockwise about +z, any origin). Throws
/// std::logic_error (SEFLEX_DEMAND) for a zero-area or clockwise triangle.
DktCurvature dkt_curvature(const std::array<Eigen::Vector2d, 3>& p);

/// Bending stiffness of the DKT (9 x 9, (w, theta_x, theta_y) of corner i at 3 i + 0..2): corners p
/// counter-clockwise about +z, D the bending stiffness (M = D kappa) in the same axes.
PlateMatrix3 dkt_stiffness(const std::array<Eigen::Vector2d, 3>& p, const Eigen::Matrix3d& D);

}  // namespace seflex::fem
