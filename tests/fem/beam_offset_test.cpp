// CBEAM neutral-axis (PBEAM N1/N2) and non-structural-mass (M1/M2) offsets from the shear centre:
// closed forms of an eccentric cantilever, the rigid-link equivalent, the thermal strain of the
// reference axis, and the rigid-body mass of offset line masses.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "fem_test_util.hpp"
#include "seflex/fem/element_bar.hpp"

namespace seflex::fem {
namespace {

constexpr double kL = 2.0, kE = 2e11, kG = 8e10, kA = 1e-2, kI1 = 4e-5, kI2 = 2e-5, kJ = 3e-5;

// A CBEAM along basic x with element y = basic y (v = y), so element and basic axes coincide.
BarElement beam(double n1, double n2, double k = 0.0) {
  BarElement e;
  e.x_B = {kL, 0, 0};
  e.v = {0, 1, 0};
  e.section = {kA, kI1, kI2, 0, kJ, k, k, 0};
  e.material = {1, kE, kG, 0.25, 7800};
  e.is_beam = true;
  e.n_A = e.n_B = {n1, n2};
  return e;
}

// Displacements of end B (6) for loads F at end B with end A clamped.
Eigen::Matrix<double, 6, 1> tip(const BarElement& e, const Eigen::Matrix<double, 6, 1>& F) {
  const NodeMatrix<2> K = bar_stiffness(e);
  return K.bottomRightCorner<6, 6>().ldlt().solve(F);
}

// An axial force P at the nodes (the reference axis) of a beam whose neutral axis is offset by
// (n1, n2) acts at the neutral axis with the moments Mz = n1 P, My = -n2 P: the cantilever's tip
// rotates by n1 P L / (E I1) about z and -n2 P L / (E I2) about y, deflects by n1 P L^2 / (2 E I1)
// and n2 P L^2 / (2 E I2), and its reference axis stretches by P L / (E A) + (n1^2 / I1 + n2^2 / I2) P L / E
// (Castigliano, or the rigid section: u = u_n + n1 theta_z - n2 theta_y). The transverse shear
// flexibility (K1, K2) does not enter: there is no shear force.
TEST(BeamOffset, AxialForceAtTheNodesBendsAnEccentricCantilever) {
  const double P = 1e5, n1 = 0.03, n2 = -0.05;
  for (double k : {0.0, 5.0 / 6.0}) {
    Eigen::Matrix<double, 6, 1> F = Eigen::Matrix<double, 6, 1>::Zero();
    F(0) = P;
    const auto u = tip(beam(n1, n2, k), F);
    const double theta_z = n1 * P * kL / (kE * kI1), theta_y = -n2 * P * kL / (kE * kI2);
    EXPECT_NEAR(u(5), theta_z, 1e-12 * std::abs(theta_z));  // measured 2.2e-15 relative (worst of the five)
    EXPECT_NEAR(u(4), theta_y, 1e-12 * std::abs(theta_y));
    EXPECT_NEAR(u(1), n1 * P * kL * kL / (2 * kE * kI1), 1e-12 * std::abs(theta_z) * kL);
    EXPECT_NEAR(u(2), n2 * P * kL * kL / (2 * kE * kI2), 1e-12 * std::abs(theta_y) * kL);
    const double stretch = P * kL / (kE * kA) + (n1 * n1 / kI1 + n2 * n2 / kI2) * P * kL / kE;
    EXPECT_NEAR(u(0), stretch, 1e-12 * stretch);
    EXPECT_NEAR(u(3), 0.0, 1e-15);
    // no offset: the bar only stretches
    const auto u0 = tip(beam(0, 0, k), F);
    EXPECT_NEAR(u0(0), P * kL / (kE * kA), 1e-12 * P * kL / (kE * kA));
    EXPECT_LE(u0.tail<5>().norm(), 1e-15);
  }
}

// Without twist and shear flexibility, a neutral axis offset by n is the same beam as one on the neutral
// axis joined to the reference axis by rigid links (offsets WA = WB = n): the stiffness matrices agree
// entry by entry on every dof but the twists (theta_x at A and B). A twist does not: about the shear
// centre it turns the section rigidly and bends nothing (Vlasov's thin-walled beam, the fibres' axial
// displacement u - y v' - z w' in the shear centre's v, w), where the links would carry the neutral
// axis sideways. A taper of n (N(A) != N(B)) keeps six rigid-body modes.
TEST(BeamOffset, EqualsRigidLinksWithoutTwistAndHasSixRigidModes) {
  const BarElement e = beam(0.03, -0.05);
  BarElement linked = beam(0, 0);
  linked.w_A = linked.w_B = {0, 0.03, -0.05};
  const NodeMatrix<2> K = bar_stiffness(e), Kl = bar_stiffness(linked);
  double worst = 0;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j)
      if (i % 6 != 3 && j % 6 != 3) worst = std::max(worst, std::abs(K(i, j) - Kl(i, j)));
  EXPECT_LE(worst, 1e-12 * Kl.cwiseAbs().maxCoeff());  // measured 8.3e-16
  EXPECT_GT((K - Kl).cwiseAbs().maxCoeff(), 0.1 * kG * kJ / kL);  // the twist differs (by 0.5 G J / L)

  BarElement g = beam(0.03, -0.05, 0.7);
  g.x_A = {0.3, -0.2, 0.5};
  g.x_B = {2.1, 0.9, -0.4};
  g.v = {0.2, -0.5, 1.0};
  g.w_A = {0.05, 0.1, -0.02};
  g.n_B = {-0.02, 0.04};
  g.section.I12 = 0.6e-5;
  const NodeMatrix<2> Kg = bar_stiffness(g);
  EXPECT_LE((Kg - Kg.transpose()).norm(), 1e-12 * Kg.norm());
  const auto D = rigid_body_modes<2>({g.x_A, g.x_B}, Eigen::Vector3d(1, 2, 3));
  EXPECT_LE((Kg * D).norm(), 1e-9 * Kg.norm() * D.norm());
  EXPECT_EQ(test::null_space_dimension(Kg), 6);
}

// A free thermal expansion: a fibre at (y, z) from the neutral axis strains alpha (dT + TP1 y + TP2 z)
// (I12 = 0). The cantilever's tip turns by -alpha TP1 L about z and alpha TP2 L about y (theta_y = -w',
// w'' = -alpha TP2), deflects by -alpha TP1 L^2 / 2 along y, whatever the
// offset, and its reference axis, at -n from the neutral axis, stretches by alpha L (dT - TP1 n1 - TP2 n2).
TEST(BeamOffset, ThermalStrainOfTheReferenceAxis) {
  const double alpha = 1.2e-5, n1 = 0.03, n2 = -0.05;
  BarTemperatureField t;
  t.dT = 40;
  t.tp1a = t.tp1b = 300;
  t.tp2a = t.tp2b = -200;
  const BarElement e = beam(n1, n2);
  const Eigen::Matrix<double, 12, 1> f = bar_thermal_load(e, alpha, t);
  const auto u = tip(e, f.tail<6>());
  const double stretch = alpha * kL * (t.dT - t.tp1a * n1 - t.tp2a * n2);
  EXPECT_NEAR(u(0), stretch, 1e-12 * std::abs(stretch));  // measured 1.7e-15 relative (worst of the four)
  EXPECT_NEAR(u(5), -alpha * t.tp1a * kL, 1e-12 * alpha * t.tp1a * kL);
  EXPECT_NEAR(u(4), alpha * t.tp2a * kL, 1e-12 * alpha * t.tp1a * kL);
  EXPECT_NEAR(u(1), -alpha * t.tp1a * kL * kL / 2, 1e-12 * alpha * t.tp1a * kL * kL);
}

// The rigid-body mass (D^T M D about the origin, 6 x 6) of a CBEAM whose structure (rho A, polar inertia
// rho (I1 + I2)) sits on the neutral axis at n and whose non-structural mass (NSM, NSI) at m, both
// lines of length L along x, against the closed form: mass, first moments, and the inertia about the
// reference axis and the products Iyz; the coupled mass also the inertias about y and z (its bending
// has no rotary inertia of the section: int (x^2 + z^2) dm and int (x^2 + y^2) dm exactly), the lumped
// mass puts half at each end (x^2 -> L^2 / 2).
TEST(BeamOffset, MassOfOffsetNeutralAxisAndNonStructuralMass) {
  const double rho = 7800, nsm = 55, nsi = 0.8;
  const Eigen::Vector2d n(0.03, -0.05), m(-0.12, 0.07);
  BarElement e = beam(n(0), n(1));
  e.m_A = e.m_B = m;
  e.section.nsm = nsm;
  e.nsi = nsi;
  const double ms = rho * kA * kL, mn = nsm * kL;
  const double mass = ms + mn;
  const Eigen::Vector3d S = ms * Eigen::Vector3d(kL / 2, n(0), n(1)) + mn * Eigen::Vector3d(kL / 2, m(0), m(1));
  const double Ixx = rho * (kI1 + kI2) * kL + ms * n.squaredNorm() + nsi * kL + mn * m.squaredNorm();
  const double Iyz = -(ms * n(0) * n(1) + mn * m(0) * m(1));
  const double Ixy = -(ms * n(0) + mn * m(0)) * kL / 2, Ixz = -(ms * n(1) + mn * m(1)) * kL / 2;
  const double Iyy = (ms + mn) * kL * kL / 3 + ms * n(1) * n(1) + mn * m(1) * m(1);
  const double Izz = (ms + mn) * kL * kL / 3 + ms * n(0) * n(0) + mn * m(0) * m(0);
  const auto D = rigid_body_modes<2>({e.x_A, e.x_B}, Eigen::Vector3d::Zero());
  for (MassKind kind : {MassKind::Lumped, MassKind::Coupled}) {
    const Eigen::Matrix<double, 6, 6> R = D.transpose() * bar_mass(e, kind) * D;
    const double tol = 1e-12 * mass;  // measured 2.2e-16 relative (every entry checked)
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(R(i, i), mass, tol);
    // first moments: R(0..2, 3..5) = -[S]x
    EXPECT_NEAR(R(1, 3), -S(2), tol);
    EXPECT_NEAR(R(2, 3), S(1), tol);
    EXPECT_NEAR(R(0, 4), S(2), tol);
    EXPECT_NEAR(R(0, 5), -S(1), tol);
    EXPECT_NEAR(R(2, 4), -S(0), tol * kL);
    EXPECT_NEAR(R(1, 5), S(0), tol * kL);
    EXPECT_NEAR(R(3, 3), Ixx, 1e-12 * Ixx);
    EXPECT_NEAR(R(4, 5), Iyz, 1e-12 * Ixx);
    if (kind == MassKind::Coupled) {
      EXPECT_NEAR(R(4, 4), Iyy, 1e-12 * Iyy);
      EXPECT_NEAR(R(5, 5), Izz, 1e-12 * Izz);
      EXPECT_NEAR(R(3, 4), Ixy, 1e-12 * Iyy);
      EXPECT_NEAR(R(3, 5), Ixz, 1e-12 * Iyy);
    } else {
      EXPECT_NEAR(R(4, 4), (ms + mn) * kL * kL / 2 + ms * n(1) * n(1) + mn * m(1) * m(1), 1e-12 * Iyy);
    }
    const NodeMatrix<2> M = bar_mass(e, kind);
    EXPECT_LE((M - M.transpose()).norm(), 1e-14 * M.norm());
  }
}

}  // namespace
}  // namespace seflex::fem
