#pragma once
// Static load vectors on the g-set (every grid's six components in its displacement (CD) system,
// then the scalar points; dof_map.hpp).
//
// FORCE  SID G CID F N1 N2 N3:  force  F (N1, N2, N3) in system CID (axes at the grid) on G's T1-T3;
// MOMENT SID G CID M N1 N2 N3:  moment M (N1, N2, N3) on G's R1-R3.
// SLOAD SID S F:                F on scalar point S (a grid S: its T1).
// PLOAD SID P G1 G2 G3 [G4]:     P A along (G1 -> G2) x (G1 -> G3), a third per grid; four grids:
//                               the triangles 123, 234, 341, 412 with P/2 each (QRG PLOAD).
// FORCE1/MOMENT1 SID G F G1 G2: F along the unit vector from G1 to G2; FORCE2/MOMENT2 SID G F G1 G2
//                               G3 G4: along the unit vector of (G1 -> G2) x (G3 -> G4); directions
//                               at the grids' undeformed positions (linear Nastran, QRG FORCE1/2).
// PLOAD4 (face_pressure.hpp):   corner pressures P1..P4 on a CQUAD4/CTRIA3 or on the face of a CHEXA/
//                               CPENTA/CTETRA/CPYRAM (G1, G3/G4), work-equivalent grid forces f_a = int N_a p d dA
//                               with d the shell normal, the inward normal of a solid face, or N/|N| in CID;
//                               the THRU form loads the shells of the range and skips other ids.
// PLOAD2 SID P EID...:          uniform pressure P on CQUAD4/CTRIA3, along the element normal
//                               (right-hand rule on G1 G2 G3 [G4], MSC QRG PLOAD2 remark); work-
//                               equivalent corner forces f_i = P int N_i n dA (bilinear N_i of the
//                               quad, 2 x 2 Gauss, exact also when warped; a triangle gives P A n / 3
//                               per corner); no moments: the resultant acts through the element's
//                               centroid as Nastran's (NX Nastran User's Guide, "Distributed Loads":
//                               the CQUAD4's total force "is distributed to corner grid points using
//                               the geometric shape of the element"), and it is the consistent load
//                               of MITC4/MITC3, whose deflection comes from the corner deflections.
//                               With PARAM QUAD4TYP MIN4T (MYSTRAN's plate elements, assembly.hpp)
//                               the work-equivalent load of MIN4T/MIN3 instead: forces along the
//                               normal AND corner moments (their deflection depends on the corner
//                               rotations; element_plate_min3.hpp, element_plate_min4t.hpp), on the
//                               quad's mean plane.
// GRAV   SID CID A N1 N2 N3:    acceleration g = A (N1, N2, N3) (magnitude A |N|, MSC QRG GRAV) in
//                               rectangular system CID, applied to every mass:  p = M a_g.
// RFORCE SID G CID A R1 R2 R3 METHOD / RACC: steady rotation w = 2 pi A R and angular acceleration
//                               alpha = 2 pi RACC R (R = (R1, R2, R3) in rectangular system CID; A in
//                               revolutions per unit time) about the axis through grid G (0: basic
//                               origin):  p = -M a,  a_i = w x (w x r_i) + alpha x r_i on the
//                               translations and alpha on the rotations of grid i, r_i from G to grid i
//                               (MSC QRG RFORCE remark 1; MYSTRAN RFORCE_PROC has the same signs).
// LOAD   SID S S1 L1 S2 L2 ...:  S * sum_i S_i * (load set L_i); a set is every FORCE, MOMENT,
//                               PLOAD2, GRAV and RFORCE card with that SID.
//
// GRAV and RFORCE use the assembled mass matrix (WTMASS and M2GG included; an external superelement's
// MAA not: GlobalMatrices::load_mass), once for all of them:
// the grid accelerations of every inertia card of the set (scaled) are summed into one g-set vector
// a and p += M a. With a lumped mass this is Nastran's per-grid 6 x 6 mass times the grid's rigid-
// body acceleration (MYSTRAN GRAV_PROC, RFORCE_PROC); with COUPMASS the coupling terms are kept,
// which for GRAV is exact (M times a rigid-body acceleration) and for RFORCE is Nastran's METHOD 1.
//
// Thermal loads (TEMPERATURE(LOAD) = SID): TEMP SID G T (grid temperatures), TEMPD SID T (the
// default of the set's grids), TEMPRB SID EID TA TB TP1A TP1B TP2A TP2B (line elements). Equivalent
// element loads of the free thermal deformation, f_e = K_e u_free (exact for the flexibility-based
// bar):
//   CBAR/CBEAM: mean temperature T = (TA + TB)/2, axial strain alpha (T - TREF); curvatures from
//               the effective gradients TP1, TP2 (linear along the bar), thermal moments
//               E alpha (I1 TP1, I2 TP2) (as MYSTRAN BAR1 computes them);
//   CROD/CONROD: axial force E A alpha (T - TREF) (TEMPRB TA/TB or the grids' temperatures).
//   CQUAD4/CTRIA3: the mean of the element's grid temperatures (QRG TEMP, no TEMPPi), uniform
//               through the thickness, from the section's TREF (PSHELL: MID1's; PCOMP/PCOMPG: the
//               property's); thermal resultants N_T, M_T of the PSHELL (MID1 alphas) or of the
//               laminate's plies (MAT1/MAT2/MAT8 alphas, classical lamination theory), applied as
//               the stiffness times the free thermal deformation (element_shell_thermal.hpp). A
//               PSHELL whose MID4 has thermal expansion is refused (its thermal moment is not
//               computed);
//   CHEXA/CPENTA/CTETRA/CPYRAM: grid temperatures interpolated by the shape functions, f = int B^T D
//               eps_T dV (element_solid.hpp: solid_thermal_load).
// Grid temperatures give a bar/rod T = mean of its two grids and no gradient. A new element type
// with a thermal expansion coefficient must either get its thermal load here or be refused
// (solutions::check_card_usage), never be skipped silently.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

/// Load vector (size dofs.size()) of load set `sid`: a LOAD combination if one has this SID,
/// otherwise the load cards with this SID. `M_gg` is the g-set mass GRAV and RFORCE act on
/// (GlobalMatrices::load_mass, assembly.hpp), needed when the set holds GRAV or RFORCE cards
/// (InvariantError if it is then null).
/// Throws InputError if nothing has this SID, if a LOAD references an undefined set, or a card
/// references an undefined grid, element or coordinate system, or a PLOAD2 element is not a shell.
Eigen::VectorXd load_vector(const Model& model, const DofMap& dofs, int sid,
                            const Eigen::SparseMatrix<double>* M_gg = nullptr);

/// Equivalent nodal loads (size dofs.size()) of thermal load set `sid` (TEMP, TEMPD, TEMPRB) on the
/// CBAR/CBEAM/CROD/CONROD, CQUAD4/CTRIA3 and CHEXA/CPENTA/CTETRA/CPYRAM elements. Throws InputError if no
/// temperature card has this SID, if a TEMPRB names an element that is not a bar or rod, if an
/// element with thermal expansion (a bar/rod without TEMPRB) has a grid with no temperature in the
/// set (no TEMP for it and no TEMPD), or for a heated PSHELL whose MID4 has thermal expansion.
Eigen::VectorXd thermal_load_vector(const Model& model, const DofMap& dofs, int sid);

}  // namespace seflex::fem
