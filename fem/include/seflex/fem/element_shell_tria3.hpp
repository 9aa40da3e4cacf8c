#pragma once
// CTRIA3: 3-node flat shell, 18 x 18 on 3 grids x 6 dofs, basic.
//
// Formulation, in the element plane (e1 along G1->G2, e3 the normal):
// - Membrane: constant-strain triangle.
// - Bending and transverse shear: the Mindlin plate of MITC3 (Lee & Bathe, "Development of MITC
//   isotropic triangular shell finite elements", Computers & Structures 82 (2004) 945-962): linear
//   rotations and deflection; the transverse shear strain is the field a + b (-y, x) whose
//   tangential component at each edge midpoint equals the edge's tangential shear strain, which
//   passes the constant-curvature patch test; the shear stiffness is scaled by t^2 / (t^2 + 0.1 h^2)
//   (h the longest edge; Lyly, Stenberg & Vihinen, Computational Mechanics 13 (1993) 371-387), which
//   removes the residual shear locking of the linear triangle in thin plates and tends to 1 under
//   refinement.
// - Sections without transverse shear flexibility (PSHELL MID3 blank, PCOMP/PCOMPG plies whose MAT8
//   leaves G1Z and G2Z blank: ShellSection::shear_flexible false; MSC's QRG PSHELL: blank MID3 means
//   no transverse shear flexibility, the thin-plate case): bending by the discrete Kirchhoff triangle
//   instead (DKT, element_plate_dkt.hpp; Batoz, Bathe & Ho, IJNME 15 (1980) 1771-1812), which has no
//   shear to lock. MITC3 with the Kirchhoff penalty locked there (issue 40: a simply supported plate
//   +93 % in f11 at 8 x 8 cells, +50 % at 16 x 16; the DKT converges as h^2). The membrane-bending
//   coupling B uses the DKT's mean curvature (its curvature is linear; the CST strain constant).
// - Drilling: as CQUAD4, G t A (theta_z - omega)^2 at the centroid plus the K6ROT penalty on
//   (theta_z - omega)^2 with the 3-point rule.
// Section: as CQUAD4 (A, B, D, S of the PSHELL or PCOMP/PCOMPG in element axes; THETA from G1-G2;
// ZOFFS shifts it).
// Mass: lumped (rho t + NSM) A / 3 on the translations of each grid; coupled
// (rho t + NSM) A / 12 [2 1 1; 1 2 1; 1 1 2] on each translation; no rotary inertia.
#include <Eigen/Core>
#include <array>

#include "seflex/fem/element_common.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/fem/section.hpp"

namespace seflex::fem {

struct Tria3Element {
  std::array<Eigen::Vector3d, 3> x{};  ///< corner positions G1..G3, basic
  ShellSection section;
  /// CTRIAR: Allman's membrane with drilling rotations (element_membrane_drilling.hpp) instead of
  /// the CST and the drilling terms above; K6ROT has no effect on it. The plate is as CTRIA3's.
  bool drilling = false;
};

/// Stiffness (18 x 18, basic). mystran (PARAM QUAD4TYP MIN4T): MIN3 bending and transverse shear
/// (element_plate_min3.hpp) instead of MITC3's; the rest unchanged.
NodeMatrix<3> tria3_stiffness(const Tria3Element& e, double k6rot, const MystranPlate* mystran = nullptr);
/// Work-equivalent load (18, basic) of a uniform pressure q along the normal of MIN3 (PARAM
/// QUAD4TYP MIN4T): forces along the normal and corner moments (element_plate_min3.hpp; MIN3's
/// load does not depend on the shear factor).
Eigen::Matrix<double, 18, 1> tria3_mystran_pressure_load(const Tria3Element& e, double q);
NodeMatrix<3> tria3_mass(const Tria3Element& e, MassKind kind);      ///< before WTMASS

/// Resolve a CTRIA3 of a finalized model; throws InputError for undefined references, repeated
/// grids or a zero area.
/// `section` (material axes), when given, is used instead of resolving the property again (assembly
/// caches it); Tria3Element::section is in element axes.
Tria3Element make_tria3_element(const Model& model, const Shell& shell, const ShellSection* section = nullptr);

/// Membrane stress resultants (Nxx, Nyy, Nxy; element axes, constant) for grid displacements u
/// (18, basic): N = A eps + B kappa. Implemented in element_shell_tria3_kg.cpp.
Eigen::Vector3d tria3_membrane_resultants(const Tria3Element& e, const Eigen::Matrix<double, 18, 1>& u_basic);

/// Differential (geometric) stiffness (18 x 18, basic) under constant membrane resultants N (element
/// axes): K_sigma(i, j) = A grad N_i^T [Nxx Nxy; Nxy Nyy] grad N_j (x) I_3 on the translations
/// (in-plane and out-of-plane displacements), nothing on the rotations.
NodeMatrix<3> tria3_geometric_stiffness(const Tria3Element& e, const Eigen::Vector3d& N);

}  // namespace seflex::fem
