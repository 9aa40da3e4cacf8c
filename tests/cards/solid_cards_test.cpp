// Solids with some mid-edge grids blank through the reader and `seflex convert`'s writer: what is
// read (numbers) and written back (blank fields where the grids are missing). The numerics are
// tested in tests/fem/solid_partial_test.cpp.
#include <gtest/gtest.h>

#include <sstream>

#include "nastran_test_util.hpp"
#include "seflex/io/nastran_writer.hpp"

namespace seflex {
namespace {

using test::mentions;
using test::read_deck;
using test::read_error;

fem::Model written_and_read(const fem::Model& m) {
  std::ostringstream out;
  io::write_nastran(m, out);
  return read_deck(out.str(), "converted.bdf");
}

/// A unit cube's 8 corners (grids 1-8), mid-edge grids 9 (edge 1-2), 10 (2-3) and 15 (3-7), then `more`.
std::string cube(const std::string& more) {
  return "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\n"
         "GRID,5,,0.,0.,1.\nGRID,6,,1.,0.,1.\nGRID,7,,1.,1.,1.\nGRID,8,,0.,1.,1.\n"
         "GRID,9,,.5,0.,0.\nGRID,10,,1.,.5,0.\nGRID,15,,1.,1.,.5\n" + more;
}

const std::string kMat1 = "MAT1,1,2.1+11,,0.3,7800.,1.2-5,20.\n";

TEST(SolidCards, SomeMidEdgeGridsAreReadAndWrittenBack) {
  // G9 (edge 1-2) and G10 (2-3) present, G11-G14 blank, G15 (edge 3-7) present, G16-G20 blank.
  const fem::Model m = read_deck(cube(kMat1 + "PSOLID,2,1\nCHEXA,10,2,1,2,3,4,5,6\n,7,8,9,10\n,15\n"));
  ASSERT_EQ(m.solids.size(), 1u);
  const fem::Solid& s = m.solids[0];
  EXPECT_EQ(s.nnode, 11);
  EXPECT_EQ(s.g[8], 9);
  EXPECT_EQ(s.g[9], 10);
  EXPECT_EQ(s.g[10], 15);
  EXPECT_EQ(s.missing_mid, 0b111110111100);  // present: edges 0, 1 and 6 (G9, G10, G15)
  EXPECT_EQ(s.grid_number(10), 15);
  EXPECT_TRUE(m.unsupported.empty());
  const fem::Model back = written_and_read(m);
  ASSERT_EQ(back.solids.size(), 1u);
  EXPECT_EQ(back.solids[0].nnode, s.nnode);
  EXPECT_EQ(back.solids[0].missing_mid, s.missing_mid);
  EXPECT_EQ(back.solids[0].g, s.g);
  // A CPENTA 7 and a CTETRA 9: the same rule.
  const fem::Model p = read_deck(cube(kMat1 + "PSOLID,2,1\nCPENTA,11,2,1,2,3,5,6,7\n,,,,,,15\nCTETRA,12,2,1,2,3,5,9,10\n"));
  ASSERT_EQ(p.solids.size(), 2u);
  EXPECT_EQ(p.solids[0].nnode, 7);
  EXPECT_EQ(p.solids[0].missing_mid, 0b111011111);  // only G12 (edge 3-6) present
  EXPECT_EQ(p.solids[1].nnode, 6);
  EXPECT_EQ(p.solids[1].missing_mid, 0b111100);  // G5 (edge 1-2) and G6 (2-3) present
}

}  // namespace
}  // namespace seflex
