#pragma once
// CQUAD4: 4-node flat shell facet with warping correction, 24 x 24 on 4 grids x 6 dofs, basic.
//
// Formulation, in the element's mean plane (normal e3 = (x3 - x1) x (x4 - x2) normalised, origin
// at the centroid; the corners are projected onto it):
// - Membrane: the bilinear quadrilateral with two incompatible modes per direction (QM6), the
//   incompatible-mode strains evaluated with the centre Jacobian so that it passes the patch test
//   on any convex quadrilateral: Taylor, Beresford & Wilson, "A non-conforming element for stress
//   analysis", IJNME 10 (1976) 1211-1219. Exact in-plane pure bending on rectangles.
// - Bending and transverse shear: the Mindlin plate of the MITC4 element (Bathe & Dvorkin, "A
//   four-node plate bending element based on Mindlin/Reissner plate theory and a mixed
//   interpolation", IJNME 21 (1985) 367-383): bilinear rotations, covariant transverse shear
//   strains tied at the edge midpoints, so the element does not lock in thin plates and passes the
//   constant-curvature patch test on distorted meshes. The transverse shear stiffness is scaled by
//   t^2 / (t^2 + 0.1 h^2), h the longest edge (the stabilised MITC4 of Lyly, Stenberg & Vihinen, "A
//   stable bilinear element for the Reissner-Mindlin plate model", CMAME 110 (1993) 343-357): it
//   tends to 1 under refinement and, like the residual bending flexibility of Nastran's QUAD4, keeps
//   coarse thin elements from over-constraining the rotations of the beams they are attached to
//   (with it the ALL-ELEM-TEST validation deck agrees with MYSTRAN to 1e-4, without it by 6 %).
// - Drilling: the rotation about the normal theta_z is tied to the membrane rotation
//   omega = (dv/dx - du/dy)/2 (incompatible modes included) by
//     G t A (theta_z - omega)^2 at the centre  +  (K6ROT * 1e-6) G t int (theta_z - omega)^2 dA,
//   both rigid-body invariant. The first is the Hughes-Brezzi drilling term with gamma = G
//   (Hughes & Brezzi, "On drilling degrees of freedom", CMAME 72 (1989) 105-121) in one-point form,
//   so that it cannot lock; it couples the membrane rotation to the bending rotation of neighbouring
//   non-coplanar facets, without which twisted and warped meshes are far too flexible (MacNeal-Harder
//   twisted beam). The second, scaled by PARAM K6ROT (default 100: a drilling diagonal of about
//   1e-5 G t A per corner, the magnitude of MSC Nastran's K6ROT, MYSTRAN pull request #175), gives
//   every corner's drilling rotation stiffness.
// - Warped elements: rigid links from the grids to their projections on the mean plane
//   (MacNeal, "Finite Elements: Their Design and Performance", 1994, sec. 9.4), which keep the six
//   rigid-body modes exact.
// Section (section.hpp): [N; M] = [A B; B D] [eps0; kappa] and Q = S gamma from the PSHELL (MID1,
// MID2 with 12I/T^3, MID3 with TS/T, MID4 coupling; MAT1, MAT2, MAT8) or the PCOMP/PCOMPG laminate,
// rotated from the material axes (THETA from the projected G1-G2 edge, or the projected x axis of
// MCID) to the element axes; the coupling B ties the membrane (incompatible modes included, so they
// are condensed together with the plate dofs) to the curvatures. Corner thicknesses T1..T4 of a
// PSHELL are averaged. ZOFFS (the reference plane that far above the grids along the normal) shifts
// the section: B + e A, D + 2 e B + e^2 A (ShellSection::offset); the mass stays at the grids.
// Mass: lumped (Nastran default) m_i = (rho t + NSM) int N_i dA on the translations of grid i
// (A/4 on a parallelogram); coupled (COUPMASS > 0) (rho t + NSM) int N_i N_j dA on each
// translation; no rotary inertia either way.
#include <Eigen/Core>
#include <array>

#include "seflex/fem/element_common.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/fem/section.hpp"

namespace seflex::fem {

struct Quad4Element {
  std::array<Eigen::Vector3d, 4> x{};  ///< corner positions G1..G4, basic (consecutive around the edge)
  ShellSection section;                ///< in element axes (e1 along the projected G1-G2 edge)
  /// CQUADR: the Allman-type membrane with drilling rotations (element_membrane_drilling.hpp)
  /// instead of QM6 and the drilling terms above; K6ROT has no effect on it. The plate is MITC4's.
  bool drilling = false;
};

/// Stiffness (24 x 24, basic). k6rot: PARAM K6ROT. mystran (PARAM QUAD4TYP MIN4T): MIN4T bending
/// and transverse shear (element_plate_min4t.hpp) instead of MITC4's; the rest unchanged.
NodeMatrix<4> quad4_stiffness(const Quad4Element& e, double k6rot, const MystranPlate* mystran = nullptr);
/// Work-equivalent load (24, basic) of a uniform pressure q along the normal e3 of MIN4T
/// (PARAM QUAD4TYP MIN4T): forces along e3 and moments about the corners (element_plate_min4t.hpp).
Eigen::Matrix<double, 24, 1> quad4_mystran_pressure_load(const Quad4Element& e, double q, const MystranPlate& mystran);
/// Mass (24 x 24, basic), before WTMASS.
NodeMatrix<4> quad4_mass(const Quad4Element& e, MassKind kind);
/// Lumped translational mass of each corner (int N_i dA (rho t + NSM)), before WTMASS.
std::array<double, 4> quad4_lumped_masses(const Quad4Element& e);

/// Resolve a CQUAD4 of a finalized model; throws InputError for undefined references, repeated
/// grids, a degenerate (zero-area or non-convex) quadrilateral, or an unusable MCID.
/// `section` (material axes), when given, is used instead of resolving the property again (assembly
/// caches it); Quad4Element::section is in element axes.
Quad4Element make_quad4_element(const Model& model, const Shell& shell, const ShellSection* section = nullptr);

/// Membrane stress resultants (Nxx, Nyy, Nxy; force per length, element axes e1 e2 of the mean plane)
/// at the 2 x 2 Gauss points for grid displacements u (24, basic): N = A eps + B kappa with the QM6
/// membrane strain (compatible + incompatible modes condensed with the membrane and coupling
/// stiffness; the small K6ROT drilling penalty is left out of that condensation).
/// Implemented in element_shell_quad4_kg.cpp.
std::array<Eigen::Vector3d, 4> quad4_membrane_resultants(const Quad4Element& e, const Eigen::Matrix<double, 24, 1>& u_basic);

/// Differential (geometric) stiffness (24 x 24, basic) under membrane resultants N_g at the 2 x 2
/// Gauss points (element axes): the Hessian of int (1/2) [N_ab u_k,a u_k,b] dA over the three
/// translations k of the bilinear field (in-plane AND out-of-plane displacements, the consistent form),
///   K_sigma(i, j) = int grad N_i^T [Nxx Nxy; Nxy Nyy] grad N_j dA  (x) I_3,
/// nothing on the rotations. I_3 is the same in every frame, so the blocks need no rotation.
NodeMatrix<4> quad4_geometric_stiffness(const Quad4Element& e, const std::array<Eigen::Vector3d, 4>& N_gauss);

}  // namespace seflex::fem
