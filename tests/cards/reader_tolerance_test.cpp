// Reader tolerance for public decks: DEQATN equations (commas, '=' and blanks are not fields) are
// skipped with their continuation lines and listed as unsupported, not a parse error.
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
    if (u.name == "DEQATN") listed = true, EXPECT_EQ(u.count, 2u), EXPECT_EQ(u.first.line, 2u);
  EXPECT_TRUE(listed);
}

}  // namespace
}  // namespace seflex
