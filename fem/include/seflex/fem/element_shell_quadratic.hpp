#pragma once
// CTRIA6 / CQUAD8: quadratic flat shell facets, 48 x 48 on up to 8 grids x 6 dofs, basic (a
// CTRIA6 uses grids 0-5, a CQUAD8 0-7; the blocks of absent mid-side grids are zero).
//
// Formulation, in the corners' mean plane (normal from the corners: (x2 - x1) x (x3 - x1), or the
// diagonals' cross product of a quadrilateral; x along the projected G1-G2 edge; every grid
// projected onto it, isoparametric in the plane, so curved edges are followed):
// - The plate is the MITC9 element for the CQUAD8 and the MITC7 element for the CTRIA6 (Bathe, Brezzi
//   & Cho, "The MITC7 and MITC9 plate bending elements", Comput. Struct. 32 (1989) 797-814; Bucalem
//   & Bathe, IJNME 36 (1993) 3729-3754): their interior node is added and condensed statically.
//   MITC9: nine-node Lagrange w and rotations; covariant transverse shear e_r tied at the 2 x 3
//   points r = +-1/sqrt(3), s = 0, +-sqrt(3/5) and interpolated linearly in r, quadratically in s
//   (e_s the same, r and s swapped). MITC7: quadratic w, quadratic rotations plus the cubic bubble
//   27 L1 L2 L3; the covariant shear interpolated in the rotated Raviart-Thomas space of degree 2
//   (eight parameters) from its tangential component at the two Gauss points of each edge and its
//   two means over the element. Both are free of shear locking and of spurious modes, converge at
//   the optimal order (deflection error O(h^3), energy O(h^4) on smooth problems: measured in
//   tests/solutions/shell_quadratic_test.cpp), and so take the Kirchhoff penalty of a section without
//   transverse shear flexibility (PSHELL MID3 blank; section.hpp) without locking. Bending and
//   the shear energy by 3 x 3 Gauss (quadrilateral) or the 7-point degree-5 rule (triangle).
// - Membrane: the same nine-node (CQUAD8) or six-node (CTRIA6) interpolation of u, v; the section's
//   B couples it to the curvatures.
// - Drilling: (K6ROT * 1e-6) G t int (theta_z - omega)^2 dA with omega = (v,x - u,y)/2, rigid-body
//   invariant: the same small drilling stiffness as the CQUAD4's K6ROT term (element_shell_quad4.hpp).
// - A blank mid-side grid: the element's field is linear along that edge (the mid-side values the
//   mean of the edge's corners), which is the lower-order element on that edge (QRG CQUAD8/CTRIA6
//   allow the mid-side grids blank).
// - Warped or curved facets: rigid links from the grids to their projections (as the CQUAD4).
// Mass: the quadratic (serendipity eight-node, six-node) translational field, (rho t + NSM) int N_i
// N_j dA; lumped (Nastran default) by the HRZ rule (Hinton, Rock & Zienkiewicz, Earthquake Eng.
// Struct. Dyn. 4 (1976) 245-249: the consistent diagonal scaled to the element's mass), no rotary
// inertia either way.
// Loads: a uniform pressure along the normal (PLOAD2, PLOAD4) as the work-equivalent forces of the
// plate's w (interior node condensed); thermal load of a mean temperature rise (the section's N_T,
// M_T) as int B^T [N_T; M_T] dA. Not computed: differential stiffness (buckling refuses them).
#include <Eigen/Core>
#include <array>

#include "seflex/fem/element_common.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/fem/section.hpp"

namespace seflex::fem {

struct QuadraticShellElement {
  int corners = 4;                       ///< 3: CTRIA6, 4: CQUAD8
  std::array<Eigen::Vector3d, 8> x{};    ///< corners, then the mid-side grid of edge k (k to k + 1), basic
  std::array<bool, 4> has_mid{};         ///< mid-side grid given (absent: x is the edge's midpoint)
  ShellSection section;                  ///< in element axes
};

NodeMatrix<8> quadratic_shell_stiffness(const QuadraticShellElement& e, double k6rot);
NodeMatrix<8> quadratic_shell_mass(const QuadraticShellElement& e, MassKind kind);  ///< before WTMASS

/// Work-equivalent grid loads (48, basic) of a uniform pressure p along the element normal.
Eigen::Matrix<double, 48, 1> quadratic_shell_pressure_load(const QuadraticShellElement& e, double p, double k6rot);
/// Work-equivalent grid loads (48, basic) of a uniform temperature rise dT over the section's TREF.
Eigen::Matrix<double, 48, 1> quadratic_shell_thermal_load(const QuadraticShellElement& e, double dT, double k6rot);

/// The element's unit normal (basic): the mean plane's e3.
Eigen::Vector3d quadratic_shell_normal(const QuadraticShellElement& e);

/// Resolve a CTRIA6/CQUAD8 of a finalized model; throws InputError for undefined references, a
/// degenerate or non-convex element, or a mid-side grid far from its edge's middle third.
QuadraticShellElement make_quadratic_shell_element(const Model& model, const QuadraticShell& q,
                                                   const ShellSection* section = nullptr);

}  // namespace seflex::fem
