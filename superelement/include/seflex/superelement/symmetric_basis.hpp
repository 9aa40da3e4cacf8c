#pragma once
// The symmetric 3x3 basis S_s of the centrifugal field (inertia_invariants.hpp, stiffening_invariants.hpp):
// s = 0..5 <-> xx, yy, zz, xy, xz, yz, with S_xy = e_x e_y^T + e_y e_x^T etc., so that a symmetric
// W = sum_s w_s S_s has w = (W_xx, W_yy, W_zz, W_xy, W_xz, W_yz).
#include <Eigen/Core>

namespace seflex::se {

inline Eigen::Matrix3d sym_basis(int s) {
  static constexpr int pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
  S(pairs[s][0], pairs[s][1]) = 1.0;
  S(pairs[s][1], pairs[s][0]) = 1.0;
  return S;
}

/// The components w_s of a symmetric W = sum_s w_s S_s.
inline Eigen::Matrix<double, 6, 1> sym_components(const Eigen::Matrix3d& W) {
  Eigen::Matrix<double, 6, 1> v;
  v << W(0, 0), W(1, 1), W(2, 2), W(0, 1), W(0, 2), W(1, 2);
  return v;
}

}  // namespace seflex::se
