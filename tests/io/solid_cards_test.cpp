// Solids (CHEXA/CPENTA/CTETRA/CPYRAM) with some mid-edge grids blank and MAT9 through the reader and `seflex convert`'s writer:
// what is read (numbers), written back (blank fields where the grids are missing), and the errors
// for a MAT9 where it cannot be used (shells, bars, rods). The numerics of both are tested in
// tests/fem/solid_partial_test.cpp and tests/fem/solid_mat9_test.cpp.
#include <gtest/gtest.h>

#include <sstream>

#include "nastran_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_solid.hpp"
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
// The same material as a MAT9: lambda + 2 mu, lambda, mu of E = 2.1e11, nu = 0.3; A1-A3 = ALPHA.
const std::string kMat9 =
    "MAT9,1,2.8269230769230769+11,1.2115384615384615+11,1.2115384615384615+11,0.,0.,0.,2.8269230769230769+11\n"
    ",1.2115384615384615+11,0.,0.,0.,2.8269230769230769+11,0.,0.,0.\n"
    ",8.0769230769230769+10,0.,0.,8.0769230769230769+10,0.,8.0769230769230769+10,7800.,1.2-5\n"
    ",1.2-5,1.2-5,0.,0.,0.,20.\n";

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
  // A CPYRAM 7 on the bottom face, apex grid 5: G6 (edge 1-2) and G7 (2-3) present; written back.
  const fem::Model y = read_deck(cube(kMat1 + "PSOLID,2,1\nCPYRAM,13,2,1,2,3,4,5,9\n,10\n"));
  ASSERT_EQ(y.solids.size(), 1u);
  EXPECT_STREQ(y.solids[0].card(), "CPYRAM");
  EXPECT_EQ(y.solids[0].nnode, 7);
  EXPECT_EQ(y.solids[0].missing_mid, 0b11111100);
  const fem::Model yb = written_and_read(y);
  ASSERT_EQ(yb.solids.size(), 1u);
  EXPECT_EQ(yb.solids[0].shape, fem::Solid::Shape::Pyram);
  EXPECT_EQ(yb.solids[0].missing_mid, y.solids[0].missing_mid);
  EXPECT_EQ(yb.solids[0].g, y.solids[0].g);
}

TEST(SolidCards, Mat9IsReadWrittenBackAndGivesTheMat1Element) {
  const std::string hexa = "PSOLID,2,1\nCHEXA,10,2,1,2,3,4,5,6\n,7,8\n";
  const fem::Model m9 = read_deck(cube(kMat9 + hexa)), m1 = read_deck(cube(kMat1 + hexa));
  ASSERT_EQ(m9.mat9.size(), 1u);
  const fem::Mat9& mat = m9.mat9[0];
  EXPECT_EQ(mat.id, 1);
  EXPECT_EQ(mat.g[0], 2.8269230769230769e11);  // G11
  EXPECT_EQ(mat.g[6], 2.8269230769230769e11);  // G22
  EXPECT_EQ(mat.g[15], 8.0769230769230769e10);  // G44
  EXPECT_EQ(mat.g[20], 8.0769230769230769e10);  // G66
  EXPECT_EQ(mat.rho, 7800.0);
  EXPECT_EQ(mat.a[0], 1.2e-5);
  EXPECT_EQ(mat.a[2], 1.2e-5);
  EXPECT_EQ(mat.a[3], 0.0);
  EXPECT_EQ(mat.tref, 20.0);
  EXPECT_TRUE(m9.unsupported.empty());
  const fem::GlobalMatrices g9 = fem::assemble(m9, fem::assembly_options(m9)), g1 = fem::assemble(m1, fem::assembly_options(m1));
  EXPECT_LT((g9.K - g1.K).norm(), 1e-12 * g1.K.norm());
  EXPECT_LT((g9.M - g1.M).norm(), 1e-12 * g1.M.norm());
  const fem::Model back = written_and_read(m9);
  ASSERT_EQ(back.mat9.size(), 1u);
  for (std::size_t k = 0; k < 21; ++k) EXPECT_NEAR(back.mat9[0].g[k], mat.g[k], 1e-12 * mat.g[0]) << k;
  EXPECT_EQ(back.mat9[0].a, mat.a);
  EXPECT_EQ(back.mat9[0].rho, mat.rho);
}

TEST(SolidCards, Mat9WhereItCannotBeUsedIsAnError) {
  EXPECT_TRUE(mentions(read_error(cube(kMat9 + "PSHELL,5,1,.01,1\nCQUAD4,20,5,1,2,3,4\n")),
                       {"deck.bdf:", "PSHELL 5, field 3 (MID1): references material 1, a MAT9 (an anisotropic solid material, for PSOLID only)",
                        "expected the id of a MAT1, MAT2 or MAT8 card"}));
  EXPECT_TRUE(mentions(read_error(cube(kMat9 + "PBAR,6,1,1.e-4,1.e-8,1.e-8,2.e-8\nCBAR,21,6,1,2,0.,0.,1.\n")),
                       {"PBAR 6, field 3 (MID): references material 1, a MAT9 (an anisotropic solid material, for PSOLID only); "
                        "expected the id of a MAT1 card"}));
  EXPECT_TRUE(mentions(read_error(cube(kMat9 + "PROD,7,1,1.e-4\nCROD,22,7,1,2\n")), {"PROD 7, field 3 (MID)", "a MAT9"}));
  // reader: a diagonal term that is not positive
  EXPECT_TRUE(mentions(read_error("MAT9,3,1.e9,,,,,,-1.\n"), {"deck.bdf:1: MAT9 3", "G22", "expected a diagonal modulus > 0"}));
}

}  // namespace
}  // namespace seflex
