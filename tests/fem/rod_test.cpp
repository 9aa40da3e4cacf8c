// CROD/CONROD element: stiffness and mass against the closed forms of an axial-torsional rod, and
// the CROD (PROD) and CONROD paths of make_rod_element giving the same element.
#include <gtest/gtest.h>

#include <cmath>

#include "fem_test_util.hpp"
#include "seflex/fem/element_rod.hpp"

namespace seflex::fem {
namespace {

using test::null_space_dimension;

RodElement general_rod() {
  RodElement e;
  e.x_A = {0.3, -0.2, 0.5};
  e.x_B = {2.1, 0.9, -0.4};
  e.A = 2e-3;
  e.J = 3e-6;
  e.nsm = 0.4;
  e.material = {1, 7e10, 2.7e10, 0.3, 2700};
  return e;
}

// A rod carries only axial force and torque (the pin-jointed bar and the torsion member of matrix
// structural analysis, e.g. Przemieniecki, Theory of Matrix Structural Analysis, 1968): end B moved by
// delta along the axis n needs the force E A delta / L along n at B (and -that at A), turned by phi
// about the axis the torque G J phi / L; displacements across the axis and rotations about other
// axes cost nothing. So K has rank 2 (null space 10), and the rigid-body modes lie in it.
TEST(Rod, StiffnessIsAxialAndTorsionalOnly) {
  const RodElement e = general_rod();
  const Eigen::Vector3d d = e.x_B - e.x_A;
  const double L = d.norm();
  const Eigen::Vector3d n = d / L;
  const NodeMatrix<2> K = rod_stiffness(e);
  EXPECT_LE((K - K.transpose()).norm(), 1e-15 * K.norm());
  const double ka = e.material.E * e.A / L, kt = e.material.G * e.J / L;
  Eigen::Matrix<double, 12, 1> u = Eigen::Matrix<double, 12, 1>::Zero();
  u.segment<3>(6) = 1e-3 * n;
  Eigen::Matrix<double, 12, 1> f = K * u;
  EXPECT_LE((f.segment<3>(6) - ka * 1e-3 * n).norm(), 1e-14 * ka * 1e-3);
  EXPECT_LE((f.segment<3>(0) + ka * 1e-3 * n).norm(), 1e-14 * ka * 1e-3);
  EXPECT_LE((f.segment<3>(3).norm() + f.segment<3>(9).norm()), 1e-14 * ka * 1e-3);
  u.setZero();
  u.segment<3>(9) = 2e-3 * n;  // twist of B about the axis
  f = K * u;
  EXPECT_LE((f.segment<3>(9) - kt * 2e-3 * n).norm(), 1e-14 * kt * 2e-3);
  EXPECT_LE((f.segment<3>(3) + kt * 2e-3 * n).norm(), 1e-14 * kt * 2e-3);
  EXPECT_EQ(f.segment<3>(0).norm() + f.segment<3>(6).norm(), 0.0);
  // across the axis: nothing
  const Eigen::Vector3d across = n.unitOrthogonal();
  u.setZero();
  u.segment<3>(6) = across;
  u.segment<3>(9) = across;
  EXPECT_LE((K * u).norm(), 1e-14 * ka);
  const auto D = rigid_body_modes<2>({e.x_A, e.x_B}, Eigen::Vector3d(1, 2, 3));
  EXPECT_LE((K * D).norm(), 1e-12 * K.norm() * D.norm());
  EXPECT_EQ(null_space_dimension(K), 10);
}

// Mass m = (rho A + NSM) L on the three translations of each end only (no rotary inertia), so a
// rigid motion sees the total mass and its centre at the middle; turning the rod rigidly about an
// axis through its centre, across the rod, the lumped mass (m/2 at the ends) has the inertia
// m L^2 / 4 and the coupled (linear shape functions, m/6 [2 1; 1 2] on each translation) that of the
// continuous rod, m L^2 / 12; about the rod's own axis both have none.
TEST(Rod, MassOfLumpedAndCoupledRod) {
  const RodElement e = general_rod();
  const Eigen::Vector3d d = e.x_B - e.x_A, c = 0.5 * (e.x_A + e.x_B);
  const double L = d.norm(), m = (e.material.rho * e.A + e.nsm) * L;
  const Eigen::Vector3d n = d / L, across = n.unitOrthogonal();
  for (MassKind kind : {MassKind::Lumped, MassKind::Coupled}) {
    const NodeMatrix<2> M = rod_mass(e, kind);
    const char* name = kind == MassKind::Lumped ? "lumped" : "coupled";
    EXPECT_LE((M - M.transpose()).norm(), 1e-15 * M.norm()) << name;
    const auto D = rigid_body_modes<2>({e.x_A, e.x_B}, c);
    const Matrix6 M0 = D.transpose() * M * D;
    EXPECT_LE((M0.topLeftCorner<3, 3>() - m * Eigen::Matrix3d::Identity()).norm(), 1e-14 * m) << name;
    EXPECT_LE((M0.topRightCorner<3, 3>().norm()), 1e-14 * m * L) << name;  // centre of mass at c
    const double I_across = kind == MassKind::Lumped ? m * L * L / 4 : m * L * L / 12;
    EXPECT_NEAR(across.dot(M0.bottomRightCorner<3, 3>() * across), I_across, 1e-14 * m * L * L) << name;
    EXPECT_NEAR(n.dot(M0.bottomRightCorner<3, 3>() * n), 0.0, 1e-14 * m * L * L) << name;
    for (int k : {3, 4, 5, 9, 10, 11}) EXPECT_EQ(M.row(k).norm(), 0.0) << name << " row " << k;
  }
}

// The same rod as CONROD (inline A, J, NSM, MID) and as CROD on a PROD: the same element.
TEST(Rod, CrodOnProdEqualsConrod) {
  Model m;
  test::add_grid(m, 1, 0.3, -0.2, 0.5);
  test::add_grid(m, 2, 2.1, 0.9, -0.4);
  test::add_mat1(m, 1, 7e10, 0.3, 2700);
  Rod& conrod = test::add_conrod(m, 10, 1, 2, 1, 2e-3, 0.4);
  conrod.J = 3e-6;
  RodProperty p;
  p.id = 5;
  p.mid = 1;
  p.A = 2e-3;
  p.J = 3e-6;
  p.nsm = 0.4;
  m.rod_props.push_back(p);
  Rod crod;
  crod.id = 11;
  crod.pid = 5;
  crod.ga = 1;
  crod.gb = 2;
  m.rods.push_back(crod);
  test::finalize_for_test(m);
  ASSERT_EQ(m.rods.size(), 2u);
  const RodElement a = make_rod_element(m, m.rods[0]), b = make_rod_element(m, m.rods[1]);
  const NodeMatrix<2> Ka = rod_stiffness(a);
  EXPECT_GT(Ka.norm(), 0.0);
  EXPECT_EQ((rod_stiffness(b) - Ka).norm(), 0.0);
  for (MassKind kind : {MassKind::Lumped, MassKind::Coupled}) EXPECT_EQ((rod_mass(b, kind) - rod_mass(a, kind)).norm(), 0.0);
  // and both are the closed-form rod of general_rod() (the material's G from E and nu: 7e10 / 2.6)
  EXPECT_NEAR(a.material.G, 7e10 / 2.6, 1e-6);
  EXPECT_EQ(a.A, 2e-3);
  EXPECT_EQ(a.J, 3e-6);
  EXPECT_EQ(a.nsm, 0.4);
}

}  // namespace
}  // namespace seflex::fem
