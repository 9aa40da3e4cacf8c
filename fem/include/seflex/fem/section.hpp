#pragma once
// Cross-section data of line and shell elements, resolved from the property cards (PBAR/PBEAM,
// PSHELL) and their materials.
#include <Eigen/Core>
#include <cmath>

#include "seflex/fem/material.hpp"

namespace seflex::fem {

/// Bar/beam section in element axes (Nastran PBAR conventions).
/// I1 = int y^2 dA (bending in plane 1, the element x-y plane), I2 = int z^2 dA, I12 = int y z dA.
/// K1, K2: shear area factors (shear area K1 A in plane 1, K2 A in plane 2); 0 = blank = no
/// transverse shear flexibility (Euler-Bernoulli). nsm: non-structural mass per length.
struct BarSection {
  double A = 0, I1 = 0, I2 = 0, I12 = 0, J = 0, K1 = 0, K2 = 0, nsm = 0;
};

/// PSHELL resolved: membrane (MID1, thickness t), bending (MID2, 12I/T^3), transverse shear
/// (MID3, TS/T), non-structural mass per area.
struct ShellSection {
  double t = 0;                          ///< membrane thickness
  bool has_membrane = false, has_bending = false, has_shear = false;
  IsotropicMaterial membrane, bending, shear;  ///< MID1, MID2, MID3 (valid when has_*)
  double bend_ratio = 1.0;               ///< 12 I / T^3
  double ts_t = 0.833333;                ///< TS / T
  double nsm = 0;                        ///< non-structural mass per area
  double rho = 0;                        ///< structural density (MID1's, else MID2's)

  /// Membrane stiffness A = t * D_plane_stress(MID1) (3 x 3, force per length per strain).
  Eigen::Matrix3d membrane_matrix() const {
    return has_membrane ? Eigen::Matrix3d(t * plane_stress(membrane)) : Eigen::Matrix3d::Zero();
  }
  /// Bending stiffness D = (12I/T^3) t^3/12 * D_plane_stress(MID2) (moment per length per curvature).
  Eigen::Matrix3d bending_matrix() const {
    return has_bending ? Eigen::Matrix3d(bend_ratio * t * t * t / 12.0 * plane_stress(bending))
                       : Eigen::Matrix3d::Zero();
  }
  /// Transverse shear stiffness per length G3 * TS. Nastran: MID3 blank means no transverse shear
  /// flexibility; seflex then uses 1000 x (5/6) G2 t_b (t_b = (12 I)^(1/3), the thickness of the
  /// homogeneous plate with the section's bending stiffness), a Kirchhoff limit whose shear energy is
  /// negligible (the MITC shear interpolation does not lock, so the penalty is harmless).
  double shear_stiffness() const {
    if (has_shear) return shear.G * ts_t * t;
    if (has_bending) return 1000.0 * physical_shear_stiffness();
    return 0.0;
  }
  /// The shear stiffness that defines the section's bending-to-shear ratio: G3 TS, or with MID3
  /// blank that of the homogeneous plate of the same bending stiffness, (5/6) G2 t_b.
  double physical_shear_stiffness() const {
    if (has_shear) return shear.G * ts_t * t;
    return has_bending ? (5.0 / 6.0) * bending.G * std::cbrt(bend_ratio) * t : 0.0;
  }
  /// Squared thickness of the homogeneous (5/6 shear factor) plate whose bending-to-shear stiffness
  /// ratio the section has: t_s^2 = (5/6) G2 (12 I) / S, S = physical_shear_stiffness(). For a
  /// homogeneous PSHELL (12I/T^3 = 1, MID3 = MID2, TS/T = 5/6) it is T^2; for a sandwich (12I/T^3 =
  /// 11200, TS/T = 19.13) about (22 T)^2, where T, the face-sheet thickness, would be 22x too thin.
  /// The shear stabilisation of the MITC elements is written in this thickness (Lyly, Stenberg &
  /// Vihinen, Comput. Mech. 13 (1993) 371-387, state the plate in the scaled form in which t^2 is
  /// exactly this ratio).
  double shear_thickness_squared() const {
    const double S = physical_shear_stiffness();
    if (!has_bending || !(S > 0.0)) return t * t;
    return (5.0 / 6.0) * bending.G * bend_ratio * t * t * t / S;
  }
  /// Transverse shear stiffness of an element whose longest edge squared is h2, stabilised (ibid.):
  /// shear_stiffness() t_s^2 / (t_s^2 + alpha h^2), alpha = 0.1; it removes the residual shear
  /// locking of thin plates and vanishes under refinement (h -> 0).
  double stabilised_shear_stiffness(double h2) const {
    constexpr double alpha = 0.1;
    const double ts2 = shear_thickness_squared();
    return shear_stiffness() * ts2 / (ts2 + alpha * h2);
  }
  /// Mass per area (structural + non-structural), before WTMASS.
  double mass_per_area() const { return rho * t + nsm; }
};

}  // namespace seflex::fem

namespace seflex::fem {
struct Model;
struct Shell;
/// PSHELL of a CQUAD4/CTRIA3 with its materials and the element's corner thicknesses (averaged;
/// TFLAG = 1 makes them fractions of T). Throws InputError for undefined references, a missing
/// thickness, or a PSHELL with none of MID1/MID2.
ShellSection make_shell_section(const Model& model, const Shell& shell);
}  // namespace seflex::fem
