#pragma once
// Cross-section data of line and shell elements, resolved from the property cards (PBAR/PBEAM,
// PSHELL) and their materials.
#include <Eigen/Core>

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
  /// flexibility; seflex then uses 1000 x (5/6) G2 t, a Kirchhoff limit whose shear energy is
  /// negligible (the MITC shear interpolation does not lock, so the penalty is harmless).
  double shear_stiffness() const {
    if (has_shear) return shear.G * ts_t * t;
    if (has_bending) return 1000.0 * (5.0 / 6.0) * bending.G * t;
    return 0.0;
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
