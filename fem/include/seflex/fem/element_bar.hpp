#pragma once
// CBAR / CBEAM: 3-D beam between two grids, 12 x 12 on (GA, GB) x (T1 T2 T3 R1 R2 R3),
// in the basic system.
//
// Formulation (exact for a prismatic bar, Przemieniecki, Theory of Matrix Structural Analysis,
// 1968, ch. 5): the flexibility of the bar clamped at end A and loaded at end B,
//   C = int_0^L B(s)^T S^-1 B(s) ds,   section resultants = B(s) * (tip loads),
// with the section compliance S^-1 = diag(1/EA, 1/(G K1 A), 1/(G K2 A), 1/GJ) and the bending
// compliance inv(E [I2 -I12; -I12 I1]); K = Gamma^T C^-1 Gamma with Gamma the deformation of B
// relative to A's rigid motion. A tapered CBEAM integrates C over its stations (section properties
// linear between them). Euler-Bernoulli when K1/K2 are blank, Timoshenko otherwise; I12
// couples the two bending planes. The six rigid-body modes are in the null space by construction.
//
// Element axes (Nastran): x from offset end A to offset end B; y in the plane of x and the
// orientation vector v; z = x X y. Offsets WA/WB are rigid links from the grid to the bar end.
//
// Neutral-axis offset (PBEAM N1/N2, MSC's CBEAM): the reference axis joining the offset ends is the
// shear centre, where torsion and transverse shear act; axial force and bending act at the neutral
// axis n(s) = (n1, n2) in element y, z. With the section resultants (N, Vy, Vz, T, My, Mz) taken about
// the reference axis, the moments about the neutral axis are My - n2 N and Mz + n1 N, so the section
// compliance about the reference axis is Q^T S^-1 Q (Q that map) and the flexibility is integrated
// along the bar as for a taper; an axial force at the reference axis bends the beam with P n / (E I).
// Pin flags release element-axis dofs at an end by static condensation (their rows/columns of the
// end stiffness become zero); mass is not affected by pin flags.
//
// Mass: lumped (Nastran default): (rho A + NSM) L / 2 on the three translations of each bar end;
// a CBAR has no rotary inertia, a CBEAM has its polar inertia (rho (I1 + I2) + NSI) L / 2 about the
// beam axis at each end (Simcenter Nastran 2019.2 and MSC Nastran 2005 on pyNastran's models/beam_modes: grid point weight
// generator and torsion eigenvalue, tests/data/validation/nastran_cbar_cbeam_conm2_modes). Coupled
// (PARAM COUPMASS > 0): linear axial, cubic-Hermite transverse translational mass (no rotary
// inertia of bending) and torsional inertia (rho (I1 + I2) + NSI) L/6 [2 1; 1 2] so that the rigid
// spin about the bar axis has the section's exact polar inertia. With offsets the end masses sit
// at the bar ends and reach the grids through the rigid links.
// A CBEAM whose neutral axis (N1/N2) or non-structural mass (M1/M2) is off the reference axis carries
// two line masses: rho A with polar inertia rho (I1 + I2) at the neutral axis (the centroid of a
// homogeneous section) and NSM with NSI at (M1, M2), each a rigid part of the section: lumped, the
// rigid-body mass (6 x 6) of each Gauss point's slice shared between the ends by the linear functions
// (total mass, centre of gravity in y, z and inertia about the axis kept); coupled, the velocity of the
// offset line u + theta x r with the shape functions above (theta_y = -w', theta_z = v' from the
// Hermite functions), integrated along the bar.
#include <Eigen/Core>
#include <vector>

#include "seflex/fem/element_common.hpp"
#include "seflex/fem/material.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/fem/section.hpp"

namespace seflex::fem {

/// A station of a tapered bar: its section at x (fraction of the length from end A).
struct BarStation {
  double x = 0;
  BarSection section;
  double nsi = 0;
};

struct BarElement {
  Eigen::Vector3d x_A = Eigen::Vector3d::Zero(), x_B = Eigen::Vector3d::Zero();  ///< grid positions, basic
  Eigen::Vector3d w_A = Eigen::Vector3d::Zero(), w_B = Eigen::Vector3d::Zero();  ///< offsets grid -> bar end, basic
  Eigen::Vector3d v = Eigen::Vector3d::UnitZ();  ///< orientation vector, basic (any length, not along x)
  BarSection section;
  IsotropicMaterial material;
  ComponentMask pin_A = 0, pin_B = 0;  ///< released element-axis dofs (bit c-1 for component c)
  bool is_beam = false;  ///< CBEAM (lumped mass carries the polar inertia), else CBAR
  double nsi = 0;        ///< PBEAM NSI: non-structural mass moment of inertia per length
  /// Tapered CBEAM (PBEAM/PBEAML stations): sections at x = 0 .. 1 along the bar, linear between
  /// them; `section` and `nsi` are end A's. Empty: prismatic.
  std::vector<BarStation> taper;
  /// PBEAM N1/N2: the neutral axis (element y, z) from the reference axis, which is the shear centre
  /// (the line between the offset ends), at end A and end B, linear between; M1/M2 likewise the
  /// centre of gravity of the non-structural mass.
  Eigen::Vector2d n_A = Eigen::Vector2d::Zero(), n_B = Eigen::Vector2d::Zero();
  Eigen::Vector2d m_A = Eigen::Vector2d::Zero(), m_B = Eigen::Vector2d::Zero();
};

/// True when the neutral axis of `e` is off its reference axis (N1/N2 not all 0).
bool bar_has_neutral_axis_offset(const BarElement& e);

/// Element axes as columns in basic (R_BE: x, y, z) and the length between the offset ends.
/// Precondition: non-zero length and v not parallel to the axis (SEFLEX_DEMAND).
Eigen::Matrix3d bar_axes(const BarElement& e);
double bar_length(const BarElement& e);

/// Stiffness in element axes at the bar ends (before pin flags, offsets and rotation), 12 x 12.
NodeMatrix<2> bar_stiffness_element_axes(const BarElement& e);

/// Stiffness (12 x 12, basic, grid dofs): pins, offsets and rotation applied.
/// Throws InvariantError if a pin flag releases a dof the bar has no stiffness for.
NodeMatrix<2> bar_stiffness(const BarElement& e);

/// Mass (12 x 12, basic, grid dofs), before WTMASS.
NodeMatrix<2> bar_mass(const BarElement& e, MassKind kind);

/// Temperatures of a bar for its thermal load (TEMPRB, or the mean of its grids' temperatures).
struct BarTemperatureField {
  double dT = 0;                                  ///< mean temperature (TA + TB)/2 minus the material's TREF
  double tp1a = 0, tp1b = 0, tp2a = 0, tp2b = 0;  ///< effective gradients along element y (1) and z (2) at A, B
};

/// Equivalent grid loads (12, basic, grid dofs) of the bar's free thermal deformation with expansion
/// coefficient alpha: f = K u_free, u_free the motion of end A with end B clamped (element axes):
///   u_A = -alpha L dT;  (v_A, w_A) = -alpha L^2 (k_A / 6 + k_B / 3);  theta_z,A = alpha L (k1A + k1B)/2,
///   theta_y,A = -alpha L (k2A + k2B)/2, with (k1, k2) = inv([I1 I12; I12 I2]) (I1 TP1, I2 TP2)
/// (linear gradients along the bar; MYSTRAN BAR1 thermal loads). K is the pinned, offset stiffness,
/// so the result is exact for this element (a pin releases the thermal deformation it frees).
Eigen::Matrix<double, 12, 1> bar_thermal_load(const BarElement& e, double alpha, const BarTemperatureField& t);

/// Resolve a CBAR/CBEAM of a finalized model (property, material, orientation, offsets).
/// Throws InputError naming the card for undefined references, zero length, v along the axis,
/// or a section with I1 I2 <= I12^2.
BarElement make_bar_element(const Model& model, const Bar& bar);

/// Forces and moments (12: end A then end B, element axes) that the grids exert on the bar ends for grid
/// displacements u (12, basic): K T q of the pinned, offset stiffness. Implemented in element_bar_kg.cpp.
Eigen::Matrix<double, 12, 1> bar_end_forces(const BarElement& e, const Eigen::Matrix<double, 12, 1>& u_basic);

/// Axial force N (tension positive) of the bar for grid displacements u (12, basic): the element-axis
/// end force of the (pinned, offset) stiffness, N = f_x at end B. Implemented in element_bar_kg.cpp.
double bar_axial_force(const BarElement& e, const Eigen::Matrix<double, 12, 1>& u_basic);

/// Differential (geometric) stiffness (12 x 12, basic, grid dofs) of the bar under axial force N
/// (tension positive), element axes (Przemieniecki 1968, sec. 15.4, cubic Hermite bending):
///   axial N/L [1 -1; -1 1]; each bending plane N/(30 L) [36 3L -36 3L; 3L 4L^2 -3L -L^2; ...]
///   (the sign of the rotation terms follows theta_y = -w'); torsion N (I1 + I2)/(A L) [1 -1; -1 1].
/// Euler-Bernoulli form also for shear-flexible (K1/K2) sections; end moments and shears of the
/// preload are not included (axial force only). Pin flags: the released dofs follow the elastic
/// static condensation, K_sigma_c = T^T K_sigma T with u_p = -K_pp^-1 K_pr u_r. Offsets: rigid links
/// as for K (their own geometric term, the rotation of the offset arm under the end force, is not
/// included).
NodeMatrix<2> bar_geometric_stiffness(const BarElement& e, double N);

}  // namespace seflex::fem
