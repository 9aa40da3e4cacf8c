// The cautions of solutions::check_card_usage (a bar without torsional stiffness, plates thick for
// their mesh, RFORCE's unit) reach the user as warnings on stderr from every command, with count and
// first file:line, and seflex info lists them in their own group; the commands still run.
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace seflex {
namespace {

/// A cantilever of two CBARs on PBAR 1 (J blank: 0) along x, clamped at grid 1; SOL 105 with an
/// axial preload (LOAD 7) and EIGRL 3.
std::string column_deck() {
  return "SOL 105\nCEND\nSPC = 1\nSUBCASE 1\nLOAD = 7\nSUBCASE 2\nMETHOD = 3\nBEGIN BULK\n"
         "MAT1,1,7.e10,,0.3,2700.\nPBAR,1,1,1.e-4,2.e-8,2.e-8\n"  // PBAR: line 10
         "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,2.,0.,0.\nCBAR,1,1,1,2,0.,1.,0.\nCBAR,2,1,2,3,0.,1.,0.\n"
         "SPC1,1,123456,1\nFORCE,7,3,0,-1.,1.,0.,0.\nEIGRL,3,,,2\nENDDATA\n";
}

TEST(CautionCli, BucklingOfABarWithoutTorsionalStiffnessWarns) {
  test::TempDir dir;
  dir.write("column.bdf", column_deck());
  const auto r = test::run_seflex("buckling column.bdf", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: PBAR: 1 card, first at column.bdf:10: PBAR 1 (2 CBAR elements): J = 0, no torsional "
                       "stiffness: the twist of these elements about their axis is held only by what they connect to "
                       "(other elements, SPC, or AUTOSPC where nothing else holds it); in buckling the torsion (Wagner) "
                       "term N (I1 + I2) / (A L) of the bar's differential stiffness couples the twist to the bending "
                       "rotations, so the load factors depend on those constraints; give J if the section has "
                       "torsional stiffness\n"),
            std::string::npos)
      << r.err;
  // seflex info: its own group
  const auto info = test::run_seflex("info column.bdf", dir.path());
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("  computed as written, with a consequence to check (warning)\n    PBAR: 1 card, first at "
                          "column.bdf:10: PBAR 1 (2 CBAR elements): J = 0"),
            std::string::npos)
      << info.out;
}

TEST(CautionCli, StaticWithRforceStatesTheAngularVelocity) {
  const std::string deck = std::string(SEFLEX_TEST_DATA) + "/validation/mystran_static_loads/BAR-RFORCE-OFFSET.DAT";
  test::TempDir dir;
  const auto r = test::run_seflex("static '" + deck + "' -o u.csv", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("BAR-RFORCE-OFFSET.DAT:29: load set 61: A = 20 revolutions per unit time (MSC Nastran QRG): "
                       "angular velocity 125.66 rad per unit time; if A was meant in rad per unit time, give A = 3.1831\n"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("warning: RFORCE: 1 card, first at "), std::string::npos) << r.err;
}

TEST(CautionCli, ModesOfAThickPlateWarnAndTheDemoMeshesDoNot) {
  const std::string deck = std::string(SEFLEX_TEST_DATA) + "/validation/mystran_static_loads/AQ3U2S004.DAT";
  test::TempDir dir;
  const auto r = test::run_seflex("modes '" + deck + "' --count 2", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("AQ3U2S004.DAT:49: thick for their size (first: element 1001; t / sqrt(area) up to 0.8, above "
                       "0.5): transverse shear governs their bending and the element converges slowly on such a mesh; "
                       "check the higher modes and the stresses with a finer mesh\n"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("warning: CQUAD4: 16 cards, first at "), std::string::npos) << r.err;
  // the demo meshes: every card used, nothing to warn about
  for (const char* mesh : {"meshes/panel.bdf", "meshes/yoke.bdf"}) {
    const auto info = test::run_seflex(std::string("info '") + SEFLEX_SOURCE_DIR + "/" + mesh + "'", dir.path());
    ASSERT_EQ(info.exit_code, 0) << info.err;
    EXPECT_NE(info.out.find("  every card is used\n"), std::string::npos) << mesh << "\n" << info.out;
  }
}

}  // namespace
}  // namespace seflex
