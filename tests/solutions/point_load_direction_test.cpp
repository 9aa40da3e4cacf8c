// FORCE1, FORCE2, MOMENT1, MOMENT2: loads whose direction comes from grid positions (QRG: G1 -> G2;
// (G1 -> G2) x (G3 -> G4)), taken at the undeformed geometry as linear Nastran does. Checked against
// directions worked out by hand below, on a grid whose displacement system is rotated, with a
// direction grid given in a cylindrical system; through LOAD, a static solution on springs, the
// writer and back; and the refusals by their whole message.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <sstream>
#include <string>

#include "nastran_test_util.hpp"
#include "statics_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/loads.hpp"
#include "seflex/io/nastran_writer.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

// Grid 5 carries the loads; its displacement system 9 has x' = basic y, z' = basic z, so
// y' = z' x x' = -basic x: a basic vector (a, b, c) has the CD components (b, -a, c).
// Direction grids: 6 at the origin, 7 at (3, 4, 0) given in cylindrical system 8 as r = 5,
// theta = atan2(4, 3) = 53.130102354155978 degrees, 11 at (0, 0, 2).
const std::string kGrids =
    "CORD2R,9,,0.,0.,0.,0.,0.,1.,\n,0.,1.,0.\n"
    "CORD2C,8,,0.,0.,0.,0.,0.,1.,\n,1.,0.,0.\n"
    "GRID,5,,1.,2.,3.,9\nGRID,6,,0.,0.,0.\nGRID,7,8,5.,53.130102354155978,0.\nGRID,11,,0.,0.,2.\n";

Eigen::VectorXd grid5_load(const fem::Model& m, int sid) {
  const fem::DofMap dofs = fem::make_dof_map(m);
  const Eigen::VectorXd p = fem::load_vector(m, dofs, sid);
  Eigen::VectorXd g5(6);
  for (int c = 1; c <= 6; ++c) g5[c - 1] = p[*fem::find_dof(m, dofs, 5, c)];
  return g5;
}

TEST(PointLoadDirection, Force1AndMoment1AlongTwoGrids) {
  // G1 -> G2 = (3, 4, 0) / 5: F = 10 gives basic (6, 8, 0), CD (8, -6, 0); MOMENT1 M = -2 the
  // moment basic (-1.2, -1.6, 0), CD (-1.6, 1.2, 0).
  const fem::Model m = test::read_deck(kGrids + "FORCE1,1,5,10.,6,7\nMOMENT1,1,5,-2.,6,7\n");
  Eigen::VectorXd expected(6);
  expected << 8, -6, 0, -1.6, 1.2, 0;
  EXPECT_LT((grid5_load(m, 1) - expected).norm(), 1e-13) << grid5_load(m, 1).transpose();
}

TEST(PointLoadDirection, Force2AndMoment2AlongACrossProduct) {
  // (G1 -> G2) x (G3 -> G4) = (3, 4, 0) x (0, 0, 2) = (8, -6, 0): unit (0.8, -0.6, 0). FORCE2 F = 5:
  // basic (4, -3, 0), CD (-3, -4, 0). MOMENT2 with G3 -> G4 = 11 -> 6 = (0, 0, -2): the opposite
  // direction; M = 3: basic (-2.4, 1.8, 0), CD (1.8, 2.4, 0). G2 = G3 as the public decks write it.
  const fem::Model m = test::read_deck(kGrids + "FORCE2,1,5,5.,6,7,6,11\nMOMENT2,1,5,3.,6,7,11,6\n");
  Eigen::VectorXd expected(6);
  expected << -3, -4, 0, 1.8, 2.4, 0;
  EXPECT_LT((grid5_load(m, 1) - expected).norm(), 1e-13) << grid5_load(m, 1).transpose();
  const fem::Model shared = test::read_deck(kGrids + "FORCE2,1,5,5.,6,7,7,11\n");  // (3,4,0) x (-3,-4,2) = (8,-6,0)
  EXPECT_LT((grid5_load(shared, 1).head<3>() - expected.head<3>()).norm(), 1e-13);
}

// Through a LOAD combination into a static solution: grid 5 held by six grounded springs of stiffness
// k (in its CD system) moves by p / k; the writer gives back the same cards.
TEST(PointLoadDirection, StaticSolutionThroughLoadAndWriter) {
  std::string deck = "SOL 101\nCEND\nLOAD = 3\nBEGIN BULK\n" + kGrids +
                     "SPC1,1,123456,6,7,11\nFORCE1,1,5,10.,6,7\nMOMENT2,2,5,3.,6,7,11,6\nLOAD,3,2.,1.,1,0.5,2\n";
  for (int c = 1; c <= 6; ++c) deck += "CELAS2," + std::to_string(20 + c) + ",4.,5," + std::to_string(c) + "\n";
  const fem::Model m = test::read_deck(deck + "ENDDATA\n");
  // p = 2 (F1 + 0.5 M2) = 2 ((8, -6, 0) + 0.5 (1.8, 2.4, 0) on the rotations); u = p / 4
  Eigen::VectorXd expected(6);
  expected << 4, -3, 0, 0.45, 0.6, 0;
  for (const fem::Model* model : {&m}) {
    const auto s = solutions::solve_static(*model);
    for (int c = 1; c <= 6; ++c) EXPECT_NEAR(test::displacement(*model, s, 5, c), expected[c - 1], 1e-13) << c;
  }
  std::ostringstream out;
  io::write_nastran(m, out);
  EXPECT_NE(out.str().find("FORCE1,1,5,10.,6,7"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("MOMENT2,2,5,3.,6,7,11,6"), std::string::npos) << out.str();
  const fem::Model back = test::read_deck(out.str(), "converted.bdf");
  const auto s = solutions::solve_static(back);
  for (int c = 1; c <= 6; ++c) EXPECT_NEAR(test::displacement(back, s, 5, c), expected[c - 1], 1e-13) << c;
}

std::string load_error(const std::string& cards) {
  try {
    const fem::Model m = test::read_deck(kGrids + cards);
    grid5_load(m, 1);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for " << cards;
  return "";
}

TEST(PointLoadDirection, RefusalsNameCardFieldAndWhatWasExpected) {
  EXPECT_EQ(test::read_error("FORCE1,1,5,10.,6,6\n"),
            "deck.bdf:1: FORCE1 1, field 6 (G2): grid 6 is also G1; expected two distinct grids to give a direction");
  EXPECT_EQ(test::read_error("MOMENT2,1,5,10.,6,7,11,11\n"),
            "deck.bdf:1: MOMENT2 1, field 8 (G4): grid 11 is also G3; expected two distinct grids to give a direction");
  EXPECT_EQ(test::read_error("FORCE2,1,5,10.,6,7,6\n"), "deck.bdf:1: FORCE2 1, field 8 (G4): blank; expected an integer > 0");
  EXPECT_EQ(test::read_error("FORCE1,1,5,10.,6,7,8\n"), "deck.bdf:1: FORCE1 1, field 7 (): got integer '8' after G2; expected nothing more");
  EXPECT_EQ(load_error("GRID,12,,0.,0.,0.\nFORCE1,1,5,10.,6,12\n"),
            "deck.bdf:10: FORCE1 1, field 5 (G1): grids G1 and G2 are at the same point; expected a direction G1 -> G2");
  EXPECT_EQ(load_error("GRID,12,,6.,8.,0.\nFORCE2,1,5,10.,6,7,6,12\n"),
            "deck.bdf:10: FORCE2 1, field 5 (G1): G1 -> G2 and G3 -> G4 are parallel; expected two directions whose cross "
            "product gives the load's");
  EXPECT_EQ(load_error("MOMENT1,1,5,10.,6,99\n"),
            "deck.bdf:9: MOMENT1 1, field 6 (G2): references GRID 99, which is not defined");
}

// SLOAD on a scalar point and on a grid (its T1, in the CD system); PLOAD on a triangle (P A along
// (G1 -> G2) x (G1 -> G3), a third per grid) and on a quadrilateral (the triangles 123, 234, 341, 412
// with P/2 each: QRG PLOAD remarks), by hand below.
TEST(PointLoadDirection, SloadAndPload) {
  const fem::Model m = test::read_deck(kGrids + "SPOINT,30\nSLOAD,1,30,2.5,5,-1.5\n"
                                                "GRID,21,,0.,0.,0.\nGRID,22,,2.,0.,0.\nGRID,23,,2.,1.,0.\nGRID,24,,0.,3.,0.\n"
                                                "PLOAD,2,6.,21,22,23\nPLOAD,3,6.,21,22,23,24\n");
  const fem::DofMap dofs = fem::make_dof_map(m);
  const Eigen::VectorXd p1 = fem::load_vector(m, dofs, 1);
  EXPECT_EQ(p1[*fem::find_dof(m, dofs, 30, 0)], 2.5);
  EXPECT_EQ(p1[*fem::find_dof(m, dofs, 5, 1)], -1.5);  // grid 5's T1 in its CD system 9
  EXPECT_EQ(p1.cwiseAbs().sum(), 4.0);
  // triangle 21-22-23: area 1, normal +z: 6 x 1 / 3 = 2 on each grid
  const Eigen::VectorXd p2 = fem::load_vector(m, dofs, 2);
  for (const int g : {21, 22, 23}) EXPECT_NEAR(p2[*fem::find_dof(m, dofs, g, 3)], 2.0, 1e-15) << g;
  // quadrilateral 21-22-23-24 (area 4): triangle areas 123: 1, 234: 1, 341: 3, 412: 3 (all normal +z),
  // each loaded by P/2 = 3, a third per grid: grid 21 (in 123, 341, 412) 1 + 3 + 3 = 7; 22 (123, 234,
  // 412) 5; 23 (123, 234, 341) 5; 24 (234, 341, 412) 7; total 24 = P x area
  const Eigen::VectorXd p3 = fem::load_vector(m, dofs, 3);
  const double expected[4] = {7, 5, 5, 7};
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(p3[*fem::find_dof(m, dofs, 21 + k, 3)], expected[k], 1e-14) << 21 + k;
  std::ostringstream out;
  io::write_nastran(m, out);
  const fem::Model back = test::read_deck(out.str(), "converted.bdf");
  EXPECT_EQ((fem::load_vector(back, fem::make_dof_map(back), 3) - p3).norm(), 0.0);
  EXPECT_EQ(test::read_error("PLOAD,2,6.,21,22,21\n"), "deck.bdf:1: PLOAD 2, field 6 (G3): grid 21 repeats G1; expected distinct grids");
}

}  // namespace
}  // namespace seflex
