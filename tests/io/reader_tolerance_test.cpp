// Reader tolerance for public decks: DEQATN equations (commas, '=' and blanks are not fields) are
// skipped with their continuation lines and listed as unsupported, not a parse error; a free-field
// line with more fields than one card line continues the card (pyNastran's models/ have such lines,
// e.g. "CORD2C,1,0, 0.,0.,0., 0.,0.,1., 0.,1.,0." in sol_101_elements).
#include <gtest/gtest.h>

#include "nastran_test_util.hpp"

namespace seflex {
namespace {

TEST(ReaderTolerance, DeqatnIsListedNotAParseError) {
  const fem::Model m = test::read_deck(
      "GRID,1,,0.,0.,0.\n"
      "DEQATN  10      F(A,B,C) = A + B*C;\n"
      "                G = F(A, B, C)**2\n"
      "DEQATN,11,H(X)=SIN(X)\n"
      "GRID,2,,1.,0.,0.\n");
  ASSERT_EQ(m.grids.size(), 2u);
  EXPECT_EQ(m.grids[1].id, 2);
  bool listed = false;
  for (const auto& u : m.unsupported)
    if (u.name == "DEQATN") {
      listed = true;
      EXPECT_EQ(u.count, 2u);
      EXPECT_EQ(u.first.line, 2u);
    }
  EXPECT_TRUE(listed);
}

TEST(ReaderTolerance, LongFreeFieldLineContinuesTheCard) {
  const fem::Model one = test::read_deck("CORD2C,1,0, 0.,0.,0., 0.,0.,1., 0.,1.,0.\nGRID,1,1,1.,90.,2.\n");
  const fem::Model two = test::read_deck("CORD2C,1,0,0.,0.,0.,0.,0.,1.,\n,0.,1.,0.\nGRID,1,1,1.,90.,2.\n");
  ASSERT_EQ(one.coords.size(), 1u);
  for (int k = 0; k < 9; ++k) EXPECT_EQ(one.coords[0].abc[k], two.coords[0].abc[k]) << k;
  EXPECT_LT((one.grids[0].x_basic - two.grids[0].x_basic).norm(), 1e-15);
  // x' = basic y (point C), z' = basic z: (r, theta, z) = (1, 90 deg, 2) is at y' = -basic x
  EXPECT_NEAR(one.grids[0].x_basic.x(), -1.0, 1e-12);
  EXPECT_NEAR(one.grids[0].x_basic.z(), 2.0, 1e-12);
  // 17 data fields: three card lines
  const fem::Model pl = test::read_deck("GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\nGRID,5,,2.,0.,0.\n"
                                        "RBE2,9,1,123456,2,3,4,5,,,,,,,,,,\n");
  ASSERT_EQ(pl.rbe2.size(), 1u);
  EXPECT_EQ(pl.rbe2[0].gm.size(), 4u);
}

}  // namespace
}  // namespace seflex
