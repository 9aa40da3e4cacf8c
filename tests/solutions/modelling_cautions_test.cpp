// Cautions of solutions::check_card_usage (solutions/src/modelling_cautions.hpp): what a deck asks
// for and seflex computes as written, with a consequence the user is told in a warning: a bar
// without torsional stiffness (J = 0), plates thick for their mesh, RFORCE's unit. Each message is
// asserted whole, and each is absent from ordinary decks (the demo meshes, the examples, the
// validation decks). Also run under ASan + UBSan.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "nastran_test_util.hpp"
#include "seflex/io/nastran.hpp"
#include "seflex/solutions/buckling.hpp"
#include "seflex/solutions/card_usage.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

using solutions::CardUse;
using solutions::Solution;

solutions::CardUsage usage(const fem::Model& m, Solution s) {
  if (s == Solution::Buckling) {
    const auto [preload, buckle] = solutions::buckling_cases(m);
    return solutions::check_card_usage(m, s, {preload, buckle});
  }
  const auto cases = s == Solution::Statics ? solutions::select_cases(m) : std::vector{solutions::select_case(m)};
  return solutions::check_card_usage(m, s, cases);
}

/// The Caution entries of `u`, described ("CARD: N cards, first at file:line: reason").
std::vector<std::string> cautions(const fem::Model& m, const solutions::CardUsage& u) {
  std::vector<std::string> out;
  for (const CardUse& e : u.uses)
    if (e.kind == CardUse::Kind::Caution) out.push_back(solutions::describe(m, e));
  return out;
}

/// A clamped two-bar cantilever along x (grids 1-3) on PBAR 1 (`pbar`), tip FORCE in set 7, SPC 1.
std::string cantilever(const std::string& case_control, const std::string& pbar, const std::string& more = "") {
  return "SOL 101\nCEND\n" + case_control + "BEGIN BULK\nMAT1,1,7.e10,,0.3,2700.\n" + pbar +  // line 7
         "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,2.,0.,0.\n"
         "CBAR,1,1,1,2,0.,1.,0.\nCBAR,2,1,2,3,0.,1.,0.\nSPC1,1,123456,1\nFORCE,7,3,0,1.,0.,0.,1.\n" + more +
         "ENDDATA\n";
}

const std::string kPbarNoJ = "PBAR,1,1,1.e-4,2.e-8,2.e-8\n";        // J blank: 0
const std::string kPbarJ = "PBAR,1,1,1.e-4,2.e-8,2.e-8,4.e-8\n";

TEST(ModellingCautions, BarWithoutTorsionalStiffnessIsNamedWithItsElements) {
  // PBAR 1 (J blank) on both CBARs; PBAR 2 (J = 0 too) used by no element: not named
  const fem::Model m = test::read_deck(cantilever("SPC = 1\nLOAD = 7\n", kPbarNoJ, "PBAR,2,1,1.e-4,1.e-8,1.e-8,0.\n"));
  const auto statics = usage(m, Solution::Statics);
  EXPECT_FALSE(statics.refused());
  EXPECT_EQ(cautions(m, statics),
            std::vector<std::string>{
                "PBAR: 1 card, first at deck.bdf:7: PBAR 1 (2 CBAR elements): J = 0, no torsional stiffness: the twist "
                "of these elements about their axis is held only by what they connect to (other elements, SPC, or "
                "AUTOSPC where nothing else holds it); give J if the section has torsional stiffness"});
  EXPECT_NO_THROW(solutions::solve_static(m));  // a warning, not a refusal: the clamp holds the twist
  // normal modes: the same
  EXPECT_EQ(cautions(m, usage(m, Solution::NormalModes)), cautions(m, statics));

  // buckling: what the torsion term of the differential stiffness does with it
  const fem::Model b = test::read_deck(
      "SOL 105\nCEND\nSPC = 1\nSUBCASE 1\nLOAD = 7\nSUBCASE 2\nMETHOD = 3\nBEGIN BULK\nMAT1,1,7.e10,,0.3,2700.\n" +
      kPbarNoJ + "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,2.,0.,0.\nCBAR,1,1,1,2,0.,1.,0.\nCBAR,2,1,2,3,0.,1.,0.\n"
      "SPC1,1,123456,1\nFORCE,7,3,0,-1.,1.,0.,0.\nEIGRL,3,,,2\nENDDATA\n");
  EXPECT_EQ(cautions(b, usage(b, Solution::Buckling)),
            std::vector<std::string>{
                "PBAR: 1 card, first at deck.bdf:10: PBAR 1 (2 CBAR elements): J = 0, no torsional stiffness: the twist "
                "of these elements about their axis is held only by what they connect to (other elements, SPC, or "
                "AUTOSPC where nothing else holds it); in buckling the torsion (Wagner) term N (I1 + I2) / (A L) of the "
                "bar's differential stiffness couples the twist to the bending rotations, so the load factors depend on "
                "those constraints; give J if the section has torsional stiffness"});

  // several properties of one card are listed in one entry; a PBEAM has its own
  const fem::Model several = test::read_deck(cantilever(
      "SPC = 1\nLOAD = 7\n", kPbarNoJ,
      "PBAR,4,1,1.e-4,2.e-8,2.e-8\nGRID,4,,3.,0.,0.\nGRID,5,,4.,0.,0.\nCBAR,3,4,3,4,0.,1.,0.\n"
      "PBEAM,6,1,1.e-4,2.e-8,2.e-8\nCBEAM,4,6,4,5,0.,1.,0.\n"));
  EXPECT_EQ(cautions(several, usage(several, Solution::Statics)),
            (std::vector<std::string>{
                "PBAR: 2 cards, first at deck.bdf:7: PBAR 1, 4 (3 CBAR elements): J = 0, no torsional stiffness: the "
                "twist of these elements about their axis is held only by what they connect to (other elements, SPC, "
                "or AUTOSPC where nothing else holds it); give J if the section has torsional stiffness",
                "PBEAM: 1 card, first at deck.bdf:19: PBEAM 6 (1 CBEAM element): J = 0, no torsional stiffness: the "
                "twist of these elements about their axis is held only by what they connect to (other elements, SPC, "
                "or AUTOSPC where nothing else holds it); give J if the section has torsional stiffness"}));
}

TEST(ModellingCautions, BarWithTorsionalStiffnessOrUnusedPropertyIsNotNamed) {
  const fem::Model m = test::read_deck(cantilever("SPC = 1\nLOAD = 7\n", kPbarJ, "PBAR,2,1,1.e-4,1.e-8,1.e-8\n"));
  for (const Solution s : {Solution::Statics, Solution::NormalModes, Solution::Info})
    EXPECT_TRUE(cautions(m, usage(m, s)).empty()) << solutions::solution_name(s);
  // seflex convert writes the deck as it is: nothing to caution about
  const fem::Model z = test::read_deck(cantilever("SPC = 1\nLOAD = 7\n", kPbarNoJ));
  EXPECT_TRUE(cautions(z, solutions::check_card_usage(z, Solution::Convert, {})).empty());
}

// RFORCE A is in revolutions per unit time (MSC Nastran QRG; fem/src/loads.cpp applies 2 pi A,
// checked against the spinning rod in tests/solutions/static_loads_test.cpp): the warning gives
// omega = 2 pi 20 = 125.66 rad per unit time and the A a user who meant rad/s should give,
// 20 / (2 pi) = 3.1831; RACC likewise (2 pi 3 = 18.850, 3 / (2 pi) = 0.47746).
TEST(ModellingCautions, RforceOfASelectedSetStatesItsAngularVelocityInRadians) {
  const std::string rforce = "CONM2,9,3,,2.\nRFORCE,7,1,,20.,0.,0.,1.\n";  // line 16: RFORCE
  const fem::Model m = test::read_deck(cantilever("SPC = 1\nLOAD = 7\n", kPbarJ, rforce));
  EXPECT_EQ(cautions(m, usage(m, Solution::Statics)),
            std::vector<std::string>{"RFORCE: 1 card, first at deck.bdf:16: load set 7: A = 20 revolutions per unit "
                                     "time (MSC Nastran QRG): angular velocity 125.66 rad per unit time; if A was meant "
                                     "in rad per unit time, give A = 3.1831"});
  // with an angular acceleration, selected through a LOAD combination
  const fem::Model acc = test::read_deck(cantilever("SPC = 1\nLOAD = 20\n", kPbarJ,
                                                    "CONM2,9,3,,2.\nRFORCE,8,1,,20.,0.,0.,1.,,+R\n+R,3.\n"
                                                    "LOAD,20,1.,1.,7,2.,8\n"));
  EXPECT_EQ(cautions(acc, usage(acc, Solution::Statics)),
            std::vector<std::string>{
                "RFORCE: 1 card, first at deck.bdf:16: load set 8: A = 20 revolutions per unit time (MSC Nastran QRG): "
                "angular velocity 125.66 rad per unit time, RACC = 3 revolutions per unit time squared: angular "
                "acceleration 18.85 rad per unit time squared; if A was meant in rad per unit time, give A = 3.1831 "
                "and RACC = 0.47746"});
}

TEST(ModellingCautions, RforceNotSelectedOrNotUsedIsNotStated) {
  // in an unselected set: the usual "not selected" warning only; in normal modes loads are unused
  const fem::Model m =
      test::read_deck(cantilever("SPC = 1\nLOAD = 7\n", kPbarJ, "CONM2,9,3,,2.\nRFORCE,8,1,,20.,0.,0.,1.\n"));
  EXPECT_TRUE(cautions(m, usage(m, Solution::Statics)).empty());
  const fem::Model sel =
      test::read_deck(cantilever("SPC = 1\nLOAD = 8\n", kPbarJ, "CONM2,9,3,,2.\nRFORCE,8,1,,20.,0.,0.,1.\n"));
  EXPECT_TRUE(cautions(sel, usage(sel, Solution::NormalModes)).empty());
  EXPECT_EQ(cautions(sel, usage(sel, Solution::Statics)).size(), 1u);
}

/// A plate of 2 x 2 CQUAD4 of size h = 1 (grids 1-9) on PSHELL 1 (`pshell`, line 5).
std::string plate(const std::string& pshell) {
  std::string d = "SOL 103\nCEND\nMETHOD = 1\nBEGIN BULK\n" + pshell + "MAT1,1,2.1+11,,0.3,7800.\nEIGRL,1,,,3\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      d += "GRID," + std::to_string(3 * j + i + 1) + ",," + std::to_string(i) + ".," + std::to_string(j) + ".,0.\n";
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int a = 3 * j + i + 1;
      d += "CQUAD4," + std::to_string(10 + 2 * j + i) + ",1," + std::to_string(a) + "," + std::to_string(a + 1) + "," +
           std::to_string(a + 4) + "," + std::to_string(a + 3) + "\n";
    }
  return d + "ENDDATA\n";
}

const std::string kThickText =
    "): transverse shear governs their bending and the element converges slowly on such a mesh; check the higher "
    "modes and the stresses with a finer mesh";

// The threshold t > 0.5 sqrt(area) (modelling_cautions.hpp: at t = 0.5 h transverse shear makes a
// quarter of the flexibility of the shortest wave the mesh carries).
TEST(ModellingCautions, ThickPlatesAreNamedWithTheirLargestRatio) {
  const fem::Model m = test::read_deck(plate("PSHELL,1,1,0.8,1,,1\n"));  // t / h = 0.8, as MYSTRAN's AQ3U2S004
  EXPECT_EQ(cautions(m, usage(m, Solution::NormalModes)),
            std::vector<std::string>{"CQUAD4: 4 cards, first at deck.bdf:17: thick for their size (first: element 10; "
                                     "t / sqrt(area) up to 0.8, above 0.5" + kThickText});
  // just above and just below the threshold
  const fem::Model above = test::read_deck(plate("PSHELL,1,1,0.51,1,,1\n"));
  EXPECT_EQ(cautions(above, usage(above, Solution::Statics)).size(), 1u);
  const fem::Model below = test::read_deck(plate("PSHELL,1,1,0.49,1,,1\n"));
  EXPECT_TRUE(cautions(below, usage(below, Solution::NormalModes)).empty());
  // corner thicknesses (TFLAG = 1: fractions of T) count: element 13 at 0.4 x (1 + 1 + 2 + 2) / 4 = 0.6
  std::string corners = plate("PSHELL,1,1,0.4,1,,1\n");
  const auto at = corners.find("CQUAD4,13,1,5,6,9,8\n");
  ASSERT_NE(at, std::string::npos);
  corners.replace(at, 20, "CQUAD4,13,1,5,6,9,8,,,+Q\n+Q,,1,1.,1.,2.,2.\n");
  const fem::Model tapered = test::read_deck(corners);
  EXPECT_EQ(cautions(tapered, usage(tapered, Solution::NormalModes)),
            std::vector<std::string>{"CQUAD4: 1 card, first at deck.bdf:20: thick for their size (first: element 13; "
                                     "t / sqrt(area) up to 0.6, above 0.5" + kThickText});
}

TEST(ModellingCautions, SandwichIsThickByItsShearNotItsFaceThickness) {
  // T = 0.1, 12 I / T^3 = 100, TS / T = 1: t_s^2 = (5/6) G 100 T^3 / (G T) = 0.8333, t_s = 0.913
  const fem::Model m = test::read_deck(plate("PSHELL,1,1,0.1,1,100.,1,1.\n"));
  EXPECT_EQ(cautions(m, usage(m, Solution::NormalModes)),
            std::vector<std::string>{
                "CQUAD4: 4 cards, first at deck.bdf:17: thick for their size (first: element 10; t / sqrt(area) up to "
                "0.91, above 0.5; t of a sandwich or laminate: the homogeneous plate's with its ratio of bending to "
                "transverse shear stiffness" + kThickText});
}

TEST(ModellingCautions, ThinKirchhoffOrMembranePlatesAreNotNamed) {
  for (const char* p : {"PSHELL,1,1,0.05,1,,1\n",  // thin
                        "PSHELL,1,1,0.8,1\n",       // MID3 blank: rigid in shear (Kirchhoff)
                        "PSHELL,1,1,0.8\n"})        // membrane only
  {
    const fem::Model m = test::read_deck(plate(p));
    EXPECT_TRUE(cautions(m, usage(m, Solution::NormalModes)).empty()) << p;
  }
}

TEST(ModellingCautions, CtriaThicknessIsMeasuredAgainstItsOwnArea) {
  // right triangles of legs 1: sqrt(area) = 0.7071; t = 0.4 gives 0.57
  const fem::Model m = test::read_deck(
      "SOL 103\nCEND\nMETHOD = 1\nBEGIN BULK\nPSHELL,1,1,0.4,1,,1\nMAT1,1,2.1+11,,0.3,7800.\nEIGRL,1,,,3\n"
      "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\nCTRIA3,1,1,1,2,3\nCTRIA3,2,1,1,3,4\n"
      "ENDDATA\n");
  EXPECT_EQ(cautions(m, usage(m, Solution::NormalModes)),
            std::vector<std::string>{"CTRIA3: 2 cards, first at deck.bdf:12: thick for their size (first: element 1; "
                                     "t / sqrt(area) up to 0.57, above 0.5" + kThickText});
}

// The MYSTRAN decks the cautions are about (docs/validation-mystran.md) state them; the demo meshes,
// the examples and the other validation decks state none.
TEST(ModellingCautions, ValidationDecksStateTheirsOrdinaryDecksNone) {
  const std::filesystem::path src = SEFLEX_SOURCE_DIR, data = SEFLEX_TEST_DATA;
  const std::filesystem::path loads = data / "validation/mystran_static_loads";
  auto cautions_of = [](const std::filesystem::path& p) {
    const fem::Model m = io::read_nastran(p);
    const Solution s = solutions::solution_of_deck(m);
    return cautions(m, usage(m, s == Solution::Info ? Solution::NormalModes : s));
  };
  const auto thick = cautions_of(loads / "AQ3U2S004.DAT");
  ASSERT_EQ(thick.size(), 1u);
  EXPECT_TRUE(test::mentions(thick[0], {"CQUAD4: 16 cards, first at ", "AQ3U2S004.DAT:49: thick for their size (first: "
                                        "element 1001; t / sqrt(area) up to 0.8, above 0.5)"}));
  const auto spin = cautions_of(loads / "BAR-RFORCE-OFFSET.DAT");
  ASSERT_EQ(spin.size(), 1u);
  EXPECT_TRUE(test::mentions(spin[0], {"BAR-RFORCE-OFFSET.DAT:29: load set 61: A = 20 revolutions per unit time (MSC "
                                       "Nastran QRG): angular velocity 125.66 rad per unit time"}));
  const auto grav = cautions_of(loads / "BAR-GRAV.DAT");  // J blank on the PBAR: true, and said
  ASSERT_EQ(grav.size(), 1u);
  EXPECT_TRUE(test::mentions(grav[0], {"BAR-GRAV.DAT:35: PBAR 10 (5 CBAR elements): J = 0"}));

  for (const std::filesystem::path& p :
       {src / "meshes/panel.bdf", src / "meshes/yoke.bdf", src / "examples/scenes/link.bdf",
        data / "buckling/plate_ss_cquad4_10x10.bdf", data / "buckling/euler_column_cbar.bdf",
        data / "validation/nastran_cbar_cbeam_conm2_modes/beam_modes.dat",
        data / "validation/mystran_mixed_cbar_crod_cquad4_ctria3_celas_modes/ALL-ELEM-TEST-GIV.DAT",
        data / "validation/mystran_cbar_cantilever_and_freefree_modes/BAR-CC-GIV.DAT",
        data / "validation/mystran_craig_bampton_cbar_frame/CB-EXAMPLE-12.DAT", loads / "ALL-ELEM-TEST.DAT",
        loads / "BAR-THERM-CONSTR.DAT", loads / "BAR-THERM-FREE.DAT"})
    EXPECT_TRUE(cautions_of(p).empty()) << p << ":\n" << (cautions_of(p).empty() ? "" : cautions_of(p)[0]);
}

}  // namespace
}  // namespace seflex
