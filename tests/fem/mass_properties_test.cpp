// Grid point weight generator: element-by-element M0 against the assembled mass matrix and against
// values derived by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "fem_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/mass_properties.hpp"

namespace seflex::fem {
namespace {

// Bars with offsets, a rod, a warped CQUAD4, a CTRIA3, CONM2 in a rotated system, WTMASS, GRDPNT.
Model mixed_model(bool coupled) {
  Model m;
  test::add_grid(m, 1, 0, 0, 0);
  test::add_grid(m, 2, 1.2, 0.1, 0.0);
  test::add_grid(m, 3, 1.3, 1.0, 0.2);
  test::add_grid(m, 4, -0.1, 0.9, 0.0);
  test::add_grid(m, 5, 0.5, 1.6, 0.4);
  test::add_mat1(m, 1, 7e10, 0.3, 2700);
  test::add_pbar(m, 2, 1, 1e-3, 2e-6, 1e-6, 3e-6, 0.4);
  Bar& b = test::add_cbar(m, 10, 2, 1, 2, {0, 0, 1});
  b.wa = {0, 0, 0.05};
  b.wb = {0, 0.02, 0.05};
  test::add_cbar(m, 11, 2, 2, 3, {0, 0, 1});
  test::add_conrod(m, 12, 3, 5, 1, 2e-4, 0.1);
  test::add_pshell(m, 3, 1, 0.003, true, 0.5);
  test::add_shell(m, 20, 3, {1, 2, 3, 4});  // warped: grid 3 is 0.2 above the others
  test::add_shell(m, 21, 3, {4, 3, 5});
  test::add_rect_coord(m, 6, {1, 2, 3}, so3::exp(Eigen::Vector3d(0.3, 0.2, -0.4)));
  Conm2& c = test::add_conm2(m, 30, 4, 2.5);
  c.cid = 6;
  c.x = {0.1, 0.2, -0.1};
  c.I11 = 0.03;
  c.I22 = 0.02;
  c.I33 = 0.05;
  c.I21 = 0.004;
  c.I32 = -0.002;
  test::add_param(m, "WTMASS", "0.5");
  test::add_param(m, "GRDPNT", "2");
  if (coupled) test::add_param(m, "COUPMASS", "1");
  test::finalize_for_test(m);
  return m;
}

// M0 of the element-by-element generator equals D^T M D with the assembled M (divided by WTMASS)
// and D the rigid-body modes of all grids about the reference grid.
TEST(MassProperties, EqualsRigidBodyProjectionOfAssembledMass) {
  for (bool coupled : {false, true}) {
    const Model m = mixed_model(coupled);
    const MassProperties mp = mass_properties(m);
    EXPECT_EQ(mp.reference_grid, 2);
    EXPECT_EQ(mp.wtmass, 0.5);
    const GlobalMatrices g = assemble(m, assembly_options(m));
    Eigen::MatrixXd D(g.dofs.size(), 6);
    for (std::size_t i = 0; i < m.grids.size(); ++i)
      D.middleRows<6>(6 * static_cast<Eigen::Index>(i)) = rigid_link(m.grids[i].x_basic - m.grids[1].x_basic);
    const Eigen::MatrixXd M0 = D.transpose() * test::dense(g.M) * D / 0.5;
    EXPECT_LE((M0 - mp.M0).norm(), 1e-12 * M0.norm()) << (coupled ? "coupled" : "lumped");
  }
}

// A single CBAR of mass m and length L along x: the lumped mass (m/2 at each end, no rotary
// inertia) gives I_yy = I_zz = m L^2 / 4 about the CG; the coupled mass reproduces the continuous
// bar, m L^2 / 12, and the section's polar inertia rho (I1 + I2) L about the axis.
TEST(MassProperties, BarByHand) {
  for (bool coupled : {false, true}) {
    Model m;
    test::add_grid(m, 1, 1, 2, 3);
    test::add_grid(m, 2, 3, 2, 3);
    test::add_mat1(m, 1, 2e11, 0.3, 7800);
    test::add_pbar(m, 2, 1, 1e-3, 2e-6, 3e-6, 4e-6, 0.5);
    test::add_cbar(m, 10, 2, 1, 2, {0, 1, 0});
    if (coupled) test::add_param(m, "COUPMASS", "1");
    test::finalize_for_test(m);
    const MassProperties mp = mass_properties(m);
    const double L = 2.0, mass = (7800 * 1e-3 + 0.5) * L;
    EXPECT_NEAR(mp.mass, mass, 1e-12 * mass);
    EXPECT_LE((mp.cg - Eigen::Vector3d(2, 2, 3)).norm(), 1e-12);
    const double It = coupled ? mass * L * L / 12 : mass * L * L / 4;
    const double Ia = coupled ? 7800 * 5e-6 * L : 0.0;
    EXPECT_NEAR(mp.I_cg(0, 0), Ia, 1e-12 * mass);
    EXPECT_NEAR(mp.I_cg(1, 1), It, 1e-12 * It);
    EXPECT_NEAR(mp.I_cg(2, 2), It, 1e-12 * It);
    EXPECT_NEAR(mp.I_cg(0, 1), 0.0, 1e-12 * It);
    // reference point: the basic origin (no GRDPNT): M0(4, 4) = I_yy about the origin
    EXPECT_EQ(mp.reference_grid, 0);
    EXPECT_NEAR(mp.M0(4, 4), It + mass * (4 + 9), 1e-12 * mp.M0(4, 4));
  }
}

// Four equal CONM2 masses at +-a e1, +-b e2 of a rotated frame R (columns e1 e2 e3) about a centre c:
// the inertia about the CG is R diag(2 m b^2, 2 m a^2, 2 m (a^2 + b^2)) R^T; the principal moments
// are those values (ascending) and the principal axes are the columns of R (up to sign).
TEST(MassProperties, PrincipalAxesOfRotatedMasses) {
  const Eigen::Matrix3d R = so3::exp(Eigen::Vector3d(0.5, -0.3, 0.8));
  const Eigen::Vector3d c(1, -2, 0.5);
  const double a = 2.0, b = 1.0, mk = 3.0;
  Model m;
  const Eigen::Vector3d p[4] = {c + a * R.col(0), c - a * R.col(0), c + b * R.col(1), c - b * R.col(1)};
  for (int k = 0; k < 4; ++k) {
    test::add_grid(m, k + 1, p[k].x(), p[k].y(), p[k].z());
    test::add_conm2(m, 10 + k, k + 1, mk);
  }
  test::finalize_for_test(m);
  const MassProperties mp = mass_properties(m);
  EXPECT_NEAR(mp.mass, 4 * mk, 1e-12);
  EXPECT_LE((mp.cg - c).norm(), 1e-12);
  const Eigen::Vector3d I(2 * mk * b * b, 2 * mk * a * a, 2 * mk * (a * a + b * b));
  EXPECT_LE((mp.I_cg - R * I.asDiagonal() * R.transpose()).norm(), 1e-12);
  EXPECT_LE((mp.principal_moments - I).norm(), 1e-12);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(std::abs(mp.principal_axes.col(k).dot(R.col(k))), 1.0, 1e-12);
  EXPECT_NEAR(mp.principal_axes.determinant(), 1.0, 1e-12);
}

}  // namespace
}  // namespace seflex::fem
