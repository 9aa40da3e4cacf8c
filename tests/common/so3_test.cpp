// SO(3) helpers: exp/log round trip, the near-pi branch of log, the left Jacobian and its
// inverse against central finite differences, and the projection onto SO(3) (orthonormalize).
#include <gtest/gtest.h>

#include <random>

#include "seflex/common/so3.hpp"

using namespace seflex;

TEST(So3, ExpLogRoundTrip) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double scale : {1e-9, 1e-4, 0.3, 1.5, 3.0, 3.14159}) {
    for (int k = 0; k < 20; ++k) {
      Eigen::Vector3d axis(u(rng), u(rng), u(rng));
      axis.normalize();
      const Eigen::Vector3d th = scale * axis;
      const Eigen::Matrix3d R = so3::exp(th);
      EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), 1e-14);
      EXPECT_NEAR(R.determinant(), 1.0, 1e-14);
      EXPECT_LT((so3::log(R) - th).norm(), 1e-12 * std::max(1.0, scale)) << "scale " << scale;
    }
  }
}

TEST(So3, LeftJacobianMatchesFiniteDifferences) {
  const Eigen::Vector3d th(0.4, -1.1, 0.7);
  const double h = 1e-6;
  Eigen::Matrix3d J_fd;
  for (int c = 0; c < 3; ++c) {
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e[c] = h;
    // delta pi = vee(dR R^T): spatial increment caused by a change of theta
    const Eigen::Matrix3d dR = (so3::exp(th + e) - so3::exp(th - e)) / (2 * h);
    J_fd.col(c) = so3::vee(dR * so3::exp(th).transpose());
  }
  EXPECT_LT((so3::jl(th) - J_fd).norm(), 1e-9);
  EXPECT_LT((so3::jl_inv(th) * so3::jl(th) - Eigen::Matrix3d::Identity()).norm(), 1e-12);
}

// orthonormalize returns the orthogonal polar factor of R = Q (I + S), S symmetric, which is Q: on
// both of its branches (a near-rotation's Newton-Schulz step within 1e-8 of orthonormal, the SVD
// beyond: sizes 1e-7 and up), a rotation.
TEST(So3, OrthonormalizeReturnsThePolarFactor) {
  const Eigen::Matrix3d Q = so3::exp(Eigen::Vector3d(0.4, -1.1, 0.7));
  Eigen::Matrix3d S;
  S << 0.3, -0.2, 0.5, -0.2, 0.1, 0.4, 0.5, 0.4, -0.6;
  for (double size : {1e-12, 1e-9, 1e-7, 1e-5, 1e-2, 0.3}) {
    const Eigen::Matrix3d R = Q * (Eigen::Matrix3d::Identity() + size * S);
    const Eigen::Matrix3d P = so3::orthonormalize(R);
    EXPECT_LT((P.transpose() * P - Eigen::Matrix3d::Identity()).norm(), 1e-14) << "size " << size;
    EXPECT_NEAR(P.determinant(), 1.0, 1e-14) << "size " << size;
    EXPECT_LT((P - Q).norm(), 1e-14) << "size " << size;
  }
}
