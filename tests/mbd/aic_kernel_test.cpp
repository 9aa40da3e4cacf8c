// Kernel tests T1-T6 of formulation.md section 6.2 on the 9-node spatial L-frame of
// ../shared/reference/aic_verify.py (3 interfaces 0, 8, 6; frame node 3), and the same with
// internal modes (section 2.5). References: exact identities of the Craig-Bampton reduction and
// central finite differences of the implemented force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "aic_test_util.hpp"
#include "beam_superelement.hpp"
#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/bodies/aic_element.hpp"

using namespace seflex;
using namespace seflex::mbd;
using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {

using test::Poses;
using test::poses_from;
using test::random_xi;

struct Fixture {
  se::Superelement s;
  AicElement e;
  explicit Fixture(int modes) {
    auto fe = test::l_frame();
    s = test::craig_bampton(fe, {0, 8, 6}, 3, modes, "lframe");
    e = make_aic_element(s);
  }
};

VectorXd force(const AicElement& e, const Poses& P, const VectorXd& eta, const FloatingFrame& warm, TangentModel t,
               MatrixXd* K = nullptr) {
  AicKinematics kin;
  recover_frame(e, P.R, P.p, eta, FrameRecovery::Newton6, warm, kin);
  VectorXd f;
  elastic_force(e, kin, t, f, K);
  return f;
}

// Central finite-difference tangent of the exact elastic force.
MatrixXd fd_tangent(const AicElement& e, const Poses& P, const VectorXd& eta, const FloatingFrame& warm) {
  return test::fd_tangent(e, P, eta, [&](const Poses& Q, const VectorXd& et) { return force(e, Q, et, warm, TangentModel::Exact); });
}

}  // namespace

// T1: Psi Phi_rig0 = Phi_rig^FE; Phi_f Phi_rig0 = I; K Phi_rig0 = 0; the block sums of section 1.3.
TEST(AicKernel, T1_CraigBamptonIdentities) {
  Fixture F(0);
  const AicElement& e = F.e;
  const MatrixXd P0 = rigid_modes(e, VectorXd::Zero(e.n));
  auto fe = test::l_frame();
  test::assemble(fe);
  const MatrixXd PFE = test::fe_rigid_modes(fe, fe.pts[3]);
  EXPECT_LT((F.s.recovery * P0 - PFE).norm() / PFE.norm(), 1e-10);
  EXPECT_LT((e.Phi_f * P0 - MatrixXd::Identity(6, 6)).norm(), 1e-10);
  EXPECT_LT((e.K * P0).norm() / e.K.norm(), 1e-10);
  Matrix3d Suu = Matrix3d::Zero(), Sthu = Matrix3d::Zero(), Sut = Matrix3d::Zero(), Stt = Matrix3d::Zero();
  for (int j = 0; j < e.N; ++j) {
    const MatrixXd A = e.Phi_f.middleCols(6 * j, 6);
    const Matrix3d xs = so3::skew(e.x[j]);
    Suu += A.block<3, 3>(0, 0);
    Sthu += A.block<3, 3>(3, 0);
    Sut += A.block<3, 3>(0, 3) - A.block<3, 3>(0, 0) * xs;
    Stt += A.block<3, 3>(3, 3) - A.block<3, 3>(3, 0) * xs;
  }
  EXPECT_LT((Suu - Matrix3d::Identity()).norm(), 1e-10);
  EXPECT_LT(Sthu.norm(), 1e-10);
  EXPECT_LT(Sut.norm(), 1e-10);
  EXPECT_LT((Stt - Matrix3d::Identity()).norm(), 1e-10);
  // Mass properties implied by M equal those of the FE model.
  EXPECT_NEAR(e.mass, F.s.mass, 1e-12 * F.s.mass);
  EXPECT_LT((e.p_BoCm_B - F.s.p_BoCm_B).norm(), 1e-12);
  EXPECT_LT((e.I_Cm_B - F.s.I_Cm_B).norm(), 1e-10 * F.s.I_Cm_B.norm());
}

// Error bounds of a recovered frame (T2), from what recover_frame guarantees. It stops when its
// Newton step is below 1e-9 (|dp|/scale + |dtheta|); its Newton matrix is exact, so one more step
// would leave ~1e-18 and what remains is rounding, and for Decoupled3 the reduction's own defect:
// - Rounding: every local coordinate is formed by about ten floating-point operations on positions
//   no longer than `scale` (poses_from, then R^T (p_WI - p) - x_j, and the exp/log of rotations), so
//   its error is below c eps scale with c = 16 (a generous count): |d xi| <= delta = 16 eps scale sqrt(n).
// - The frame solves Phi_f xi(z) = 0, z = [dp_B; dtheta]. To first order a change d xi of the local
//   coordinates moves it by dz = A^-1 Phi_f d xi, A = sum_j Phi_f,j B_j with
//   B_j = [I, -skew(x_j + u_j); 0, jl_inv(theta_j)] (the Newton matrix at the solution), and the
//   recomputed local coordinates by d xi - B dz.
// - Decoupled3 forms the frame condition from the world positions R^T p_WI instead of R^T (p_WI - p):
//   it is exact only if Phi_f maps a rigid translation to itself. The reduced basis does so up to its
//   defect D = Phi_f Phi_rig0 - I (round-off of the reduction, T1 bounds it by 1e-10), so Decoupled3
//   solves Phi_f xi = -D_t R^T p_WBo (D_t: the 3 translation columns), which moves the frame by up
//   to |A^-1| |D_t| |p_WBo| more: a body far from the world origin is recovered less exactly (checked
//   on this L-frame, |D_t| = 4.4e-13: Decoupled3's R error is 5e-16, 7.7e-13 and 7.7e-11 for |r_k| = 0,
//   2.24 and 224 m with gcc -O3, Newton6's 5e-16 to 8e-15).
// Hence |dz| <= |A^-1 Phi_f| delta (+ |A^-1| |D_t| |p_WBo|), |R - R_k|_F <= sqrt(2) |dz|,
// |p - r_k| <= |dz|, |xi - xi_k| <= delta + |B| |dz| (Frobenius norms, which bound the 2-norms).
// On the L-frame the bounds are 1.5e-13..1.5e-11. Errors seen (R, p, xi; modes 0): Newton6 6e-16,
// 2e-16, 9e-16 (gcc -O3) and 7e-16, 4e-16, 9e-16 (clang -O0 ASan); Decoupled3 7.7e-13, 1.5e-13,
// 9.7e-13 (gcc) and 1.05e-12, 2.0e-13, 1.32e-12 (clang) against bounds 3.6e-12, 2.5e-12, 1.2e-11:
// the fixed 1e-12 this test had was below Decoupled3's defect term and failed with clang. A recovery
// that stopped one Newton step early would be off by ~1e-9, above the 1e-10 the bounds must stay under.
namespace {

struct RecoveryBounds {
  double R, p, xi;
};

RecoveryBounds recovery_bounds(const AicElement& e, const Poses& P, const Vector3d& rk, FrameRecovery method,
                               const AicKinematics& kin) {
  double scale = std::max(e.length, rk.norm());
  for (int j = 0; j < e.N; ++j) scale = std::max({scale, P.p[j].norm(), rk.norm() + e.x[j].norm()});
  const double delta = 16 * std::numeric_limits<double>::epsilon() * scale * std::sqrt(double(e.n));
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  MatrixXd B = MatrixXd::Zero(6 * e.N, 6);
  for (int j = 0; j < e.N; ++j) {
    B.block<3, 3>(6 * j, 0).setIdentity();
    B.block<3, 3>(6 * j, 3) = -so3::skew(e.x[j] + kin.xi.segment<3>(6 * j));
    B.block<3, 3>(6 * j + 3, 3) = so3::jl_inv(kin.xi.segment<3>(6 * j + 3));
    A += e.Phi_f.middleCols(6 * j, 6) * B.middleRows(6 * j, 6);
  }
  const Eigen::Matrix<double, 6, 6> A_inv = A.inverse();
  double dz = (A_inv * e.Phi_f).norm() * delta;
  if (method == FrameRecovery::Decoupled3) {
    const MatrixXd D = e.Phi_f.leftCols(6 * e.N) * rigid_modes(e, VectorXd::Zero(e.n)) - MatrixXd::Identity(6, 6);
    dz += A_inv.norm() * D.leftCols(3).norm() * kin.frame.p_WBo.norm();
  }
  return {std::sqrt(2.0) * dz, dz, delta + B.norm() * dz};
}

}  // namespace

// T2: recover a random frame (rotation ~1.5 rad) from interface poses with both algorithms,
// starting from interface node 0; pose error within round-off (recovery_bounds) in <= 5 iterations.
// With internal modes too.
TEST(AicKernel, T2_FrameRecovery) {
  for (int modes : {0, 3}) {
    Fixture F(modes);
    const AicElement& e = F.e;
    std::mt19937 rng(1);
    std::normal_distribution<double> nd;
    const Matrix3d Rk = so3::exp(1.5 * Vector3d(nd(rng), nd(rng), nd(rng)).normalized());
    const Vector3d rk(nd(rng), nd(rng), nd(rng));
    const VectorXd xi = random_xi(e, 1e-2, rng);
    const Poses P = poses_from(e, Rk, rk, xi);
    const VectorXd eta = xi.tail(e.m);
    for (auto method : {FrameRecovery::Newton6, FrameRecovery::Decoupled3}) {
      AicKinematics kin;
      recover_frame(e, P.R, P.p, eta, method, frame_guess(e, P.R[0], P.p[0]), kin);
      const RecoveryBounds tol = recovery_bounds(e, P, rk, method, kin);
      // The bounds stay at round-off, far below what one Newton step short of convergence leaves.
      EXPECT_LT(std::max({tol.R, tol.p, tol.xi}), 1e-10) << "modes " << modes;
      EXPECT_LT((kin.frame.R_WB - Rk).norm(), tol.R) << "modes " << modes;
      EXPECT_LT((kin.frame.p_WBo - rk).norm(), tol.p) << "modes " << modes;
      EXPECT_LT((kin.xi - xi).norm(), tol.xi) << "modes " << modes;
      EXPECT_LE(kin.iterations, 5);
    }
  }
}

// T3: an arbitrary rigid motion of all interfaces leaves xi unchanged and rotates the elastic
// force with it; a rigidly placed undeformed body has zero elastic force.
TEST(AicKernel, T3_RigidInvariance) {
  Fixture F(2);
  const AicElement& e = F.e;
  std::mt19937 rng(2);
  const VectorXd xi = random_xi(e, 1e-3, rng);
  const Matrix3d Rk = so3::exp(Vector3d(0.3, -0.2, 0.5));
  const Vector3d rk(0.1, 0.2, -0.3);
  const Poses P = poses_from(e, Rk, rk, xi);
  const VectorXd eta = xi.tail(e.m);
  AicKinematics k1, k2;
  recover_frame(e, P.R, P.p, eta, FrameRecovery::Newton6, frame_guess(e, P.R[0], P.p[0]), k1);
  const Matrix3d Q = so3::exp(Vector3d(-1.2, 2.0, 0.7));
  const Vector3d d(3.0, -1.0, 2.0);
  Poses P2 = P;
  for (int j = 0; j < e.N; ++j) {
    P2.p[j] = Q * P.p[j] + d;
    P2.R[j] = Q * P.R[j];
  }
  recover_frame(e, P2.R, P2.p, eta, FrameRecovery::Newton6, frame_guess(e, P2.R[0], P2.p[0]), k2);
  EXPECT_LT((k1.xi - k2.xi).norm(), 1e-12);
  VectorXd f1, f2;
  elastic_force(e, k1, TangentModel::Exact, f1, nullptr);
  elastic_force(e, k2, TangentModel::Exact, f2, nullptr);
  VectorXd f1r = f1;
  for (int i = 0; i < 2 * e.N; ++i) f1r.segment<3>(3 * i) = Q * f1.segment<3>(3 * i);
  EXPECT_LT((f1r - f2).norm(), 1e-10 * f1.norm());
  const Poses P0 = poses_from(e, Q * Rk, d, VectorXd::Zero(e.n));
  AicKinematics k0;
  recover_frame(e, P0.R, P0.p, VectorXd::Zero(e.m), FrameRecovery::Newton6, frame_guess(e, P0.R[0], P0.p[0]), k0);
  VectorXd f0;
  elastic_force(e, k0, TangentModel::Exact, f0, nullptr);
  EXPECT_LT(f0.norm(), 1e-12 * f1.norm() / 1e-3);
}

// T4: the elastic forces are self-equilibrated about the deformed configuration.
TEST(AicKernel, T4_SelfEquilibrium) {
  Fixture F(0);
  const AicElement& e = F.e;
  std::mt19937 rng(3);
  const VectorXd xi = random_xi(e, 1e-2, rng);
  const Poses P = poses_from(e, so3::exp(Vector3d(0.4, 1.0, -0.6)), Vector3d(1, 2, 3), xi);
  AicKinematics kin;
  recover_frame(e, P.R, P.p, VectorXd(), FrameRecovery::Newton6, frame_guess(e, P.R[0], P.p[0]), kin);
  const VectorXd fw = transfer_matrix(e, kin).transpose() * e.K * kin.xi;
  EXPECT_LT((kin.Phi_rig.transpose() * fw).norm(), 1e-10 * (e.K * kin.xi).norm());
}

// Tx applied in O(6n) (the time loop never forms it) equals the formed matrix, and its transpose.
TEST(AicKernel, TransferAppliedEqualsFormed) {
  Fixture F(0);
  const AicElement& e = F.e;
  std::mt19937 rng(5);
  const VectorXd xi = random_xi(e, 1e-2, rng);
  const Poses P = poses_from(e, so3::exp(Vector3d(-0.3, 0.7, 0.2)), Vector3d(0.5, -1, 2), xi);
  AicKinematics kin;
  recover_frame(e, P.R, P.p, VectorXd(), FrameRecovery::Newton6, frame_guess(e, P.R[0], P.p[0]), kin);
  const Eigen::MatrixXd T = transfer_matrix(e, kin);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VectorXd x(e.n), y;
  for (int i = 0; i < e.n; ++i) x[i] = u(rng);
  apply_transfer(e, kin, x, y);
  EXPECT_LT((y - T * x).norm(), 1e-14 * (T * x).norm() + 1e-15);
  apply_transfer_transpose(e, kin, x, y);
  EXPECT_LT((y - T.transpose() * x).norm(), 1e-14 * (T.transpose() * x).norm() + 1e-15);
  // Tx removes the rigid motion: Zx Tx = 0 (Zx R6 = I).
  EXPECT_LT((kin.Zx * T).norm(), 1e-12 * kin.Zx.norm());
}

// T5: the exact tangent against central finite differences (<= 1e-8), and the simplified tangent's
// error growing like |q|^2 (formulation section 3: 9e-7 at 1e-3 and 8e-5 at 1e-2).
TEST(AicKernel, T5_TangentAgainstFiniteDifferences) {
  for (int modes : {0, 3}) {
    Fixture F(modes);
    const AicElement& e = F.e;
    double err_simple[2];
    int k = 0;
    for (double amp : {1e-3, 1e-2}) {
      std::mt19937 rng(1);
      std::normal_distribution<double> nd;
      const Matrix3d Rk = so3::exp(1.5 * Vector3d(nd(rng), nd(rng), nd(rng)).normalized());
      const Vector3d rk(nd(rng), nd(rng), nd(rng));
      const VectorXd xi = random_xi(e, amp, rng);
      const Poses P = poses_from(e, Rk, rk, xi);
      const VectorXd eta = xi.tail(e.m);
      const FloatingFrame warm{Rk, rk};
      MatrixXd Kex, Ksi;
      force(e, P, eta, warm, TangentModel::Exact, &Kex);
      force(e, P, eta, warm, TangentModel::Simplified, &Ksi);
      const MatrixXd Kfd = fd_tangent(e, P, eta, warm);
      const double err_exact = (Kex - Kfd).norm() / Kfd.norm();
      err_simple[k++] = (Ksi - Kfd).norm() / Kfd.norm();
      // Differences of step 1e-7 (test::fd_tangent): round-off ~eps |f| / h ~ 1e-9 of K, truncation
      // ~h^2 (measured 1.5e-9..1.8e-9); the simplified tangent's error, a missing term, is >= 1e-6.
      EXPECT_LT(err_exact, 1e-8) << "modes " << modes << " amplitude " << amp;
    }
    const double ratio = err_simple[1] / err_simple[0];
    EXPECT_GT(ratio, 30.0) << "modes " << modes;   // |q|^2 growth: 100 per decade
    EXPECT_LT(ratio, 300.0) << "modes " << modes;
    if (modes == 0) {
      EXPECT_LT(err_simple[0], 1e-5);  // formulation.md: 9e-7
    }
    std::printf("T5 modes %d: simplified tangent error %.2e at |q| 1e-3, %.2e at 1e-2\n", modes, err_simple[0], err_simple[1]);
  }
}

// T6: B^T M_k(0) B = M_el with B = [Z; T] at the undeformed state.
TEST(AicKernel, T6_SimplifiedMassIsExactAtZeroDeformation) {
  auto fe = test::l_frame();
  const se::Superelement s = test::craig_bampton(fe, {0, 8, 6}, 3, 0);
  const AicElement e = make_aic_element(s);
  const MatrixXd P0 = rigid_modes(e, VectorXd::Zero(e.n));
  const MatrixXd Z = (e.Phi_f * P0).lu().solve(e.Phi_f);
  const MatrixXd T = MatrixXd::Identity(e.n, e.n) - P0 * Z;
  const MatrixXd PFE = test::fe_rigid_modes(fe, fe.pts[3]);
  const MatrixXd& Psi = s.recovery;
  MatrixXd Mk(6 + e.n, 6 + e.n);
  Mk << PFE.transpose() * fe.M * PFE, PFE.transpose() * fe.M * Psi, Psi.transpose() * fe.M * PFE, e.M;
  MatrixXd B(6 + e.n, e.n);
  B << Z, T;
  EXPECT_LT((B.transpose() * Mk * B - e.M).norm() / e.M.norm(), 1e-12);
}

// Bad input: a superelement whose frame rows do not reproduce rigid motion is rejected by name.
TEST(AicKernel, RejectsOrthonormalisedBasis) {
  auto fe = test::l_frame();
  se::Superelement s = test::craig_bampton(fe, {0, 8, 6}, 3, 0, "bad");
  s.Phi_f *= 1.1;
  try {
    make_aic_element(s);
    FAIL() << "expected InputError";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("superelement 'bad'"), std::string::npos);
    EXPECT_NE(std::string(err.what()).find("rigid motion"), std::string::npos);
  }
}
