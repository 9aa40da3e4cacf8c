// CHEXA/CPENTA/CTETRA/CPYRAM, PSOLID and PLOAD4: what the reader accepts, and the errors (file:line, card,
// field, what was expected) for what it refuses or cannot use.
#include <gtest/gtest.h>

#include "nastran_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/loads.hpp"

using namespace seflex;
using seflex::test::mentions;
using seflex::test::read_deck;
using seflex::test::read_error;

namespace {

/// A unit cube CHEXA 10 (PSOLID 2, MAT1 1) on grids 1-8; `more` appended.
std::string cube(const std::string& more, const std::string& psolid = "PSOLID,2,1\n") {
  return "MAT1,1,2.1+11,,0.3,7800.\n" + psolid +
         "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\n"
         "GRID,5,,0.,0.,1.\nGRID,6,,1.,0.,1.\nGRID,7,,1.,1.,1.\nGRID,8,,0.,1.,1.\n"
         "CHEXA,10,2,1,2,3,4,5,6\n,7,8\n" + more;
}

std::string load_error(const std::string& deck, int sid) {
  const fem::Model m = read_deck(deck);
  try {
    fem::load_vector(m, fem::make_dof_map(m), sid);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "load vector built without error";
  return "";
}

TEST(SolidInput, CardsAreReadWithTheirDefaults) {
  const fem::Model m = read_deck(cube("PLOAD4,3,10,2.,,,,1,7\n,,0.,0.,1.\nPLOAD4,4,10,1.,2.,3.,4.,THRU,12\n"));
  ASSERT_EQ(m.solids.size(), 1u);
  EXPECT_EQ(m.solids[0].nnode, 8);
  EXPECT_EQ(m.solids[0].g[7], 8);
  ASSERT_EQ(m.solid_props.size(), 1u);
  EXPECT_EQ(m.solid_props[0].in, fem::SolidProperty::Integration::Default);
  ASSERT_EQ(m.face_loads.size(), 2u);
  EXPECT_EQ(m.face_loads[0].p[3], 2.0);  // blank P2-P4 = P1
  EXPECT_EQ(m.face_loads[0].g34, 7);
  EXPECT_EQ(m.face_loads[0].n.z(), 1.0);
  EXPECT_EQ(m.face_loads[1].eid_last, 12);
  EXPECT_EQ(m.face_loads[1].p[3], 4.0);
  // A uniform pressure on the face x = 1 (G1 = 2, G3 = 7) pushes along -x with p A.
  const fem::Model m2 = read_deck(cube("PLOAD4,5,10,3.,,,,2,7\n"));
  const fem::DofMap dofs = fem::make_dof_map(m2);
  const Eigen::VectorXd f = fem::load_vector(m2, dofs, 5);
  double Fx = 0;
  for (Eigen::Index gi = 0; gi < 8; ++gi) Fx += f[dofs.grid_dof(gi, 1)];
  EXPECT_NEAR(Fx, -3.0, 1e-12);
}

TEST(SolidInput, ReaderErrorsNameTheField) {
  {  // some mid-edge grids: read (a blank one is a straight edge); an undefined one is named by its QRG field
    EXPECT_TRUE(mentions(read_error(cube("CHEXA,11,2,1,2,3,4,5,6\n,7,8,,99\n")), {"CHEXA 11, G10: references grid 99, which is not defined"}));
    EXPECT_TRUE(mentions(read_error(cube("CHEXA,11,2,1,2,3,4,5,6\n,7,8,,3\n")), {"CHEXA 11", "G10", "grid 3 repeats G3"}));
  }
  EXPECT_TRUE(mentions(read_error(cube("CTETRA,11,2,1,2,3,3\n")), {"deck.bdf:13: CTETRA 11, field 7 (G4): grid 3 repeats G3; expected distinct grids"}));
  EXPECT_TRUE(mentions(read_error(cube("", "PSOLID,2,1,,,,,FFLUID\n")), {"PSOLID 2", "FCTN", "expected SMECH, PFLUID (a fluid, listed as unsupported) or blank"}));
  EXPECT_TRUE(mentions(read_error(cube("", "PSOLID,2,1,,FOUR\n")), {"PSOLID 2", "IN", "0/BUBBLE, 2/TWO, 3/THREE"}));
  EXPECT_TRUE(mentions(read_error(cube("PLOAD4,3,10,1.,,,,1,7\n,,0.,0.,1.,LINE\n")), {"PLOAD4 3", "SORL", "edge line loads"}));
}

TEST(SolidInput, ModelErrorsNameTheCard) {
  // PSOLID referencing a material that is not a MAT1; reduced shear integration of a CHEXA 8 (IN =
  // TWO) is modelled (tests/fem/solid_thermal_test.cpp).
  EXPECT_TRUE(mentions(test::read_error(cube("", "PSOLID,2,9\n")), {"deck.bdf:2: PSOLID 2, field 3 (MID): references MAT1 9, which is not defined; expected the id of a MAT1 or MAT9 card"}));
  {
    const fem::Model m = read_deck(cube("", "PSOLID,2,1,,TWO\n"));
    EXPECT_NO_THROW(fem::assemble(m, fem::assembly_options(m)));
  }
  // PLOAD4 face selection.
  EXPECT_TRUE(mentions(load_error(cube("PLOAD4,3,10,1.\n"), 3), {"PLOAD4 3", "element 10 (CHEXA)", "G1 is blank"}));
  EXPECT_TRUE(mentions(load_error(cube("PLOAD4,3,10,1.,,,,1,7\n"), 3), {"PLOAD4 3", "G3", "not diagonally opposite"}));
  EXPECT_TRUE(mentions(load_error(cube("PLOAD4,3,10,1.,,,,1,2\n"), 3), {"not diagonally opposite"}));
  EXPECT_TRUE(mentions(load_error(cube("PLOAD4,3,10,1.,,,,99,7\n"), 3), {"G1", "grid 99 is not a corner grid"}));
  EXPECT_TRUE(mentions(load_error(cube("PLOAD4,3,77,1.\n"), 3), {"PLOAD4 3", "element 77 is not defined", "CHEXA, CPENTA, CTETRA or CPYRAM"}));
}

// CPYRAM on the cube's top face (apex grid 9 at z = 2): read, loaded, and refused with its card and
// field when its grids are wrong or the element has no volume.
TEST(SolidInput, PyramidIsReadAndItsErrorsNameTheField) {
  const std::string apex = "GRID,9,,.5,.5,2.\n";
  {
    const fem::Model m = read_deck(cube(apex + "CPYRAM,11,2,5,6,7,8,9\nPLOAD4,5,11,3.,,,,5,6\nPLOAD4,6,11,3.,,,,5,7\n"));
    ASSERT_EQ(m.solids.size(), 2u);
    EXPECT_EQ(m.solids[1].shape, fem::Solid::Shape::Pyram);
    EXPECT_EQ(m.solids[1].nnode, 5);
    EXPECT_NO_THROW(fem::assemble(m, fem::assembly_options(m)));
    const fem::DofMap dofs = fem::make_dof_map(m);
    // Triangle 5 6 9 (G1, G3 adjacent base corners, QRG PLOAD4): area vector (0, -1/2, 1/4) outward,
    // 3 pushes inward: (0, 1.5, -0.75). Base 5 6 7 8 (G1, G3 diagonal): area 1, normal -z outward.
    for (const auto& [sid, F] : {std::pair{5, Eigen::Vector3d(0, 1.5, -0.75)}, std::pair{6, Eigen::Vector3d(0, 0, 3)}}) {
      const Eigen::VectorXd f = fem::load_vector(m, dofs, sid);
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (Eigen::Index gi = 0; gi < 9; ++gi)
        for (int c = 0; c < 3; ++c) sum[c] += f[dofs.grid_dof(gi, c + 1)];
      EXPECT_LT((sum - F).norm(), 1e-12) << "PLOAD4 " << sid << ": " << sum.transpose();
    }
  }
  {  // 13 grids with some mid-edge grids blank
    const fem::Model m = read_deck(cube(apex + "GRID,10,,.5,0.,1.\nGRID,11,,.25,.25,1.5\nCPYRAM,11,2,5,6,7,8,9,10\n,,,,11\n"));
    EXPECT_EQ(m.solids[1].nnode, 7);
    EXPECT_EQ(m.solids[1].missing_mid, 0xFE & ~0x10);
    EXPECT_NO_THROW(fem::assemble(m, fem::assembly_options(m)));
  }
  EXPECT_TRUE(mentions(read_error(cube(apex + "CPYRAM,11,2,5,6,7,8\n")), {"deck.bdf:14: CPYRAM 11", "G5"}));
  EXPECT_TRUE(mentions(read_error(cube(apex + "CPYRAM,11,2,5,6,7,8,9,1\n,2,3,4,1,2,3,4,9\n")),
                       {"deck.bdf:15: CPYRAM 11, field 9 (G)", "expected at most 13 grids"}));
  EXPECT_TRUE(mentions(read_error(cube(apex + "CPYRAM,11,2,5,6,7,7,9\n")), {"CPYRAM 11", "G4", "grid 7 repeats G3; expected distinct grids"}));
  // The apex in the plane of the base: no volume.
  {
    const fem::Model m = read_deck(cube("GRID,9,,.5,.5,1.\nCPYRAM,11,2,5,6,7,8,9\n"));
    EXPECT_TRUE(mentions(test::input_error([&] { fem::assemble(m, fem::assembly_options(m)); }),
                         {"deck.bdf:14: CPYRAM 11", "degenerate or distorted"}));
  }
  EXPECT_TRUE(mentions(load_error(cube(apex + "CPYRAM,11,2,5,6,7,8,9\nPLOAD4,3,11,1.,,,,5\n"), 3),
                       {"PLOAD4 3", "element 11 (CPYRAM)", "G3 is blank"}));
  EXPECT_TRUE(mentions(load_error(cube(apex + "CPYRAM,11,2,5,6,7,8,9\nPLOAD4,3,11,1.,,,,9,5\n"), 3),
                       {"PLOAD4 3", "nor adjacent corners of the base"}));
}

}  // namespace
