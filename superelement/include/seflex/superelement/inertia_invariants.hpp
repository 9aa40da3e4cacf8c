#pragma once
// Inertia invariants of a superelement (docs/inertia-invariants.md): mass-weighted integrals of the
// Craig-Bampton basis over the FE mesh, computed once at reduction, from which the full inertia of
// formulation.md 2.4-2.5 (force, quadratic-velocity terms, mass and gyroscopic tangents) follows at
// a cost set by the reduced size n alone. Plain data; computed by reduction/, stored by io/, used by
// mbd/ (the AIC superelement and the FFRF baseline).
//
// Notation (all in body axes B; FE nodes i = 1..n_fe, 6 dofs each, node-major):
//   P      = recovery (6 n_fe x n);  P_t,i / P_r,i its 3 translation / rotation rows of node i
//   M      = M_fe (6 n_fe square, symmetric; lumped or coupled)
//   X      = the FE-level field with X_i (undeformed position from the frame origin) on the
//            translation rows and zero on the rotation rows
//   E0     = rigid modes of the FE nodes at X (6 n_fe x 6): node i rows [I, -X_i~; 0, I]
//   L_s(y) = the field y with its translation rows multiplied by the symmetric 3x3 basis S_s,
//            s = 0..5 <-> (xx, yy, zz, xy, xz, yz); S_xy = e_x e_y^T + e_y e_x^T etc.
//   G_a(y) = the field y with translation rows (2 e_a x y_t) and rotation rows (e_a x y_r), a = 0..2
//   J_i    = the 3x3 rotary block of M at node i (gyroscopic term)
//   H_k(y) = sum_i P_t,i[:,k] x (M y)_t,i   (3 x cols(y)); E1(U)^T M y = [0; sum_k xi_k H_k(y)]
//            where E1(U) is the deformation part of the FE rigid modes at X + U, U = P xi.
// A tensor T with entries T[r, c, k] (r < R rows, c < C columns, k < n contracted with xi) is
// stored as a (R C) x n matrix with row r + R c and column k: (T xi) is then vec of an R x C matrix.
#include <Eigen/Core>
#include <array>

namespace seflex::se {

struct InertiaInvariants {
  int n = 0;  ///< reduced size the invariants belong to; 0 = absent

  // Mass: N^T M N with N = P T + (E0 + E1(P xi)) Z
  Eigen::MatrixXd Mpp;                  ///< n x n     P^T M P
  Eigen::MatrixXd PmE0;                 ///< n x 6     P^T M E0
  Eigen::Matrix<double, 6, 6> E0mE0 = Eigen::Matrix<double, 6, 6>::Zero();  ///< rigid-body mass about the frame origin
  Eigen::MatrixXd HP;                   ///< 3n x n    H_k(P)
  Eigen::MatrixXd HE0;                  ///< 18 x n    H_k(E0)
  Eigen::MatrixXd HE1;                  ///< 9n x n    H_k(E1_l)[r, c] at row r + 3c + 9l: second order in xi

  // Centrifugal field L_s(X + P xi)
  Eigen::MatrixXd PmLX;                 ///< n x 6     column s: P^T M L_s(X)
  Eigen::Matrix<double, 6, 6> E0mLX = Eigen::Matrix<double, 6, 6>::Zero();  ///< column s: E0^T M L_s(X)
  std::array<Eigen::MatrixXd, 6> PmLP;  ///< n x n     P^T M L_s(P)
  std::array<Eigen::MatrixXd, 6> E0mLP; ///< 6 x n     E0^T M L_s(P)
  Eigen::MatrixXd HLX;                  ///< 18 x n    H_k(L_s(X)) at row r + 3s
  std::array<Eigen::MatrixXd, 6> HLP;   ///< 3n x n    H_k(L_s(P))

  // Coriolis field G_a(P xi_dot)
  std::array<Eigen::MatrixXd, 3> PmGP;  ///< n x n     P^T M G_a(P)
  std::array<Eigen::MatrixXd, 3> E0mGP; ///< 6 x n     E0^T M G_a(P)
  std::array<Eigen::MatrixXd, 3> HGP;   ///< 3n x n    H_k(G_a(P))

  // Gyroscopic moments w_i x J_i w_i, w_i = Omega + P_r,i xi_dot (the term quadratic in xi_dot is
  // not kept: docs/inertia-invariants.md measures it)
  Eigen::MatrixXd PgOO;                 ///< n x 9     column a + 3b: sum_i P_r,i^T (e_a x J_i e_b)
  Eigen::Matrix<double, 3, 9> EgOO = Eigen::Matrix<double, 3, 9>::Zero();  ///< sum_i e_a x J_i e_b
  std::array<Eigen::MatrixXd, 3> PgOV;  ///< n x n     sum_i P_r,i^T (e_a~ J_i - (J_i e_a)~) P_r,i
  std::array<Eigen::MatrixXd, 3> EgOV;  ///< 3 x n     sum_i (e_a~ J_i - (J_i e_a)~) P_r,i

  // Not an inertia integral, but mesh data the time loop needs: the largest FE translation of each
  // fixed-interface mode per unit amplitude (m = n - 6N entries; scales the error estimate of eta).
  Eigen::VectorXd mode_max_translation;  ///< m [m]

  bool present() const { return n > 0; }
};

struct Superelement;

/// Compute the invariants of `body` from body.recovery, body.p_BoI_B and body.M_fe (any symmetric
/// FE mass: lumped, CONM2 with offsets, coupled). Cost O(n_fe n^2); memory a few recovery-sized
/// arrays. Throws InputError naming the body when the recovery matrix or the FE mass is missing.
InertiaInvariants compute_inertia_invariants(const Superelement& body);

}  // namespace seflex::se
