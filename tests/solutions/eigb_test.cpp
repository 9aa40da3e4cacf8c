// EIGB (MSC QRG EIGB: SID METHOD L1 L2 NEP NDP NDN / NORM G C), the buckling method that METHOD of a
// SOL 105 subcase selects: the load factors in [L1, L2]. On the Euler column of the buckling deck
// (tests/data/buckling/euler_column_cbar.bdf: pi^2 E I / l^2 = 90962 N, a unit load) the same load
// factors as EIGRL and Euler's within 1e-4 (cli_buckling_test.cpp: 10 CBARs, from above); the range
// keeps the first pair (Euler's load, one mode per bending plane) and leaves out the second (4 x);
// NORM POINT; the card's errors by their message.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "nastran_test_util.hpp"
#include "test_support.hpp"
#include "seflex/fem/dof_map.hpp"
#include "seflex/io/nastran.hpp"
#include "seflex/solutions/buckling.hpp"
#include "seflex/solutions/normal_modes.hpp"

namespace seflex {
namespace {

using test::mentions;

/// The Euler column deck with its EIGRL (ND = 4) replaced by `method`.
fem::Model column(const std::string& method) {
  std::string text = test::read_file(test::data_dir() / "buckling" / "euler_column_cbar.bdf");
  const std::string eigrl = "EIGRL   10                      4\n";
  const auto at = text.find(eigrl);
  if (at == std::string::npos) throw std::runtime_error("the column deck has no EIGRL 10");
  text.replace(at, eigrl.size(), method);
  return test::read_deck(text);
}

TEST(Eigb, EulerColumnSameLoadFactorsAsEigrl) {
  const double pi = std::acos(-1.0);
  const double P_euler = pi * pi * 207000.0 * 7853.98 / (420.0 * 420.0);
  const auto eigrl = solutions::solve_buckling(column("EIGRL,10,,,4\n"));
  // L1 = 0, L2 = 2 x Euler: the first pair only; NEP = 2 (NDP = 3 NEP = 6 at most)
  const fem::Model m = column("EIGB,10,INV,0.,200000.,2\n");
  ASSERT_EQ(m.eigen_methods.size(), 1u);
  EXPECT_TRUE(m.eigen_methods[0].is_eigb);
  EXPECT_EQ(m.eigen_methods[0].nd, 6);
  const auto eigb = solutions::solve_buckling(m);
  ASSERT_EQ(eigb.load_factors.size(), 2);
  ASSERT_EQ(eigrl.load_factors.size(), 4);
  for (Eigen::Index k = 0; k < 2; ++k) {
    EXPECT_GT(eigb.load_factors(k), P_euler);  // the consistent K_sigma gives upper bounds
    EXPECT_LT(eigb.load_factors(k) / P_euler - 1.0, 1e-4) << "mode " << k + 1;
    // the same generalized eigenproblem: measured 1e-15 relative
    EXPECT_NEAR(eigb.load_factors(k), eigrl.load_factors(k), 1e-9 * P_euler) << "mode " << k + 1;
  }
  // a range above the first pair: the second pair only (4 x Euler, within 1e-3 from above)
  const auto second = solutions::solve_buckling(column("EIGB,10,SINV,200000.,500000.\n"));
  ASSERT_EQ(second.load_factors.size(), 2);
  for (Eigen::Index k = 0; k < 2; ++k) {
    EXPECT_NEAR(second.load_factors(k), eigrl.load_factors(k + 2), 1e-9 * P_euler);
    EXPECT_LT(second.load_factors(k) / (4 * P_euler) - 1.0, 1e-3);
  }
}

TEST(Eigb, NormPointScalesTheShapeToOneThere) {
  const fem::Model m = column("EIGB,10,INV,0.,200000.,2\n,POINT,6,2\n");
  const auto s = solutions::solve_buckling(m);
  const Eigen::Index d = *fem::find_dof(m, s.dofs, 6, 2);
  ASSERT_EQ(s.shapes_g.cols(), 2);
  for (Eigen::Index k = 0; k < 2; ++k) {
    if (std::abs(s.shapes_g(d, k)) > 1e-12)
      EXPECT_DOUBLE_EQ(s.shapes_g(d, k), 1.0) << "mode " << k + 1;
    else  // a mode in the other bending plane does not move grid 6 in y: MAX
      EXPECT_DOUBLE_EQ(s.shapes_g.col(k).cwiseAbs().maxCoeff(), 1.0) << "mode " << k + 1;
  }
}

TEST(Eigb, BadFieldsAndAModesSolutionSelectingIt) {
  EXPECT_TRUE(mentions(test::read_error("EIGB,10,LAN,0.,1.\n"), {"deck.bdf:1: EIGB 10, field 3 (METHOD): got text 'LAN'; expected INV or SINV"}));
  EXPECT_TRUE(mentions(test::read_error("EIGB,10,INV,5.,1.\n"), {"EIGB 10, field 5 (L2)", "expected L2 > L1"}));
  EXPECT_TRUE(mentions(test::read_error("EIGB,10,INV,0.\n"), {"EIGB 10, field 5 (L2)"}));
  EXPECT_TRUE(mentions(test::read_error("EIGB,10,INV,0.,1.,-2\n"), {"EIGB 10, field 6 (NEP)", "expected an estimated number of roots >= 0"}));
  EXPECT_TRUE(mentions(test::read_error("EIGB,10,INV,0.,1.\n,MASS\n"), {"EIGB 10", "(NORM)", "expected MAX, POINT or blank"}));
  // normal modes need EIGRL or EIGR
  std::string text = test::read_file(test::data_dir() / "buckling" / "euler_column_cbar.bdf");
  text.replace(text.find("SOL 105"), 7, "SOL 103");
  text.replace(text.find("EIGRL   10                      4"), 33, "EIGB,10,INV,0.,1.");
  const fem::Model m = test::read_deck(text);
  solutions::ModesOptions o;
  o.subcase = 2;
  try {
    solutions::solve_normal_modes(m, o);
    ADD_FAILURE() << "normal modes ran with an EIGB";
  } catch (const InputError& e) {
    EXPECT_TRUE(mentions(e.what(), {"EIGB", "a buckling method; normal modes need an EIGRL or EIGR"}));
  }
}

}  // namespace
}  // namespace seflex
