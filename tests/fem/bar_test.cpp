// CBAR/CBEAM element: physics invariants, closed-form stiffness entries, pin flags, offsets, I12.
#include <gtest/gtest.h>

#include <cmath>

#include "fem_test_util.hpp"
#include "seflex/fem/element_bar.hpp"

namespace seflex::fem {
namespace {

using test::null_space_dimension;

BarElement general_bar() {
  BarElement e;
  e.x_A = {0.3, -0.2, 0.5};
  e.x_B = {2.1, 0.9, -0.4};
  e.w_A = {0.05, 0.1, -0.02};
  e.w_B = {-0.03, 0.02, 0.08};
  e.v = {0.2, -0.5, 1.0};
  e.section = {2e-3, 3e-6, 1.5e-6, 0.4e-6, 2.5e-6, 0.8, 0.6, 0.3};
  e.material = {1, 7e10, 7e10 / 2.6, 0.3, 2700};
  return e;
}

TEST(Bar, StiffnessSymmetricWithExactlySixRigidModes) {
  for (int variant = 0; variant < 4; ++variant) {
    BarElement e = general_bar();
    if (variant == 1) e.section.I12 = 0.0;            // uncoupled planes
    if (variant == 2) e.section.K1 = e.section.K2 = 0;  // Euler-Bernoulli
    if (variant == 3) { e.pin_A = test::mask("56"); e.pin_B = test::mask("4"); }
    const NodeMatrix<2> K = bar_stiffness(e);
    EXPECT_LE((K - K.transpose()).norm(), 1e-12 * K.norm());
    // rigid modes about an arbitrary point are in the null space ...
    const auto D = rigid_body_modes<2>({e.x_A, e.x_B}, Eigen::Vector3d(1, 2, 3));
    EXPECT_LE((K * D).norm(), 1e-9 * K.norm() * D.norm()) << "variant " << variant;
    // ... and nothing else (three released dofs add three zero-energy modes in variant 3)
    EXPECT_EQ(null_space_dimension(K), variant == 3 ? 9 : 6) << "variant " << variant;
  }
}

// Closed-form prismatic-beam entries (Przemieniecki 1968, eq. 5.116) with the shear parameter
// Phi = 12 EI / (G As L^2) (Phi = 0: Euler-Bernoulli), element along basic x, y up.
TEST(Bar, MatchesClosedFormEntries) {
  for (double k1 : {0.0, 5.0 / 6.0}) {
    BarElement e;
    const double L = 2.0, E = 2e11, G = 8e10, A = 1e-2, I1 = 4e-5, I2 = 2e-5, J = 3e-5;
    e.x_B = {L, 0, 0};
    e.v = {0, 1, 0};
    e.section = {A, I1, I2, 0, J, k1, k1, 0};
    e.material = {1, E, G, 0.25, 7800};
    const NodeMatrix<2> K = bar_stiffness(e);
    const double phi1 = k1 > 0 ? 12 * E * I1 / (G * k1 * A * L * L) : 0.0;
    const double phi2 = k1 > 0 ? 12 * E * I2 / (G * k1 * A * L * L) : 0.0;
    const double tol = 1e-10;
    EXPECT_NEAR(K(0, 0), E * A / L, tol * E * A / L);
    EXPECT_NEAR(K(0, 6), -E * A / L, tol * E * A / L);
    EXPECT_NEAR(K(3, 3), G * J / L, tol * G * J / L);
    // plane 1: v, theta_z
    const double a1 = E * I1 / (L * L * L * (1 + phi1));
    EXPECT_NEAR(K(1, 1), 12 * a1, tol * 12 * a1);
    EXPECT_NEAR(K(1, 5), 6 * L * a1, tol * 6 * L * a1);
    EXPECT_NEAR(K(5, 5), (4 + phi1) * L * L * a1, tol * 4 * L * L * a1);
    EXPECT_NEAR(K(5, 11), (2 - phi1) * L * L * a1, tol * 4 * L * L * a1);
    EXPECT_NEAR(K(1, 7), -12 * a1, tol * 12 * a1);
    // plane 2: w, theta_y (theta_y = -w')
    const double a2 = E * I2 / (L * L * L * (1 + phi2));
    EXPECT_NEAR(K(2, 2), 12 * a2, tol * 12 * a2);
    EXPECT_NEAR(K(2, 4), -6 * L * a2, tol * 6 * L * a2);
    EXPECT_NEAR(K(4, 4), (4 + phi2) * L * L * a2, tol * 4 * L * L * a2);
    EXPECT_NEAR(K(4, 10), (2 - phi2) * L * L * a2, tol * 4 * L * L * a2);
    EXPECT_NEAR(K(1, 2), 0.0, tol * a1);
  }
}

// A section with principal moments Ia, Ib whose principal axes are turned by alpha about the bar
// axis has, in the element axes, I1 = Ia c^2 + Ib s^2, I2 = Ia s^2 + Ib c^2, I12 = (Ia - Ib) s c
// (I12 = int y z dA). The same bar described in its principal axes (v turned by alpha) must give
// the same stiffness in basic.
TEST(Bar, ProductOfInertiaEqualsRotatedPrincipalSection) {
  const double Ia = 5e-6, Ib = 1e-6, alpha = 0.4, c = std::cos(alpha), s = std::sin(alpha);
  for (double k : {0.0, 0.7}) {  // shear flexibility equal in both planes is invariant under rotation
    BarElement rot;
    rot.x_A = {0, 0, 0};
    rot.x_B = {1.5, 0, 0};
    rot.v = {0, 1, 0};
    rot.section = {1e-3, Ia * c * c + Ib * s * s, Ia * s * s + Ib * c * c, (Ia - Ib) * s * c, 2e-6, k, k, 0};
    rot.material = {1, 7e10, 2.7e10, 0.3, 2700};
    BarElement principal = rot;
    principal.v = {0, c, s};
    principal.section.I1 = Ia;
    principal.section.I2 = Ib;
    principal.section.I12 = 0;
    const NodeMatrix<2> K1 = bar_stiffness(rot), K2 = bar_stiffness(principal);
    EXPECT_LE((K1 - K2).norm(), 1e-10 * K2.norm()) << "K1/K2 = " << k;
  }
}

// Pin flag 6 at end A of a bar clamped at B: the tip stiffness becomes the propped value 3EI/L^3
// (Przemieniecki sec. 5.6, released moment end).
TEST(Bar, PinFlagReleasesMoment) {
  BarElement e;
  const double L = 3.0, E = 1e7, I1 = 0.1;
  e.x_B = {L, 0, 0};
  e.v = {0, 1, 0};
  e.section = {0.1, I1, 0.1, 0, 0.1, 0, 0, 0};
  e.material = {1, E, E / 2.6, 0.3, 0.1};
  e.pin_A = test::mask("6");
  const NodeMatrix<2> K = bar_stiffness(e);
  EXPECT_NEAR(K(1, 1), 3 * E * I1 / (L * L * L), 1e-10 * E * I1 / (L * L * L));
  EXPECT_EQ(K.row(5).norm(), 0.0);
  EXPECT_EQ(K.col(5).norm(), 0.0);
  // axial and the other plane are untouched
  EXPECT_NEAR(K(0, 0), E * 0.1 / L, 1e-10 * E * 0.1 / L);
  EXPECT_NEAR(K(2, 2), 12 * E * 0.1 / (L * L * L), 1e-10 * 12 * E * 0.1 / (L * L * L));
}

// Offsets: a bar whose ends sit e = 0.5 above both grids, clamped at grid A, axial force P at grid
// B. Energy balance gives the grid's axial displacement u = P L / (E A) + P e^2 L / (E I2): the
// force acts e below the bar axis, bending the bar with the uniform moment P e.
TEST(Bar, OffsetsAreRigidLinks) {
  BarElement e;
  const double L = 2.0, E = 1e7, A = 0.2, I2 = 0.03, ecc = 0.5, P = 100.0;
  e.x_B = {L, 0, 0};
  e.w_A = e.w_B = {0, 0, ecc};
  e.v = {0, 1, 0};
  e.section = {A, 0.05, I2, 0, 0.04, 0, 0, 0};
  e.material = {1, E, E / 2.6, 0.3, 0.1};
  const NodeMatrix<2> K = bar_stiffness(e);
  const Eigen::MatrixXd Kbb = K.bottomRightCorner<6, 6>();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6);
  f[0] = P;
  const Eigen::VectorXd u = Kbb.ldlt().solve(f);
  EXPECT_NEAR(u[0], P * L / (E * A) + P * ecc * ecc * L / (E * I2), 1e-10 * u[0]);
}

TEST(Bar, MassSumsToTotalAndRigidInertia) {
  BarElement e = general_bar();
  const double L = bar_length(e);
  const double m = (e.material.rho * e.section.A + e.section.nsm) * L;
  for (MassKind kind : {MassKind::Lumped, MassKind::Coupled}) {
    const NodeMatrix<2> M = bar_mass(e, kind);
    EXPECT_LE((M - M.transpose()).norm(), 1e-12 * M.norm());
    const auto D = rigid_body_modes<2>({e.x_A, e.x_B});
    const Matrix6 M0 = D.transpose() * M * D;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(M0(k, k), m, 1e-12 * m);
    // centre of gravity at the middle of the (offset) bar: first moment m * c
    const Eigen::Vector3d c = 0.5 * (e.x_A + e.w_A + e.x_B + e.w_B);
    EXPECT_NEAR(M0(1, 5), m * c.x(), 1e-12 * m);
    EXPECT_NEAR(M0(2, 3), m * c.y(), 1e-12 * m);
    EXPECT_NEAR(M0(0, 4), m * c.z(), 1e-12 * m);
  }
  // Coupled mass: spin about the bar axis through its centroid has inertia rho (I1 + I2) L.
  const Eigen::Matrix3d R = bar_axes(e);
  const Eigen::Vector3d c = 0.5 * (e.x_A + e.w_A + e.x_B + e.w_B);
  const auto D = rigid_body_modes<2>({e.x_A, e.x_B}, c);
  const Matrix6 M0 = D.transpose() * bar_mass(e, MassKind::Coupled) * D;
  const Eigen::Vector3d ax = R.col(0);
  EXPECT_NEAR(ax.dot(M0.bottomRightCorner<3, 3>() * ax), e.material.rho * (e.section.I1 + e.section.I2) * L, 1e-10 * m);
}

// Spin about the bar axis through the (offset) bar's centroid: a CBAR's lumped mass has no inertia
// about it (m/2 on the axis at each end, no rotary inertia), a CBEAM's lumped mass carries the polar
// inertia (rho (I1 + I2) + NSI) L, half at each end (as Nastran's: the MSC Nastran result quoted in
// tests/solutions/validation_modes_test.cpp, CbarCbeamConm2MatchesNastranLumpedMass), and the coupled mass of both the
// continuous rod's (rho (I1 + I2) + NSI) L (NSI only on CBEAM: PBAR has no such field).
TEST(Bar, SpinInertiaOfLumpedAndCoupledCbarAndCbeam) {
  for (bool beam : {false, true})
    for (MassKind kind : {MassKind::Lumped, MassKind::Coupled}) {
      BarElement e = general_bar();
      e.is_beam = beam;
      e.nsi = beam ? 0.35 : 0.0;
      const double L = bar_length(e);
      const Eigen::Vector3d c = 0.5 * (e.x_A + e.w_A + e.x_B + e.w_B), ax = bar_axes(e).col(0);
      const Matrix6 M0 = rigid_body_modes<2>({e.x_A, e.x_B}, c).transpose() * bar_mass(e, kind) *
                         rigid_body_modes<2>({e.x_A, e.x_B}, c);
      const double polar = (e.material.rho * (e.section.I1 + e.section.I2) + e.nsi) * L;
      const double expected = !beam && kind == MassKind::Lumped ? 0.0 : polar;
      EXPECT_NEAR(ax.dot(M0.bottomRightCorner<3, 3>() * ax), expected, 1e-12 * polar)
          << (beam ? "CBEAM " : "CBAR ") << (kind == MassKind::Lumped ? "lumped" : "coupled");
    }
}

}  // namespace
}  // namespace seflex::fem

namespace seflex::fem {
namespace {

// Orientation and offsets as a CBAR card gives them: G0 (v from GA to G0), v in GA's displacement
// system (OFFT G..) or basic (B..), offsets in the grids' displacement systems (.GG), basic (.BB)
// or element axes (.OO): all describe the same bar here, so all give the same stiffness.
TEST(Bar, OrientationAndOffsetConventions) {
  Model m;
  test::add_grid(m, 1, 0, 0, 0, 5);
  test::add_grid(m, 2, 2, 0.5, 0, 5);
  test::add_grid(m, 3, 0.3, 1.0, 2.0);
  const Eigen::Matrix3d R5 = so3::exp(Eigen::Vector3d(0.4, -0.2, 0.9));
  test::add_rect_coord(m, 5, {0, 0, 0}, R5);
  test::add_mat1(m, 1, 7e10, 0.3, 2700);
  test::add_pbar(m, 2, 1, 1e-3, 2e-6, 1e-6, 3e-6);
  const Eigen::Vector3d v_basic(0.3, 1.0, 2.0), wa(0.05, 0.02, 0.1), wb(-0.02, 0.04, 0.1);
  Bar& g0 = test::add_cbar(m, 10, 2, 1, 2, Eigen::Vector3d::Zero());  // G0 = 3 and offsets in CD 5
  g0.has_g0 = true;
  g0.g0 = 3;
  g0.wa = R5.transpose() * wa;
  g0.wb = R5.transpose() * wb;
  Bar& vg = test::add_cbar(m, 11, 2, 1, 2, R5.transpose() * v_basic);  // v in GA's CD, offsets basic
  vg.offt = "GBB";
  vg.wa = wa;
  vg.wb = wb;
  test::finalize_for_test(m);
  const BarElement e0 = make_bar_element(m, m.bars[0]), e1 = make_bar_element(m, m.bars[1]);
  // offsets in element axes of the grid-to-grid line (the same line here up to the offsets' shift)
  Bar oo = m.bars[1];
  oo.offt = "BOO";
  oo.v = v_basic;
  BarElement probe = e1;
  probe.w_A = probe.w_B = Eigen::Vector3d::Zero();
  const Eigen::Matrix3d R0 = bar_axes(probe);
  oo.wa = R0.transpose() * wa;
  oo.wb = R0.transpose() * wb;
  const BarElement e2 = make_bar_element(m, oo);
  const NodeMatrix<2> K0 = bar_stiffness(e0);
  EXPECT_LE((bar_stiffness(e1) - K0).norm(), 1e-12 * K0.norm());
  EXPECT_LE((bar_stiffness(e2) - K0).norm(), 1e-12 * K0.norm());
  EXPECT_LE((e0.v.normalized() - v_basic.normalized()).norm(), 1e-15);
}

}  // namespace
}  // namespace seflex::fem
