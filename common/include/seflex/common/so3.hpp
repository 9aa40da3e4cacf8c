#pragma once
// SO(3) helpers: skew matrix, exponential and logarithm maps (Rodrigues), the inverse left Jacobian.
// Conventions (formulation.md section 1.6): for a rotation vector theta, exp(skew(theta)) is the
// rotation about theta/|theta| by |theta| radians; log is its inverse on |theta| < pi.
// jl_inv(theta) maps a spatial rotation increment to the increment of theta:
//   delta theta = jl_inv(theta) * delta pi   for R = exp(theta), delta R = skew(delta pi) R.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace seflex::so3 {

inline Eigen::Matrix3d skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d S;
  S << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return S;
}

inline Eigen::Vector3d vee(const Eigen::Matrix3d& S) { return {S(2, 1), S(0, 2), S(1, 0)}; }

/// exp: rotation vector -> rotation matrix (Rodrigues, series near zero).
inline Eigen::Matrix3d exp(const Eigen::Vector3d& v) {
  const double t2 = v.squaredNorm();
  const Eigen::Matrix3d K = skew(v);
  double a, b;  // sin(t)/t, (1-cos t)/t^2
  if (t2 < 1e-12) {
    a = 1.0 - t2 / 6.0;
    b = 0.5 - t2 / 24.0;
  } else {
    const double t = std::sqrt(t2);
    a = std::sin(t) / t;
    b = (1.0 - std::cos(t)) / t2;
  }
  return Eigen::Matrix3d::Identity() + a * K + b * K * K;
}

/// log: rotation matrix -> rotation vector with |theta| <= pi. Accurate near 0 and near pi.
inline Eigen::Vector3d log(const Eigen::Matrix3d& R) {
  const double c = std::clamp((R.trace() - 1.0) * 0.5, -1.0, 1.0);
  const Eigen::Vector3d w = 0.5 * vee(R - R.transpose());  // sin(t) * axis
  const double s = w.norm();
  const double t = std::atan2(s, c);
  if (t < 1e-6) return (1.0 + t * t / 6.0) * w;
  if (t < 3.0) return (t / s) * w;
  // Near pi: axis from the symmetric part, R = c I + (1-c) a a^T + s [a]x
  const Eigen::Matrix3d B = (R + R.transpose()) * 0.5 - c * Eigen::Matrix3d::Identity();
  Eigen::Index k;
  B.diagonal().maxCoeff(&k);
  Eigen::Vector3d a = B.col(k) / std::sqrt(std::max(B(k, k) * (1.0 - c), 1e-300));
  a.normalize();
  if (a.dot(w) < 0.0) a = -a;
  return t * a;
}

/// Inverse of the left Jacobian of SO(3): J_l^{-1}(theta) (formulation.md section 1.6, Lambda_j).
inline Eigen::Matrix3d jl_inv(const Eigen::Vector3d& th) {
  const double t2 = th.squaredNorm();
  const Eigen::Matrix3d S = skew(th);
  double c;
  if (t2 < 1e-8) {
    c = 1.0 / 12.0 + t2 / 720.0;
  } else {
    const double t = std::sqrt(t2);
    c = 1.0 / t2 - (1.0 + std::cos(t)) / (2.0 * t * std::sin(t));
  }
  return Eigen::Matrix3d::Identity() - 0.5 * S + c * S * S;
}

/// Left Jacobian J_l(theta): delta pi = J_l(theta) delta theta.
inline Eigen::Matrix3d jl(const Eigen::Vector3d& th) {
  const double t2 = th.squaredNorm();
  const Eigen::Matrix3d S = skew(th);
  double a, b;  // (1-cos t)/t^2, (t - sin t)/t^3
  if (t2 < 1e-8) {
    a = 0.5 - t2 / 24.0;
    b = 1.0 / 6.0 - t2 / 120.0;
  } else {
    const double t = std::sqrt(t2);
    a = (1.0 - std::cos(t)) / t2;
    b = (t - std::sin(t)) / (t2 * t);
  }
  return Eigen::Matrix3d::Identity() + a * S + b * S * S;
}

/// Project a nearly orthogonal matrix back onto SO(3): the orthogonal factor of its polar
/// decomposition. A matrix within 1e-8 of orthonormal (a product of rotations, as the floating-frame
/// recovery's) takes one Newton-Schulz step, Q = R (3 I - R^T R) / 2: for R = Q (I + X), X symmetric,
/// it leaves 1.5 X^2, below round-off there; anything else takes the SVD. The SVD of every recovery was
/// 1.4 % of a Radau IIA-5 run of sync-3d (perf, 2026-12-07).
inline Eigen::Matrix3d orthonormalize(const Eigen::Matrix3d& R) {
  const Eigen::Matrix3d E = R.transpose() * R - Eigen::Matrix3d::Identity();
  if (E.cwiseAbs().maxCoeff() < 1e-8 && R.determinant() > 0.0) return R * (Eigen::Matrix3d::Identity() - 0.5 * E);
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d Q = svd.matrixU() * svd.matrixV().transpose();
  if (Q.determinant() < 0.0) {
    Eigen::Matrix3d U = svd.matrixU();
    U.col(2) *= -1.0;
    Q = U * svd.matrixV().transpose();
  }
  return Q;
}

}  // namespace seflex::so3
