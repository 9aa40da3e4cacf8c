// Geometric stiffening of the AIC superelement (mbd/src/bodies/aic_stiffening.cpp,
// docs/geometric-stiffening.md): the stiffened elastic tangent against central finite differences of
// the stiffened force, and the load factors of a rigidly spinning body against its kinematics.
// The stiffened force and its Hessian from the element's basis of the invariants against the
// formulas of docs/geometric-stiffening.md evaluated with the invariants as stored, for cases that
// depend on each other, vanish, or differ by 1e14 in size.
// The invariants here are random symmetric matrices: the tangent is that of the stiffened force
// whatever the G's are (their physics is tested in tests/reduction/stiffening_invariants_test.cpp and
// tests/mbd/spinup_stiffening_test.cpp).
#include <gtest/gtest.h>

#include <random>

#include "aic_test_util.hpp"
#include "beam_superelement.hpp"
#include "bodies/aic_inertia_detail.hpp"
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
  // Central differences of step 1e-7: round-off ~1e-9 of K (measured 2.7e-10).
  EXPECT_LT(err, 1e-8);
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

// Invariants of rank 7 (AicElement::G_basis, docs/geometric-stiffening.md "The rank of the
// invariants"): the 12 inertia cases combinations of 3 random matrices of size 1e-3 (one case zero),
// the 18 interface cases combinations of 4 of size 1e11, as a unit acceleration and a unit interface
// displacement differ. The element keeps 7 basis matrices, and the force, the potential and the
// Hessian of the stiffening equal the formulas evaluated with the 30 stored matrices.
TEST(Stiffening, RankDeficientInvariantsGiveTheFormulasOfTheStoredCases) {
  se::Superelement s = stiffened_lframe();
  const Eigen::Index n = s.size();
  const int N = s.num_interfaces(), nb = 6 * N;
  std::mt19937 rng(11);
  std::normal_distribution<double> nd;
  std::vector<MatrixXd> a, b;
  for (int i = 0; i < 3; ++i) a.push_back(random_symmetric(n, 1e-3, rng));
  for (int i = 0; i < 4; ++i) b.push_back(random_symmetric(n, 1e11, rng));
  for (int c = 0; c < 12; ++c) {
    s.stiffening.inertia[c] = MatrixXd::Zero(n, n);
    if (c != 5)
      for (const auto& A : a) s.stiffening.inertia[c] += nd(rng) * A;
  }
  for (int j = 0; j < nb; ++j) {
    s.stiffening.interface[j] = MatrixXd::Zero(n, n);
    for (const auto& B : b) s.stiffening.interface[j] += nd(rng) * B;
  }
  const AicElement e = make_aic_element(s);
  ASSERT_TRUE(e.has_stiffening());
  EXPECT_EQ(e.G_coef.rows(), 7);
  EXPECT_EQ(e.G_basis.cols(), 7 * n);
  std::vector<const MatrixXd*> G;
  for (const auto& Gc : s.stiffening.inertia) G.push_back(&Gc);
  for (const auto& Gj : s.stiffening.interface) G.push_back(&Gj);
  // A state in the frame condition's null space (as every xi of a run) with interface deformations
  // of 1e-5: the interface cases' terms are then of the order of the inertia cases'.
  const VectorXd xi = e.V_f * (e.V_f.transpose() * test::random_xi(e, 1e-5, rng));
  StiffeningLoads lambda;
  for (int c = 0; c < 12; ++c) lambda[c] = 10.0 * nd(rng);

  // The formulas with the stored matrices.
  VectorXd bq(nb), mu(12 + nb);
  for (int j = 0; j < nb; ++j) bq[j] = 0.5 * xi.dot(*G[static_cast<std::size_t>(12 + j)] * xi);
  const VectorXd sq = e.Kbb_pinv * bq;
  mu << lambda, xi.head(nb) + sq;
  MatrixXd sum = MatrixXd::Zero(n, n), Gb(n, nb);
  double V = xi.head(nb).dot(bq) + 0.5 * bq.dot(sq);
  for (int c = 0; c < 12 + nb; ++c) {
    sum += mu[c] * *G[static_cast<std::size_t>(c)];
    if (c < 12)
      V += 0.5 * lambda[c] * xi.dot(*G[static_cast<std::size_t>(c)] * xi);
    else
      Gb.col(c - 12) = *G[static_cast<std::size_t>(c)] * xi;
  }
  VectorXd g_ref = sum * xi;
  g_ref.head(nb) += bq;
  MatrixXd H_ref = sum + Gb * e.Kbb_pinv * Gb.transpose();
  H_ref.leftCols(nb) += Gb;
  H_ref.topRows(nb) += Gb.transpose();

  AicWorkspace ws;
  VectorXd g = VectorXd::Zero(n);
  const double Vg = detail::add_stress_stiffening(e, xi, lambda, g, ws);
  MatrixXd H = MatrixXd::Zero(n, n);
  detail::add_stress_stiffening_hessian(e, ws, H);
  const double eg = (g - g_ref).norm() / g_ref.norm(), eH = (H - H_ref).norm() / H_ref.norm();
  EXPECT_LT(eg, 1e-12);
  EXPECT_LT(std::abs(Vg - V), 1e-12 * std::abs(V));
  EXPECT_LT(eH, 1e-12);
  // The small inertia cases are kept to their own precision, not to that of the interface cases.
  const Eigen::Map<const MatrixXd> Gx = detail::stiffening_inertia_products(e, ws);
  for (int c = 0; c < 12; ++c) {
    const VectorXd Gc_xi = *G[static_cast<std::size_t>(c)] * xi;
    EXPECT_LE((Gx.col(c) - Gc_xi).norm(), 1e-12 * Gx.leftCols<12>().norm()) << "inertia case " << c;
  }
  EXPECT_EQ(Gx.col(5).norm(), 0.0);  // the zero case stays zero
  std::printf("rank %d of %d; force %.1e, Hessian %.1e from the formulas\n", static_cast<int>(e.G_coef.rows()), 12 + nb, eg,
              eH);
}

}  // namespace
