// Models that read but cannot be assembled or constrained: the fem library must throw InputError
// naming the file:line, the card and field, and what was expected. (Also run under ASan + UBSan.)
#include <gtest/gtest.h>

#include "assembly_test_util.hpp"
#include "nastran_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/loads.hpp"

using namespace seflex;
using seflex::test::assembly_error;
using seflex::test::mentions;
using seflex::test::read_deck;

namespace {

const std::string kBar = "MAT1,1,2.1+11,,0.3,7800.\nPBAR,7,1,1.e-4,1.e-8,2.e-8,0.\n"
                         "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,1.,0.,0.\nGRID,4,,2.,1.,0.\n";

/// The InputError message of applying the constraints (SPC set `spc`, MPC set `mpc`, if any).
std::string constraint_error(const std::string& deck, std::optional<int> spc = std::nullopt,
                             std::optional<int> mpc = std::nullopt) {
  const fem::Model m = read_deck(deck);
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  try {
    fem::ConstraintOptions o;
    o.spc_set = spc;
    o.mpc_set = mpc;
    fem::apply_constraints(m, g, o);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "constraints applied without error";
  return "";
}

}  // namespace

TEST(FemBadInput, BarGeometry) {
  EXPECT_TRUE(mentions(assembly_error(kBar + "CBAR,5,7,2,3,0.,0.,1.\n"),
                       {"deck.bdf:7: CBAR 5", "zero length"}));
  EXPECT_TRUE(mentions(assembly_error(kBar + "CBAR,5,7,1,2,1.,0.,0.\n"),
                       {"deck.bdf:7: CBAR 5, field 6-8 (X1-X3)", "parallel to the bar axis"}));
  EXPECT_TRUE(mentions(assembly_error(kBar + "CBAR,5,7,1,2,3\n"), {"deck.bdf:7: CBAR 5, field 6 (G0)", "parallel"}));
}

TEST(FemBadInput, PinFlagWithoutStiffness) {
  // J = 0: releasing the torsion (4) at end A has nothing to release
  EXPECT_TRUE(mentions(assembly_error(kBar + "CBAR,5,7,1,2,0.,0.,1.\n,4\n"),
                       {"deck.bdf:7: CBAR 5, field PA/PB", "PA = '4'", "no stiffness"}));
  // releasing the transverse translation at both ends leaves a mechanism
  EXPECT_TRUE(mentions(assembly_error(kBar + "CBAR,5,7,1,2,0.,0.,1.\n,26,26\n"), {"deck.bdf:7: CBAR 5, field PA/PB: pin flags PA = '26', PB = '26' release degrees of freedom the bar has no "
                        "stiffness for (or leave a mechanism)"}));
}

TEST(FemBadInput, ShellGeometry) {
  const std::string d = "MAT1,1,2.1+11,,0.3,7800.\nPSHELL,1,1,0.002,1\n"
                        "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,0.2,0.2,0.\nGRID,4,,0.,1.,0.\nGRID,5,,2.,0.,0.\n";
  EXPECT_TRUE(mentions(assembly_error(d + "CQUAD4,9,1,1,2,3,4\n"),
                       {"deck.bdf:8: CQUAD4 9, field 4-7 (G1-G4)", "convex quadrilateral"}));
  EXPECT_TRUE(mentions(assembly_error(d + "CQUAD4,9,1,1,4,3,2\n"), {"deck.bdf:8: CQUAD4 9, field 4-7 (G1-G4): corners must form a convex quadrilateral, ordered around its "
                        "edge (interior angles < 180 deg)"}));
  EXPECT_TRUE(mentions(assembly_error(d + "CTRIA3,9,1,1,2,5\n"), {"deck.bdf:8: CTRIA3 9, field 4-6 (G1-G3)", "collinear"}));
}

TEST(FemBadInput, ConflictingConstraints) {
  const std::string d = kBar + "CBAR,5,7,1,2,0.,0.,1.\nCBAR,6,7,2,4,0.,0.,1.\n";
  // a dependent component that is also a GRID PS constraint
  EXPECT_TRUE(mentions(constraint_error(d + "RBE2,20,1,123,4\nGRID,9,,5.,5.,5.,,3\nRBE2,21,2,3,9\n"),
                       {"deck.bdf:11: RBE2 21: grid 9 component 3 is dependent here but also constrained by PS on GRID 9 "
                        "(deck.bdf:10)", "m-set and the s-set do not overlap"}));
  // a component made dependent by two RBE2s: both cards named
  EXPECT_TRUE(mentions(constraint_error(d + "RBE2,20,1,123,4\nRBE2,21,2,12,4\n"),
                       {"deck.bdf:10: RBE2 21: grid 4 component 1 is made dependent here and by RBE2 20 (deck.bdf:9)"}));
  // RBE2s that depend on each other in a loop
  EXPECT_TRUE(mentions(constraint_error(d + "RBE2,20,1,123456,4\nRBE2,21,4,123456,2\nRBE2,22,2,123456,1\n"),
                       {"deck.bdf:10: RBE2 21: its dependent grid 2 component 6 depends on grid 4 component 6, which depends back "
                        "on it through RBE2 20 (deck.bdf:9); expected no closed loop of dependencies"}));
}

// A dof made dependent twice (by two constraints, or dependent and constrained): InputError naming
// both cards with file:line, as Nastran's m-set must not overlap itself or the s-set.
TEST(FemBadInput, DependentDofAppearsTwice) {
  const std::string d = kBar + "CBAR,5,7,1,2,0.,0.,1.\nCBAR,6,7,2,4,0.,0.,1.\nGRID,9,,1.,1.,1.\nGRID,8,,2.,2.,0.\n";
  // the reference grid of an RBE3 (dependent by default) and the first dof of an MPC equation
  EXPECT_TRUE(mentions(constraint_error(d + "RBE3,30,,9,123,1.,123,1,2\n,4\nMPC,5,9,2,1.,4,2,-1.\n", std::nullopt, 5),
                       {"deck.bdf:13: MPC set 5: grid 9 component 2 is made dependent here and by RBE3 30 (deck.bdf:11)",
                        "one rigid element or MPC equation"}));
  // a dependent end of an RBAR that an SPC of the selected set also holds
  EXPECT_TRUE(mentions(constraint_error(d + "RBAR,31,4,8,123456\nSPC1,1,3,8\n", 1),
                       {"deck.bdf:11: RBAR 31: grid 8 component 3 is dependent here but also constrained by SPC/SPC1 set 1 "
                        "(deck.bdf:12)"}));
  // an RBE2 dependent also made dependent by an RBE3 through UM
  EXPECT_TRUE(mentions(constraint_error(d + "RBE2,32,4,123,8\nRBE3,33,,9,1,1.,123,1,2\n,8\n,UM,8,1\n"),
                       {"RBE3 33: grid 8 component 1 is made dependent here and by RBE2 32 (deck.bdf:11)"}));
  // MPC equations that depend on each other in a loop
  EXPECT_TRUE(mentions(constraint_error(d + "MPC,6,8,1,1.,9,1,-1.\nMPC,6,9,1,1.,8,1,-2.\n", std::nullopt, 6),
                       {"MPC set 6", "depends back on it", "closed loop"}));
  // a selected MPC set naming a grid that does not exist
  EXPECT_TRUE(mentions(constraint_error(d + "MPC,6,8,1,1.,77,1,-1.\n", std::nullopt, 6),
                       {"deck.bdf:11: MPC 6, field G2: references point 77, which is not defined"}));
  EXPECT_TRUE(mentions(constraint_error(d, std::nullopt, 3), {"case control MPC = 3", "no MPC or MPCADD"}));
}

// Rigid and interpolation elements that do not determine their dependents.
TEST(FemBadInput, UndeterminedRigidAndInterpolationElements) {
  const std::string d = kBar + "CBAR,5,7,1,2,0.,0.,1.\nGRID,8,,3.,0.,0.\nGRID,9,,1.5,1.,0.\n";
  // translations at both ends of a bar along x leave its rotation about x free
  EXPECT_TRUE(mentions(constraint_error(d + "RBAR,40,2,8,123,123\n"),
                       {"deck.bdf:10: RBAR 40, field 5 (CNA)", "cannot describe every rigid-body motion"}));
  // translations of three grids on one line cannot give the rotation about it, nor the off-line
  // reference point's translation
  EXPECT_TRUE(mentions(constraint_error(d + "RBE3,41,,9,123456,1.,123,1,2\n,8\n"),
                       {"deck.bdf:10: RBE3 41, field 5 (REFC)", "is not determined by the independent components"}));
  EXPECT_TRUE(mentions(constraint_error(d + "RBE3,42,,9,12,1.,123,1,2\n,4\n,UM,1,123\n"),
                       {"RBE3 42, field UM", "3 dependent components listed after UM; expected as many as REFC has (2)"}));
  EXPECT_TRUE(mentions(constraint_error(d + "RBE3,43,,9,1,1.,123,1,2\n,4\n,UM,3,1\n"),
                       {"RBE3 43, field CMi (UM)", "component 1 of grid 3 is not in the element"}));
}

TEST(FemBadInput, UndefinedSets) {
  const std::string d = kBar + "CBAR,5,7,1,2,0.,0.,1.\nSPC1,3,123456,1\nFORCE,4,2,,1.,0.,0.,1.\n";
  EXPECT_TRUE(mentions(constraint_error(d, 8), {"case control SPC = 8", "no SPC, SPC1 or SPCADD"}));
  const fem::Model m = read_deck(d);
  const fem::DofMap dofs = fem::make_dof_map(m);
  try {
    fem::load_vector(m, dofs, 12);
    ADD_FAILURE() << "no error for an undefined load set";
  } catch (const InputError& e) {
    EXPECT_TRUE(mentions(e.what(), {"case control LOAD = 12", "no LOAD, FORCE, MOMENT, PLOAD2, PLOAD4, GRAV or RFORCE"}));
  }
  EXPECT_EQ(fem::load_vector(m, dofs, 4)[6 + 2], 1.0);
}

// Shell sections the elements cannot use: the message names the property or element card and field.
TEST(FemBadInput, ShellSections) {
  const std::string g = "MAT1,1,2.1+11,,0.3,7800.\nGRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\n";
  // PSHELL MID4 without MID2, MID4 = MID1, MID3 a MAT8 without G2Z
  EXPECT_TRUE(mentions(assembly_error(g + "MAT2,5,1.+9\nPSHELL,1,1,.002,,,,,,+S\n+S,,,5\nCQUAD4,1,1,1,2,3,4\n"),
                       {"deck.bdf:7: PSHELL 1, field 4 of continuation 1 (MID4): membrane-bending coupling without MID1 and MID2"}));
  EXPECT_TRUE(mentions(assembly_error(g + "PSHELL,1,1,.002,1,,,,,+S\n+S,,,1\nCQUAD4,1,1,1,2,3,4\n"),
                       {"PSHELL 1, field 4 of continuation 1 (MID4): MID4 = 1 is also MID1 or MID2"}));
  EXPECT_TRUE(mentions(assembly_error(g + "MAT8,5,1.+10,1.+9,.3,1.+9,1.+8\nPSHELL,1,1,.002,1,,5\nCQUAD4,1,1,1,2,3,4\n"),
                       {"PSHELL 1, field 7 (MID3): references MAT8 5 whose G1Z or G2Z is blank (infinite)"}));
  // PCOMP: LAM = BEND, corner thicknesses, a MAT1 ply without G
  EXPECT_TRUE(mentions(assembly_error(g + "PCOMP,1,,,,,,,BEND\n,1,.001\nCQUAD4,1,1,1,2,3,4\n"),
                       {"deck.bdf:6: PCOMP 1, field 9 (LAM): BEND is not supported; expected blank, SYM, MEM, SMEAR or SMCORE"}));
  EXPECT_TRUE(mentions(assembly_error(g + "PCOMP,1,,,,,,,\n,1,.001\nCQUAD4,1,1,1,2,3,4\n,,,,.001,.001,.001,.001\n"),
                       {"deck.bdf:8: CQUAD4 1, field T1-T4: corner thicknesses with PCOMP 1; expected them blank"}));
  EXPECT_TRUE(mentions(assembly_error(g + "MAT1,2,2.1+11\nPCOMP,1,,,,,,,\n,2,.001\nCQUAD4,1,1,1,2,3,4\n"),
                       {"PCOMP 1, field MID1: references MAT1 2 with G = 0; expected a ply material with a shear modulus"}));
  // MCID: cylindrical, or an x axis normal to the element
  EXPECT_TRUE(mentions(assembly_error(g + "PSHELL,1,1,.002,1\nCORD2C,5,,0.,0.,0.,0.,0.,1.\n,1.,0.,0.\nCQUAD4,1,1,1,2,3,4,5\n"),
                       {"deck.bdf:9: CQUAD4 1, field 8 (MCID): coordinate system 5 is cylindrical or spherical; expected a rectangular system"}));
  EXPECT_TRUE(mentions(assembly_error(g + "PSHELL,1,1,.002,1\nCORD2R,5,,0.,0.,0.,1.,0.,0.\n,0.,0.,1.\nCTRIA3,1,1,1,2,3,5\n"),
                       {"CTRIA3 1, field 7 (MCID): the x axis of coordinate system 5 is normal to the element"}));
}
