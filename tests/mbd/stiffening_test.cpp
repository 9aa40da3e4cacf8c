// Geometric stiffening of the AIC superelement (mbd/src/bodies/aic_stiffening.cpp,
// docs/geometric-stiffening.md): the stiffened elastic tangent against central finite differences of
// the stiffened force, and the load factors of a rigidly spinning body against its kinematics.
// The invariants here are random symmetric matrices: the tangent is that of the stiffened force
// whatever the G's are (their physics is tested in tests/reduction/stiffening_invariants_test.cpp and
// tests/mbd/spinup_stiffening_test.cpp).
#include <gtest/gtest.h>

#include <random>

#include "aic_test_util.hpp"
#include "beam_superelement.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/assembly/assembly.hpp"
#include "seflex/mbd/bodies/aic_element.hpp"
#include "seflex/mbd/model.hpp"

using namespace seflex;
using namespace seflex::mbd;
using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {

Eigen::MatrixXd random_symmetric(Eigen::Index n, double scale, std::mt19937& rng) {
  std::normal_distribution<double> nd;
  MatrixXd A(n, n);
  for (Eigen::Index i = 0; i < A.size(); ++i) A.data()[i] = nd(rng);
  return 0.5 * scale * (A + A.transpose());
}

/// The L-frame of aic_kernel_test.cpp (3 interfaces, 3 modes) with random stiffening invariants whose
/// terms are of the order of the elastic force at deformations of 1e-2.
se::Superelement stiffened_lframe() {
  auto fe = test::l_frame();
  se::Superelement s = test::craig_bampton(fe, {0, 8, 6}, 3, 3, "lframe");
  std::mt19937 rng(7);
  const double k = s.K.cwiseAbs().maxCoeff();
  s.stiffening.n = s.size();
  for (auto& G : s.stiffening.inertia) G = random_symmetric(s.size(), 0.05 * k, rng);
  for (int j = 0; j < 6 * s.num_interfaces(); ++j) s.stiffening.interface.push_back(random_symmetric(s.size(), 5.0 * k, rng));
  return s;
}

using test::Poses;
using test::poses_from;

VectorXd stiffened_force(const AicElement& e, const Poses& P, const VectorXd& eta, const FloatingFrame& warm,
                         const StiffeningLoads& lambda, MatrixXd* K = nullptr) {
  AicKinematics kin;
  recover_frame(e, P.R, P.p, eta, FrameRecovery::Newton6, warm, kin);
  AicWorkspace ws;
  VectorXd f;
  elastic_force_stiffened(e, kin, TangentModel::Exact, lambda, f, K, ws);
  return f;
}

TEST(Stiffening, TangentAgainstFiniteDifferences) {
  const se::Superelement s = stiffened_lframe();
  const AicElement e = make_aic_element(s);
  ASSERT_TRUE(e.has_stiffening());
  std::mt19937 rng(3);
  std::normal_distribution<double> nd;
  StiffeningLoads lambda;
  for (int c = 0; c < 12; ++c) lambda[c] = nd(rng);
  const Matrix3d Rk = so3::exp(Vector3d(0.3, -1.1, 0.7));
  const Vector3d rk(0.4, -0.2, 1.3);
  const VectorXd xi = test::random_xi(e, 1e-2, rng);
  const Poses P = poses_from(e, Rk, rk, xi);
  const VectorXd eta = xi.tail(e.m);
  const FloatingFrame warm{Rk, rk};
  MatrixXd K;
  const VectorXd f0 = stiffened_force(e, P, eta, warm, lambda, &K);
  // The stiffening really acts: the force differs from the linear elastic one by more than 10 %.
  AicKinematics kin;
  recover_frame(e, P.R, P.p, eta, FrameRecovery::Newton6, warm, kin);
  VectorXd f_lin;
  elastic_force(e, kin, TangentModel::Exact, f_lin, nullptr);
  EXPECT_GT((f0 - f_lin).norm(), 0.1 * f_lin.norm());
  const MatrixXd Kfd = test::fd_tangent(e, P, eta, [&](const Poses& Q, const VectorXd& et) {
    return stiffened_force(e, Q, et, warm, lambda);
  });
  const double err = (K - Kfd).norm() / Kfd.norm();
  EXPECT_LT(err, 1e-7);
  std::printf("stiffened tangent against central differences: %.2e\n", err);
}

// A body turning rigidly at Om (world) about the world origin: the frame origin's acceleration is
// centripetal, Om x (Om x p_WBo); the angular acceleration zero; w_s the components of Om_B~ Om_B~.
TEST(Stiffening, LoadFactorsOfARigidSpin) {
  const se::Superelement s = stiffened_lframe();
  const AicElement e = make_aic_element(s);
  const Matrix3d Rk = so3::exp(Vector3d(0.2, 0.5, -0.4));
  const Vector3d rk(1.5, -0.5, 0.3);
  const Vector3d Om(0.3, -1.2, 2.0);
  const Poses P = poses_from(e, Rk, rk, VectorXd::Zero(e.n));
  AicKinematics kin;
  recover_frame(e, P.R, P.p, VectorXd::Zero(e.m), FrameRecovery::Newton6, FloatingFrame{Rk, rk}, kin);
  VectorXd v = VectorXd::Zero(e.n), a = VectorXd::Zero(e.n);
  for (int j = 0; j < e.N; ++j) {
    v.segment<3>(6 * j) = Om.cross(P.p[j]);
    v.segment<3>(6 * j + 3) = Om;
    a.segment<3>(6 * j) = Om.cross(Om.cross(P.p[j]));
  }
  StiffeningLoads lambda;
  AicWorkspace ws;
  stiffening_load_factors(e, kin, v, a, lambda, ws);
  const Vector3d a_o = Rk.transpose() * Om.cross(Om.cross(kin.frame.p_WBo));
  const Vector3d Om_B = Rk.transpose() * Om;
  const Matrix3d W = so3::skew(Om_B) * so3::skew(Om_B);
  const double tol = 1e-12 * Om.squaredNorm() * (1.0 + rk.norm());
  EXPECT_LE((lambda.head<3>() - a_o).norm(), tol);
  EXPECT_LE(lambda.segment<3>(3).norm(), tol);
  Eigen::Matrix<double, 6, 1> w;
  w << W(0, 0), W(1, 1), W(2, 2), W(0, 1), W(0, 2), W(1, 2);
  EXPECT_LE((lambda.tail<6>() - w).norm(), tol);
}

// The assembled mass matrix is the acceleration derivative of the residual also with stiffening,
// whose first six load factors are the frame's accelerations (a rank-6, unsymmetric addition):
// the stiffened L-frame on free nodes, deformed and moving, against central differences in the
// accelerations (the residual is affine in them, so differences are exact to round-off).
TEST(Stiffening, MassMatrixIncludesTheLoadFactorsAccelerationDependence) {
  for (bool on : {false, true}) {  // without: the plain mass matrix, symmetric
    const se::Superelement s = stiffened_lframe();
    ModelBuilder mb;
    const auto sei = mb.add_superelement(s);
    std::vector<NodeIndex> nodes;
    for (int j = 0; j < s.num_interfaces(); ++j)
      nodes.push_back(mb.add_node("n" + std::to_string(j), Pose{Matrix3d::Identity(), s.p_OBo + s.interfaces[static_cast<std::size_t>(j)].p_BoN_B}));
    FlexibleBodyOptions fo;
    fo.inertia = InertiaModel::Full;
    fo.geometric_stiffening = on;
    mb.add_flexible_body("frame", sei, nodes, Pose{Matrix3d::Identity(), s.p_OBo}, fo);
    mb.set_gravity(Vector3d(0, -9.81, 1.0));
    const Model model = mb.build();
    State st = initial_state(model);
    std::mt19937 rng(3);
    std::normal_distribution<double> nd;
    VectorXd dx(model.num_dofs);
    for (int i = 0; i < model.num_dofs; ++i) dx[i] = nd(rng) * (model.dof_kind[static_cast<std::size_t>(i)] == 'e' ? 1e-2 : 1e-2);
    apply_increment(model, st, dx);
    for (int i = 0; i < model.num_dofs; ++i) {
      st.v[i] = nd(rng);
      st.vdot[i] = 10.0 * nd(rng);
    }
    auto residual = [&](const State& x) {
      Data d(model);
      assemble(model, x, d, AssemblyOptions{false, true, 1.0});
      return VectorXd(d.residual);
    };
    Data data(model);
    assemble(model, st, data, AssemblyOptions{});
    Eigen::SparseMatrix<double> S;
    combine_matrices(model, data, 0, 0, 1, nullptr, S);
    const MatrixXd M(S);
    MatrixXd Mfd(model.num_dofs, model.num_dofs);
    const double h = 1.0;  // affine in the accelerations: a large step only lowers the round-off
    for (int c = 0; c < model.num_dofs; ++c) {
      State sp = st, sm = st;
      sp.vdot[c] += h;
      sm.vdot[c] -= h;
      Mfd.col(c) = (residual(sp) - residual(sm)) / (2 * h);
    }
    const double err = (M - Mfd).norm() / Mfd.norm(), asym = (M - M.transpose()).norm() / M.norm();
    std::printf("%s: mass matrix against differences of the residual %.2e, its asymmetry %.2e\n", on ? "stiffened" : "linear", err, asym);
    EXPECT_LT(err, 1e-9);
    if (on) {
      EXPECT_GT(asym, 1e-6);  // the load factors' term is there
    }
  }
}

}  // namespace
