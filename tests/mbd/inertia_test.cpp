// T7 of formulation.md section 6.2: the full inertia force (section 2.4) against the exact
// generalised inertia force J^T M xdd of the FE nodes, computed with finite differences in time and
// space for a random large motion (|Omega| ~ 3 rad/s) of the 9-node L-frame with translational
// lumped masses (../shared/reference/aic_inertia_check.py: full 4e-5, N -> Psi 1.5e-3,
// simplified 0.96 at elastic amplitude 1e-3).
#include <gtest/gtest.h>

#include <random>

#include "beam_superelement.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/bodies/aic_element.hpp"

using namespace seflex;
using namespace seflex::mbd;
using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {

struct Motion {
  std::vector<Vector3d> r0, v, a, w, al;
  std::vector<Matrix3d> R0;
  void at(double t, std::vector<Matrix3d>& R, std::vector<Vector3d>& p) const {
    R.clear();
    p.clear();
    for (std::size_t j = 0; j < r0.size(); ++j) {
      p.push_back(r0[j] + v[j] * t + 0.5 * a[j] * t * t);
      R.push_back(so3::exp(w[j] * t + 0.5 * al[j] * t * t) * R0[j]);
    }
  }
};

// Positions of all FE nodes (translational dofs) for given interface poses.
VectorXd fe_positions(const AicElement& e, const std::vector<Matrix3d>& R, const std::vector<Vector3d>& p, const FloatingFrame& warm) {
  AicKinematics kin;
  recover_frame(e, R, p, VectorXd(), FrameRecovery::Newton6, warm, kin);
  const VectorXd U = e.Psi * kin.xi;
  const auto nfe = e.X.cols();
  VectorXd x(3 * nfe);
  for (Eigen::Index i = 0; i < nfe; ++i)
    x.segment<3>(3 * i) = kin.frame.p_WBo + kin.frame.R_WB * (e.X.col(i) + U.segment<3>(6 * i));
  return x;
}

}  // namespace

TEST(Inertia, T7_FullInertiaMatchesExactLagrangian) {
  auto fe = test::l_frame();
  fe.section.rho = 0.0;  // translational lumped masses only, as in the reference script
  for (int i = 0; i < fe.nodes(); ++i) fe.point_masses.push_back(1.0 + 0.3 * i);
  const se::Superelement s = test::craig_bampton(fe, {0, 8, 6}, 3, 0, "lframe");
  const AicElement e = make_aic_element(s);
  std::mt19937 rng(3);
  std::normal_distribution<double> nd;
  auto rvec = [&](double sc) -> Vector3d { return Vector3d(nd(rng), nd(rng), nd(rng)) * sc; };
  const Matrix3d Rk = so3::exp(rvec(1.0));
  const Vector3d rk = rvec(1.0);
  // Elastic state with Phi_f q = 0, amplitude 1e-3.
  VectorXd q = VectorXd::Zero(e.n);
  for (int i = 0; i < e.n; ++i) q[i] = 1e-3 * nd(rng);
  const MatrixXd P0 = rigid_modes(e, VectorXd::Zero(e.n));
  q -= P0 * (e.Phi_f * P0).lu().solve(e.Phi_f * q);
  Motion m;
  const Vector3d Om = rvec(3.0), V = rvec(1.0);
  for (int j = 0; j < e.N; ++j) {
    m.r0.push_back(rk + Rk * (e.x[j] + q.segment<3>(6 * j)));
    m.R0.push_back(Rk * so3::exp(q.segment<3>(6 * j + 3)));
    m.v.push_back(V + Om.cross(m.r0[j] - rk) + rvec(0.05));
    m.w.push_back(Om + rvec(0.05));
    m.a.push_back(rvec(1.0));
    m.al.push_back(rvec(1.0));
  }
  const FloatingFrame warm{Rk, rk};
  std::vector<Matrix3d> R;
  std::vector<Vector3d> p;
  // Accelerations of the FE nodes by central differences in time.
  const double ht = 1e-4;
  VectorXd xs[3];
  for (int k = 0; k < 3; ++k) {
    m.at((k - 1) * ht, R, p);
    xs[k] = fe_positions(e, R, p, warm);
  }
  const VectorXd xdd = (xs[0] - 2 * xs[1] + xs[2]) / (ht * ht);
  // Jacobian of the FE node positions w.r.t. [dr_j; dpi_j] by central differences.
  const auto nfe = e.X.cols();
  MatrixXd Jm(3 * nfe, e.n);
  const double hs = 1e-7;
  m.at(0.0, R, p);
  for (int c = 0; c < e.n; ++c) {
    VectorXd col[2];
    for (int sg = 0; sg < 2; ++sg) {
      auto R2 = R;
      auto p2 = p;
      const double d = sg == 0 ? hs : -hs;
      const int j = c / 6, k = c % 6;
      if (k < 3) p2[j][k] += d;
      else R2[j] = so3::exp(d * Vector3d::Unit(k - 3)) * R2[j];
      col[sg] = fe_positions(e, R2, p2, warm);
    }
    Jm.col(c) = (col[0] - col[1]) / (2 * hs);
  }
  VectorXd mdiag(3 * nfe);
  for (Eigen::Index i = 0; i < nfe; ++i) mdiag.segment<3>(3 * i).setConstant(1.0 + 0.3 * static_cast<double>(i));
  const VectorXd Q_exact = Jm.transpose() * mdiag.asDiagonal() * xdd;
  // seflex's inertia force at t = 0.
  AicKinematics kin;
  recover_frame(e, R, p, VectorXd(), FrameRecovery::Newton6, warm, kin);
  VectorXd v(e.n), a(e.n);
  for (int j = 0; j < e.N; ++j) {
    v.segment<3>(6 * j) = m.v[j];
    v.segment<3>(6 * j + 3) = m.w[j];
    a.segment<3>(6 * j) = m.a[j];
    a.segment<3>(6 * j + 3) = m.al[j];
  }
  InertiaResult full, simple;
  inertia_force(e, kin, InertiaModel::Full, v, a, false, full);
  inertia_force(e, kin, InertiaModel::Simplified, v, a, false, simple);
  const double err_full = (full.f - Q_exact).norm() / Q_exact.norm();
  const double err_simple = (simple.f - Q_exact).norm() / Q_exact.norm();
  std::printf("T7: full inertia %.2e, simplified %.2e (relative error against the exact Lagrangian)\n", err_full, err_simple);
  // formulation.md's T7 criterion is 1e-3 (prototype: 4e-5). Measured 9.0e-5: the error of the O(theta)
  // velocity map (deterministic: seeded state; the differences in time and space contribute ~1e-8).
  EXPECT_LT(err_full, 2e-4);
  EXPECT_GT(err_simple, 0.5);      // the simplified mass misses the quadratic-velocity terms (0.96)
  // Kinetic energy 1/2 v^T M0 v equals the FE nodes' 1/2 xdot^T M xdot up to the O(theta)
  // velocity-map approximation Lambda = I (elastic rotations ~1e-3 here).
  const VectorXd xdot = Jm * v;
  EXPECT_NEAR(full.kinetic, 0.5 * xdot.dot(mdiag.asDiagonal() * xdot), 1e-4 * full.kinetic);
}
