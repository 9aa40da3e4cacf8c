#pragma once
// Linear-elastic materials as the elements use them: isotropic (MAT1) for bars, rods and shells;
// plane-stress layers (MAT1, MAT2, MAT8) for shells, with the rotations of their matrices.
#include <Eigen/Core>
#include <cmath>

namespace seflex::fem {

/// MAT1 after completion (E, G, nu all set; Nastran's rule G = E / (2 (1 + nu)) for a blank one).
struct IsotropicMaterial {
  int id = 0;
  double E = 0, G = 0, nu = 0, rho = 0;
};

/// Plane-stress constitutive matrix (3 x 3, Voigt order xx, yy, xy with engineering shear strain),
/// Nastran's convention for MAT1: G11 = G22 = E/(1-nu^2), G12 = nu E/(1-nu^2), G33 = G.
inline Eigen::Matrix3d plane_stress(const IsotropicMaterial& m) {
  const double c = m.E / (1.0 - m.nu * m.nu);
  Eigen::Matrix3d D;
  D << c, m.nu * c, 0.0, m.nu * c, c, 0.0, 0.0, 0.0, m.G;
  return D;
}

/// A MAT1, MAT2 or MAT8 as one layer of a shell uses it, in the material's own axes (1, 2, z).
///  - Q: plane-stress matrix (3 x 3, Voigt 11, 22, 12 with engineering shear strain).
///  - Gt: the transverse shear matrix of a PSHELL MID3 ((tau_1z, tau_2z) = Gt (gamma_1z, gamma_2z)):
///    MAT1 G I; MAT2 [G11 G12; G12 G22] (QRG MAT2); MAT8 diag(G1Z, G2Z). has_Gt false for a MAT8
///    with G1Z or G2Z blank.
///  - Ct: the transverse shear compliance of a laminate ply: MAT1 I/G; MAT8 diag(1/G1Z, 1/G2Z), a
///    blank modulus meaning infinite (QRG MAT8), so 0; MAT2 0 (rigid: a MAT2 gives no transverse
///    shear moduli).
///  - G_iso: the layer's in-plane shear modulus as one number, for the drilling stiffness and the
///    shear stabilisation of the elements: MAT1's G; for MAT2/MAT8 the average of Q33 over all
///    orientations of the layer, (Q11 + Q22 - 2 Q12 + 4 Q33) / 8 (the Tsai-Pagano invariant U5: Q33-bar
///    = U5 - U3 cos 4 theta; Jones, Mechanics of Composite Materials, 2nd ed., ch. 2), which is G for
///    an isotropic matrix.
///  - alpha: thermal expansion (Voigt 11, 22, 12 engineering) in the material axes: MAT1 (A, A, 0),
///    MAT2 (A1, A2, A3), MAT8 (A1, A2, 0); tref its reference temperature (TREF).
struct ShellMaterial {
  enum class Kind : unsigned char { Mat1, Mat2, Mat8 };
  int id = 0;
  Kind kind = Kind::Mat1;
  Eigen::Matrix3d Q = Eigen::Matrix3d::Zero();
  Eigen::Matrix2d Gt = Eigen::Matrix2d::Zero();
  bool has_Gt = false;
  Eigen::Matrix2d Ct = Eigen::Matrix2d::Zero();
  double G_iso = 0;
  double rho = 0;
  Eigen::Vector3d alpha = Eigen::Vector3d::Zero();
  double tref = 0;
  const char* card() const { return kind == Kind::Mat1 ? "MAT1" : kind == Kind::Mat2 ? "MAT2" : "MAT8"; }
};

/// U5 = (Q11 + Q22 - 2 Q12 + 4 Q33) / 8: the orientation average of Q33 (see ShellMaterial).
inline double orientation_average_shear(const Eigen::Matrix3d& Q) {
  return (Q(0, 0) + Q(1, 1) - 2.0 * Q(0, 1) + 4.0 * Q(2, 2)) / 8.0;
}

/// Strain transformation T(theta) (3 x 3) of a plane strain vector (xx, yy, xy engineering) from axes
/// (x, y) to axes (1, 2) whose 1 axis is at angle theta (radians) counterclockwise from x about z:
/// eps_12 = T eps_xy. A matrix C of the 1-2 axes is C_xy = T^T C T in the x-y axes (Jones, Mechanics of
/// Composite Materials, 2nd ed., ch. 2: Q-bar; the same holds for the curvatures).
inline Eigen::Matrix3d strain_rotation(double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix3d T;
  T << c * c, s * s, c * s,  //
      s * s, c * c, -c * s,  //
      -2 * c * s, 2 * c * s, c * c - s * s;
  return T;
}

/// A plane matrix (A, B, D, Q) of axes 1-2 at angle theta from x, expressed in x-y: T^T C T.
inline Eigen::Matrix3d rotate_plane_matrix(const Eigen::Matrix3d& C, double theta) {
  if (theta == 0.0) return C;
  const Eigen::Matrix3d T = strain_rotation(theta);
  const Eigen::Matrix3d R = T.transpose() * C * T;
  return 0.5 * (R + R.transpose());
}

/// A transverse shear matrix of axes 1-2 at angle theta from x, in x-y: (gamma_1z, gamma_2z) =
/// R (gamma_xz, gamma_yz), R = [c s; -s c]; S_xy = R^T S R.
inline Eigen::Matrix2d rotate_shear_matrix(const Eigen::Matrix2d& S, double theta) {
  if (theta == 0.0) return S;
  const double c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix2d R;
  R << c, s, -s, c;
  const Eigen::Matrix2d X = R.transpose() * S * R;
  return 0.5 * (X + X.transpose());
}

}  // namespace seflex::fem
