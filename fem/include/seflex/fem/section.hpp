#pragma once
// Cross-section data of line and shell elements, resolved from the property cards (PBAR/PBEAM,
// PSHELL, PCOMP/PCOMPG) and their materials.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "seflex/fem/material.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

/// Bar/beam section in element axes (Nastran PBAR conventions).
/// I1 = int y^2 dA (bending in plane 1, the element x-y plane), I2 = int z^2 dA, I12 = int y z dA.
/// K1, K2: shear area factors (shear area K1 A in plane 1, K2 A in plane 2); 0 = blank = no
/// transverse shear flexibility (Euler-Bernoulli). nsm: non-structural mass per length.
struct BarSection {
  double A = 0, I1 = 0, I2 = 0, I12 = 0, J = 0, K1 = 0, K2 = 0, nsm = 0;
};

/// A shell section as the CQUAD4 and CTRIA3 use it, whichever card defined it (PSHELL with MAT1, MAT2
/// or MAT8, PCOMP, PCOMPG): the resultants of the Reissner-Mindlin shell per unit length,
///   [N; M] = [A B; B D] [eps0; kappa],   Q = S gamma,
/// eps0 the reference-surface strains (xx, yy, xy engineering), kappa = (theta_y,x, -theta_x,y,
/// theta_y,y - theta_x,x) the curvatures (strain at height z: eps0 + z kappa, z along the element
/// normal), gamma the transverse shear strains (xz, yz). Matrices are in the axes of the section:
/// the material axes (x along the element's THETA/MCID direction) as resolved, the element axes
/// after in_element_axes().
struct ShellSection {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();  ///< membrane (force per length)
  Eigen::Matrix3d B = Eigen::Matrix3d::Zero();  ///< membrane-bending coupling (force)
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();  ///< bending (moment per length per curvature)
  /// Transverse shear stiffness (force per length). With no transverse shear flexibility (PSHELL MID3
  /// blank, plies rigid in transverse shear) a Kirchhoff penalty, 1000 x that of the homogeneous plate
  /// of the same bending stiffness: CQUAD4's MITC4 takes it without locking, CTRIA3 bends by the DKT.
  Eigen::Matrix2d S = Eigen::Matrix2d::Zero();
  bool has_membrane = false, has_bending = false;
  bool shear_flexible = false;  ///< S is the physical transverse shear stiffness (not the penalty)
  bool isotropic = false;       ///< MAT1 only and no coupling: A, B, D, S do not change with rotation
  double t = 0;                 ///< membrane thickness (PSHELL T or the corner average; PCOMP: total)
  /// In-plane shear stiffness per length of the elements' drilling terms: G T of MID1 (MAT1), the
  /// orientation average (ShellMaterial::G_iso) for MAT2/MAT8 and, summed over the plies, for PCOMP.
  double drill_Gt = 0;
  /// Squared thickness of the homogeneous (5/6 shear factor) plate whose bending-to-shear stiffness
  /// ratio the section has, t_s^2 = 10 Dg / Sg, Dg the bending stiffness and Sg the transverse shear
  /// stiffness as scalars: PSHELL Dg = G2 (12 I)/12, Sg = G3 TS (MID3 blank: (5/6) G2 (12 I)^(1/3));
  /// PCOMP Dg = sum G_k int (z - zc)^2 dz over the plies (zc the G-weighted centroid), Sg = trace(S)/2;
  /// G the material's G_iso. For a homogeneous plate t_s = T; for a sandwich with a soft core it
  /// exceeds the total thickness (its shear is softer than its bending suggests). The MITC shear stabilisation is written in it (Lyly, Stenberg & Vihinen, Comput. Mech.
  /// 13 (1993) 371-387, state the plate in the scaled form in which t^2 is exactly this ratio).
  double ts2 = 0;
  double mass_per_area_value = 0;  ///< structural + non-structural, before WTMASS
  /// Thermal resultants per unit temperature rise (uniform through the thickness) in the section's
  /// axes: N_T = int Qbar(z) alpha(z) dz, M_T = int Qbar(z) alpha(z) z dz (classical lamination
  /// theory, Jones, Mechanics of Composite Materials, 2nd ed., sec. 4.5): the resultants are
  /// [N; M] = [A B; B D] [eps0; kappa] - (T - tref) [N_T; M_T]. PSHELL: N_T = T G1 alpha1 (MID1),
  /// M_T = 0 (a thermal moment needs a gradient through the thickness, TEMPP1, not supported).
  Eigen::Vector3d NT = Eigen::Vector3d::Zero();
  Eigen::Vector3d MT = Eigen::Vector3d::Zero();
  double tref = 0;  ///< PSHELL: TREF of MID1 (MID2 if MID1 is blank); PCOMP/PCOMPG: the property's TREF
  /// True when a temperature loads the section (N_T or M_T not zero).
  bool thermal() const { return !NT.isZero(0.0) || !MT.isZero(0.0); }

  /// Transverse shear stiffness of an element whose longest edge squared is h2, stabilised (ibid.):
  /// S t_s^2 / (t_s^2 + alpha h^2), alpha = 0.1; it removes the residual shear locking of thin plates
  /// and vanishes under refinement (h -> 0).
  Eigen::Matrix2d stabilised_shear(double h2) const {
    constexpr double alpha = 0.1;
    return S * (ts2 / (ts2 + alpha * h2));
  }
  /// Mass per area (structural + non-structural), before WTMASS.
  double mass_per_area() const { return mass_per_area_value; }
  /// The section in axes rotated by -theta: for a section whose x axis is at angle theta (radians,
  /// about the normal) from the element's x axis, the same section in element axes.
  ShellSection in_element_axes(double theta) const {
    if (isotropic || theta == 0.0) return *this;
    ShellSection s = *this;
    s.A = rotate_plane_matrix(A, theta);
    s.B = rotate_plane_matrix(B, theta);
    s.D = rotate_plane_matrix(D, theta);
    s.S = rotate_shear_matrix(S, theta);
    // Resultants are work-conjugate to the strains: N_xy = T(theta)^T N_12 (material.hpp).
    const Eigen::Matrix3d Tt = strain_rotation(theta).transpose();
    s.NT = Tt * NT;
    s.MT = Tt * MT;
    return s;
  }
  /// The section about a reference surface e below its own (CQUAD4/CTRIA3 ZOFFS = e: the section's
  /// reference plane lies e above the grids, along the element normal): the strain at the section's
  /// plane is eps0 + e kappa, so A' = A, B' = B + e A, D' = D + 2 e B + e^2 A (the parallel-axis
  /// shift of lamination theory); S, mass and the stabilisation thickness are unchanged; the
  /// thermal moment about the new surface is M_T + e N_T.
  ShellSection offset(double e) const {
    if (e == 0.0) return *this;
    ShellSection s = *this;
    s.B = B + e * A;
    s.D = D + 2.0 * e * B + e * e * A;
    s.MT = MT + e * NT;
    return s;
  }
};

/// MAT1, MAT2, MAT8 as shell layers (ShellMaterial). MAT8: Q11 = E1/(1 - nu12 nu21), Q22 =
/// E2/(1 - nu12 nu21), Q12 = nu12 E2/(1 - nu12 nu21), Q33 = G12, nu21 = nu12 E2/E1 (Jones, ch. 2).
ShellMaterial shell_material(const Mat1& m);
ShellMaterial shell_material(const Mat2& m);
ShellMaterial shell_material(const Mat8& m);

/// PSHELL data with its materials resolved (nullptr = blank MID).
struct PshellInput {
  const ShellMaterial* mid1 = nullptr;  ///< membrane
  const ShellMaterial* mid2 = nullptr;  ///< bending
  const ShellMaterial* mid3 = nullptr;  ///< transverse shear (MAT1: G; MAT2: [G11 G12; G12 G22]; MAT8: diag(G1Z, G2Z))
  const ShellMaterial* mid4 = nullptr;  ///< membrane-bending coupling
  double t = 0, bend_ratio = 1.0, ts_t = 0.833333, nsm = 0;
};

/// The PSHELL section (MSC Nastran QRG PSHELL, remarks on the stiffness matrices):
///   A = T G1,  D = (12I/T^3) T^3/12 G2,  B = T^2 G4,  S = (TS/T) T G3,
/// Gi the plane-stress matrix of MIDi (MAT1: E/(1-nu^2) [1 nu 0; nu 1 0; 0 0 (1-nu)/2] with G33 = G;
/// MAT2: Gij; MAT8: the orthotropic Q). Mass per area rho1 T + NSM (rho2 if MID1 is blank).
/// Throws InputError (via the caller) never: the caller checks the references.
ShellSection pshell_section(const PshellInput& in);

/// One ply of a laminate: material, thickness, angle of its 1 axis from the laminate's x axis
/// (radians, about the normal).
struct Ply {
  ShellMaterial material;
  double t = 0;
  double theta = 0;
};

/// A laminate (PCOMP/PCOMPG) by classical lamination theory, plies listed bottom (most negative z)
/// up (Jones, Mechanics of Composite Materials, 2nd ed., ch. 4; Reddy, Mechanics of Laminated
/// Composite Plates and Shells, 2nd ed., ch. 3):
///   A = sum Qbar_k (z_k+1 - z_k),  B = sum Qbar_k (z_k+1^2 - z_k^2)/2,  D = sum Qbar_k (z_k+1^3 - z_k^3)/3,
/// z_1 = z0 (blank: -T/2), Qbar_k = T(theta_k)^T Q_k T(theta_k). Mass per area sum rho_k t_k + nsm.
/// Transverse shear: the laminate's shear compliance H = int F(z)^T C(z) F(z) dz, S = H^-1, where
/// C(z) is the ply's transverse shear compliance in laminate axes and F(z) (2 x 2) gives the
/// transverse shear stresses per unit shear force from equilibrium of the bending stresses,
///   tau_xz,z = -(sigma_x,x + tau_xy,y),  tau_yz,z = -(tau_xy,x + sigma_y,y),
/// of the two cylindrical bending states M_x,x = Q_x and M_y,y = Q_y (N = 0, mixed derivatives of the
/// moments neglected): Whitney, "Shear correction factors for orthotropic laminates under static
/// load", J. Appl. Mech. 40 (1973) 302-304, generalised to the coupled 2 x 2 case as in Rolfes &
/// Rohwer, IJNME 40 (1997) 51-60, and the FeResPost manual, sec. II.1.6.6 (energetic approach). A
/// homogeneous ply gives S = (5/6) G T; a sandwich G_core d^2 / t_core (d: distance between the face
/// mid-planes). Plies rigid in transverse shear (MAT8 G1Z/G2Z blank, MAT2) add no compliance; a
/// laminate without any gets the Kirchhoff penalty (ShellSection::S).
/// lam: Blank (full), Sym (plies mirrored about the top of the list), Mem (membrane only), Smear
/// (stacking ignored: A, D = A T^2/12, no coupling, rigid in shear), SmCore (last ply the core, the
/// others smeared into two face sheets of half their total thickness each side of it). Bend is not
/// supported (the caller refuses it).
ShellSection laminate_section(std::vector<Ply> plies, std::optional<double> z0, double nsm,
                              CompositeProperty::Lam lam = CompositeProperty::Lam::Blank);

/// The section of a CQUAD4/CTRIA3 of a finalized model, in the property's material axes (the element
/// rotates it by its THETA/MCID): its PSHELL (corner thicknesses averaged; TFLAG = 1 makes them
/// fractions of T) or its PCOMP/PCOMPG. Throws InputError for undefined references, a missing
/// thickness, a PSHELL with none of MID1/MID2, a MID4 without MID1 and MID2, a PCOMP with corner
/// thicknesses or LAM = BEND.
ShellSection make_shell_section(const Model& model, const Shell& shell);

}  // namespace seflex::fem
