#pragma once
// Helpers of the AIC kernel tests (aic_kernel_test.cpp, stiffening_test.cpp): interface poses of a body
// with given local coordinates, random local coordinates that satisfy the frame condition, and the
// central finite-difference tangent of a body force w.r.t. [dr_j; dpi_j (spatial); deta].
#include <Eigen/Dense>
#include <functional>
#include <random>
#include <vector>

#include "seflex/common/so3.hpp"
#include "seflex/mbd/bodies/aic_element.hpp"

namespace seflex::test {

struct Poses {
  std::vector<Eigen::Matrix3d> R;
  std::vector<Eigen::Vector3d> p;
};

/// Interface poses of a body whose frame is (R_k, r_k) with local coordinates xi (Phi_f xi = 0).
inline Poses poses_from(const mbd::AicElement& e, const Eigen::Matrix3d& Rk, const Eigen::Vector3d& rk,
                        const Eigen::VectorXd& xi) {
  Poses P;
  for (int j = 0; j < e.N; ++j) {
    P.p.push_back(rk + Rk * (e.x[j] + xi.segment<3>(6 * j)));
    P.R.push_back(Rk * so3::exp(xi.segment<3>(6 * j + 3)) * e.C[j]);
  }
  return P;
}

/// Random xi of amplitude amp satisfying the frame condition Phi_f xi = 0.
inline Eigen::VectorXd random_xi(const mbd::AicElement& e, double amp, std::mt19937& rng) {
  std::normal_distribution<double> nd;
  Eigen::VectorXd xi(e.n);
  for (int i = 0; i < e.n; ++i) xi[i] = amp * nd(rng);
  const Eigen::MatrixXd P0 = mbd::rigid_modes(e, Eigen::VectorXd::Zero(e.n));
  const Eigen::Matrix<double, 6, 1> c = (e.Phi_f.leftCols(6 * e.N) * P0).lu().solve(e.Phi_f * xi);
  xi.head(6 * e.N) -= P0 * c;
  return xi;
}

/// Central finite-difference tangent (step 1e-7) of force(poses, eta) w.r.t. [dr_j; dpi_j (spatial); deta].
inline Eigen::MatrixXd fd_tangent(const mbd::AicElement& e, const Poses& P, const Eigen::VectorXd& eta,
                                  const std::function<Eigen::VectorXd(const Poses&, const Eigen::VectorXd&)>& force) {
  const double h = 1e-7;
  Eigen::MatrixXd Kfd(e.n, e.n);
  for (int c = 0; c < e.n; ++c) {
    Eigen::VectorXd col[2];
    for (int sgn = 0; sgn < 2; ++sgn) {
      const double s = sgn == 0 ? h : -h;
      Poses Q = P;
      Eigen::VectorXd et = eta;
      if (c < 6 * e.N) {
        const int j = c / 6, k = c % 6;
        if (k < 3) Q.p[j][k] += s;
        else Q.R[j] = so3::exp(s * Eigen::Vector3d::Unit(k - 3)) * Q.R[j];
      } else {
        et[c - 6 * e.N] += s;
      }
      col[sgn] = force(Q, et);
    }
    Kfd.col(c) = (col[0] - col[1]) / (2 * h);
  }
  return Kfd;
}

}  // namespace seflex::test
