// `seflex reduce MODEL --modes 0`: a static (Guyan) reduction, no fixed-interface mode kept. The
// Craig-Bampton code once took rows of the empty eigenvector matrix there (UBSan: "applying non-zero
// offset to null pointer", reduction/src/craig_bampton.cpp); this edge of the option range runs here so
// that CI's sanitizer stage (ctest -L input under ASan + UBSan) covers it.
//
// Reference: examples/scenes/link.bdf is a uniform 1 m aluminium bar of 4 CBARs without shear
// flexibility (PBAR K1/K2 blank), whose cubic shape functions are exact for Euler-Bernoulli beams, so
// condensing the interior grids 2-4 onto the ends 1 and 5 gives exactly the two-node beam stiffness
// (Przemieniecki, Theory of Matrix Structural Analysis, eq. 5.116): with grid 1 held, the block of
// grid 5 (basic axes; the bar lies along x, its CBAR y axis is basic z, so I1 bends in x-z) is
//   EA/L (x), 12 E I2/L^3 (y), 12 E I1/L^3 (z), GJ/L (rx), 4 E I1/L (ry), 4 E I2/L (rz),
//   |K(y, rz)| = 6 E I2/L^2, |K(z, ry)| = 6 E I1/L^2.
// And a rigid translation lies in the span of the constraint modes, so the reduced mass gives the
// bar's mass rho A L for it.
#include <gtest/gtest.h>

#include <cmath>

#include "seflex/io/superelement_file.hpp"
#include "test_support.hpp"

namespace seflex {
namespace {

TEST(ReduceNoModes, IsTheStaticCondensationOfTheBar) {
  test::TempDir tmp;
  const auto deck = test::source_dir() / "examples" / "scenes" / "link.bdf";
  const auto se_path = tmp / "link0.se";
  const auto r =
      test::run_seflex("reduce '" + deck.string() + "' --interface 1,5 --modes 0 -o '" + se_path.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("runtime error"), std::string::npos) << r.err;  // UBSan's report, where it recovers

  const se::Superelement se = io::load_superelement(se_path);
  ASSERT_EQ(se.num_modes, 0);
  EXPECT_EQ(se.mode_frequencies_hz.size(), 0);
  ASSERT_EQ(se.num_interfaces(), 2);
  ASSERT_EQ(se.interfaces[1].id, 5);
  ASSERT_EQ(se.K.rows(), 12);
  ASSERT_EQ(se.M.rows(), 12);

  const double E = 7.0e10, nu = 0.33, G = E / (2.0 * (1.0 + nu)), L = 1.0;
  const double A = 1.0e-4, I1 = 2.083e-10, I2 = 3.333e-9, J = 7.0e-10, rho = 2700.0;
  const Eigen::MatrixXd K5 = se.K.bottomRightCorner(6, 6);  // grid 5, grid 1 held
  const double expected_diag[6] = {E * A / L,      12 * E * I2 / (L * L * L), 12 * E * I1 / (L * L * L),
                                   G * J / L,      4 * E * I1 / L,            4 * E * I2 / L};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(K5(k, k), expected_diag[k], 1e-9 * expected_diag[k]) << "dof " << k;
  EXPECT_NEAR(std::abs(K5(1, 5)), 6 * E * I2 / (L * L), 1e-9 * 6 * E * I2);
  EXPECT_NEAR(std::abs(K5(2, 4)), 6 * E * I1 / (L * L), 1e-9 * 6 * E * I1);

  for (int dir = 0; dir < 3; ++dir) {  // rigid translation of both ends along x, y, z
    Eigen::VectorXd t = Eigen::VectorXd::Zero(12);
    t(dir) = t(6 + dir) = 1.0;
    EXPECT_NEAR(t.dot(se.M * t), rho * A * L, 1e-12 * rho * A * L) << "direction " << dir;
    EXPECT_LT((se.K * t).norm(), 1e-6 * E * A / L) << "direction " << dir;  // no force for a rigid motion
  }
}

}  // namespace
}  // namespace seflex
