// Which cards a solution uses (solutions/card_usage.hpp): what the selected subcases need and seflex
// cannot use refuses the deck with an error naming the card, file:line and why; what they do not use
// is a warning, never a refusal (Nastran runs such decks). Also run under ASan + UBSan.
#include <gtest/gtest.h>

#include "nastran_test_util.hpp"
#include "seflex/solutions/card_usage.hpp"
#include "seflex/solutions/normal_modes.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

using solutions::CardUse;
using solutions::Solution;
using test::mentions;

/// A clamped two-bar cantilever (grids 1-3) with a tip FORCE in load set 7, SPC set 1, EIGRL 1.
std::string bulk() {
  return "MAT1,1,7.e10,,0.3,2700.\nPBAR,1,1,1.e-4,2.e-8,2.e-8,4.e-8\n"
         "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,2.,0.,0.\n"
         "CBAR,1,1,1,2,0.,1.,0.\nCBAR,2,1,2,3,0.,1.,0.\nSPC1,1,123456,1\nFORCE,7,3,0,1.,0.,0.,1.\n"
         "EIGRL,1,,,2\n";
}

std::string deck(const std::string& case_control, const std::string& more_bulk) {
  return "SOL 101\nCEND\n" + case_control + "BEGIN BULK\n" + bulk() + more_bulk + "ENDDATA\n";
}

solutions::CardUsage usage(const fem::Model& m, Solution s) {
  const auto cases = s == Solution::Statics ? solutions::select_cases(m) : std::vector{solutions::select_case(m)};
  return solutions::check_card_usage(m, s, cases);
}

/// The entry of `card` (first one), or a test failure.
const CardUse* find(const solutions::CardUsage& u, const std::string& card) {
  for (const CardUse& e : u.uses)
    if (e.card == card) return &e;
  ADD_FAILURE() << "no entry for " << card;
  return nullptr;
}

std::string refusal(const fem::Model& m, Solution s) {
  try {
    solutions::require_usable(m, usage(m, s));
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "not refused";
  return "";
}

// A selected load set holding a card seflex does not apply refuses the deck, naming the card and its
// line; the same card in an unselected set is a warning, and the subcase runs.
TEST(CardUsage, SelectedLoadWithAnUnsupportedCardIsRefusedUnselectedIsAWarning) {
  const std::string pload = "PLOADX1,9,1,5.\nLOAD,20,1.,1.,7,1.,9\n";  // line 14 (PLOADX1), 15 (LOAD)
  const fem::Model used = test::read_deck(deck("SPC = 1\nLOAD = 20\n", pload));
  EXPECT_TRUE(mentions(refusal(used, Solution::Statics),
                       {"deck.bdf:16: PLOADX1: load set 9 selected by the case control holds them, and seflex does not "
                        "apply PLOADX1 loads; linear statics (SOL 101) cannot run without it"}));
  try {  // the library refuses too, with the same message
    solutions::solve_static(used);
    ADD_FAILURE() << "solve_static ran a deck whose selected load set holds PLOADX1";
  } catch (const InputError& e) {
    EXPECT_TRUE(mentions(e.what(), {"deck.bdf:16: PLOADX1: load set 9 selected by the case control holds them, and "
                                    "seflex does not apply PLOADX1 loads; linear statics (SOL 101) cannot run without it"}));
  }

  const fem::Model unused = test::read_deck(deck("SPC = 1\nLOAD = 7\n", pload));
  const auto u = usage(unused, Solution::Statics);
  EXPECT_FALSE(u.refused());
  const CardUse* p = find(u, "PLOADX1");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->kind, CardUse::Kind::Unused);
  EXPECT_EQ(solutions::describe(unused, *p),
            "PLOADX1: 1 card, first at deck.bdf:16: load set 9 not selected by any subcase linear statics (SOL 101) runs");
  EXPECT_NO_THROW(solutions::solve_static(unused));
  // in normal modes every load card is unused
  const auto modes = usage(unused, Solution::NormalModes);
  EXPECT_EQ(find(modes, "FORCE")->reason, "loads are not used by normal modes (SOL 103)");
}

// Missing references in sets the case control does not select are warnings (as Nastran); in a
// selected set they refuse the deck.
TEST(CardUsage, ReferencesOfUnselectedSetsWarnSelectedRefuse) {
  // an EIGR that METHOD does not select, normalised at a grid that does not exist (MYSTRAN's
  // AQ3U2S004 decks have one): read, and modes run with METHOD = 1
  const std::string eigr = "EIGR,2,GIV,,,,4\n,POINT,55,3\n";
  const fem::Model m = test::read_deck("SOL 103\nCEND\nSPC = 1\nMETHOD = 1\nBEGIN BULK\n" + bulk() + eigr);
  const auto u = usage(m, Solution::NormalModes);
  EXPECT_FALSE(u.refused());
  EXPECT_TRUE(mentions(solutions::describe(m, *find(u, "EIGR")),
                       {"EIGR: 1 card, first at deck.bdf:16: NORM = POINT names grid 55 component 3, which is not a dof of "
                        "the model (the method is not selected)"}));
  EXPECT_EQ(solutions::solve_normal_modes(m).eigenvalues.size(), 2);
  // selected: the modes are computed and normalised to MAX instead (eigenvalues do not depend on it)
  const fem::Model sel = test::read_deck("SOL 103\nCEND\nSPC = 1\nMETHOD = 2\nBEGIN BULK\n" + bulk() + eigr);
  const auto usel = usage(sel, Solution::NormalModes);
  const CardUse* e = find(usel, "EIGR");
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->kind, CardUse::Kind::Approximated);
  const solutions::NormalModes r = solutions::solve_normal_modes(sel);
  ASSERT_EQ(r.eigenvalues.size(), 4);  // ND of EIGR 2
  for (Eigen::Index k = 0; k < 4; ++k) EXPECT_EQ(r.shapes_g.col(k).cwiseAbs().maxCoeff(), 1.0);  // MAX

  // SPC and SPCADD sets: a missing grid or set in an unselected set is a warning
  const std::string spc = "SPC1,4,123,77\nSPCADD,5,4,88\n";
  const fem::Model s1 = test::read_deck(deck("SPC = 1\nLOAD = 7\n", spc));
  const auto u1 = usage(s1, Solution::Statics);
  EXPECT_FALSE(u1.refused());
  EXPECT_TRUE(mentions(solutions::describe(s1, *find(u1, "SPC/SPC1")),
                       {"deck.bdf:16", "SPC set 4: references point 77, which is not defined (the set is not used)"}));
  // selected through SPCADD 5: set 4's missing grid and the missing set 88 both refuse it
  EXPECT_TRUE(mentions(refusal(test::read_deck(deck("SPC = 5\nLOAD = 7\n", spc)), Solution::Statics),
                       {"deck.bdf:16: SPC/SPC1: SPC set 4: references point 77, which is not defined", "1 more problem"}));
  const fem::Model s5 = test::read_deck(deck("SPC = 5\nLOAD = 7\n", spc));
  const auto u5 = usage(s5, Solution::Statics);
  EXPECT_TRUE(mentions(solutions::describe(s5, *find(u5, "SPCADD")),
                       {"deck.bdf:17: SPCADD 5 references SPC set 88, which no card defines"}));
  // a selection that names nothing
  EXPECT_TRUE(mentions(refusal(test::read_deck(deck("SPC = 1\nLOAD = 8\n", "")), Solution::Statics),
                       {"deck.bdf: case control LOAD: the global case control: LOAD = 8 selects no load card"}));
  EXPECT_TRUE(mentions(refusal(test::read_deck("SOL 103\nCEND\nSPC = 4\nMETHOD = 1\nBEGIN BULK\n" + bulk()),
                               Solution::NormalModes),
                       {"case control SPC", "SPC = 4 selects no SPC, SPC1 or SPCADD card"}));
  EXPECT_TRUE(mentions(refusal(test::read_deck("SOL 103\nCEND\nSPC = 1\nMETHOD = 4\nBEGIN BULK\n" + bulk()),
                               Solution::NormalModes),
                       {"METHOD = 4 selects no EIGRL or EIGR card"}));
  // PARAM GRDPNT naming no grid: the basic origin, with a warning
  const fem::Model g = test::read_deck(deck("SPC = 1\nLOAD = 7\n", "PARAM,GRDPNT,12\n"));
  const auto ug = usage(g, Solution::Statics);
  EXPECT_TRUE(mentions(solutions::describe(g, *find(ug, "PARAM GRDPNT")),
                       {"deck.bdf:16", "grid 12 is not defined; the mass properties (seflex info) use the basic origin"}));
}

// SPC1 "G1 THRU G2" over grids that do not all exist: the missing ones are skipped (QRG SPC1), with
// a warning; an explicit missing grid in a selected set refuses.
TEST(CardUsage, Spc1ThruSkipsMissingGrids) {
  const fem::Model m = test::read_deck(deck("SPC = 3\nLOAD = 7\n", "SPC1,3,123456,1\nSPC1,3,1,2,THRU,1000\n"));
  const auto u = usage(m, Solution::Statics);
  EXPECT_FALSE(u.refused());
  const CardUse* e = find(u, "SPC1");
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->kind, CardUse::Kind::Approximated);
  EXPECT_EQ(e->count, 997u);  // 4 ... 1000 do not exist
  EXPECT_TRUE(mentions(solutions::describe(m, *e), {"SPC1: 997 cards, first at deck.bdf:17",
                                                    "grids of a THRU range that do not exist are skipped"}));
  const auto s = solutions::solve_static(m);
  EXPECT_GT(s.u_g.norm(), 0.0);
  EXPECT_TRUE(mentions(refusal(test::read_deck(deck("SPC = 3\nLOAD = 7\n", "SPC1,3,123456,1,1000\n")), Solution::Statics),
                       {"deck.bdf:16: SPC/SPC1: SPC set 3: references point 1000, which is not defined"}));
}

// Elements, properties, materials seflex does not model refuse every solution; seflex convert and
// seflex info only list them.
TEST(CardUsage, UnsupportedStructureRefusesEverySolution) {
  const fem::Model m = test::read_deck(deck("SPC = 1\nLOAD = 7\n", "CQUAD,9,3,1,2,3,4,5,6\n,7,8,9\nPLSOLID,3,1\n"));
  for (const Solution s : {Solution::Statics, Solution::NormalModes, Solution::CraigBampton})
    EXPECT_TRUE(mentions(refusal(m, s), {"deck.bdf:16: CQUAD: seflex does not model CQUAD", "cannot run without it",
                                         "1 more problem"}));
  const auto c = solutions::check_card_usage(m, Solution::Convert, {});
  EXPECT_FALSE(c.refused());
  EXPECT_EQ(find(c, "CQUAD")->reason, "not written: seflex does not model it");
}

// Composite and anisotropic shell cards are used by every solution (issue 13): no refusal; what they
// hold that seflex approximates (a MAT2 ply rigid in transverse shear, PSHELL Z1/Z2) is a warning.
TEST(CardUsage, CompositeShellCardsAreUsed) {
  const std::string shells =
      "GRID,11,,0.,1.,0.\nGRID,12,,1.,1.,0.\n"
      "MAT8,8,1.81+11,1.03+10,.28,7.17+9,5.+9,4.+9,1600.\nMAT2,9,1.+9,2.+8,0.,1.1+9,0.,3.+8,900.\n"
      "PCOMP,20,,,,,,,\n,8,.001,0.,,9,.001,90.\nPCOMPG,21\n,1,8,.002,45.\n"
      "PSHELL,22,1,.002,1,,1,,,+S\n+S,-.003,.001,9\n"
      "CQUAD4,20,20,1,2,12,11\nCQUAD4,21,21,1,2,12,11\nCQUAD4,22,22,1,2,12,11\n";
  const fem::Model m = test::read_deck(deck("SPC = 1\nLOAD = 7\n", shells));
  for (const Solution s : {Solution::Statics, Solution::NormalModes, Solution::CraigBampton}) {
    const auto u = usage(m, s);
    EXPECT_FALSE(u.refused()) << solutions::solution_name(s);
    for (const char* card : {"PCOMP", "PCOMPG", "MAT8", "MAT2"})
      for (const CardUse& e : u.uses) EXPECT_NE(e.card, card) << solutions::describe(m, e);
  }
  const auto u = usage(m, Solution::Statics);
  EXPECT_EQ(find(u, "PCOMP ply of MAT2 (rigid in transverse shear: a MAT2 gives no transverse shear moduli)")->kind,
            CardUse::Kind::Approximated);
  EXPECT_EQ(find(u, "PSHELL Z1/Z2 (fibre distances for stresses, which seflex does not compute: not used)")->kind,
            CardUse::Kind::Approximated);
}

// Case-control selections: refused where the solution needs what is missing (a thermal load set no
// card defines, thermal loads in buckling), warnings otherwise.
TEST(CardUsage, CaseControlSelections) {
  const std::string temps = "TEMPD,21,100.\n";
  const fem::Model m = test::read_deck(deck("SPC = 1\nSUBCASE 1\nLOAD = 7\nSUBCASE 2\nTEMP(LOAD) = 22\n", temps));
  EXPECT_TRUE(
      mentions(refusal(m, Solution::Statics),
               {"deck.bdf:6: case control TEMPERATURE(LOAD): SUBCASE 2: TEMPERATURE(LOAD) = 22 selects no TEMP, "
                "TEMPD or TEMPRB card"}));
  const fem::Model t = test::read_deck(deck("SPC = 1\nSUBCASE 1\nLOAD = 7\nSUBCASE 2\nTEMP(LOAD) = 21\n", temps));
  EXPECT_FALSE(usage(t, Solution::Statics).refused());
  const auto b = solutions::check_card_usage(t, Solution::Buckling, solutions::select_cases(t));
  ASSERT_TRUE(b.refused());
  EXPECT_TRUE(mentions(b.uses.front().reason, {"TEMPERATURE(LOAD) = 21 selects thermal loads", "in buckling"}));
  // the first subcase alone does not need it; TEMP(INIT) and DLOAD are warnings
  const fem::Model w = test::read_deck(deck("SPC = 1\nTEMP(INIT) = 21\nDLOAD = 4\nLOAD = 7\n", temps));
  const auto u = usage(w, Solution::Statics);
  EXPECT_FALSE(u.refused());
  EXPECT_EQ(find(u, "case control TEMPERATURE(INIT)")->kind, CardUse::Kind::Unused);
  EXPECT_TRUE(mentions(find(u, "case control DLOAD")->reason, {"DLOAD = 4: not used by linear statics (SOL 101)"}));
  EXPECT_TRUE(mentions(find(u, "TEMPD")->reason, {"thermal load set 21 not selected by TEMPERATURE(LOAD)"}));
  EXPECT_TRUE(
      mentions(find(usage(w, Solution::NormalModes), "TEMPD")->reason, {"temperatures are not used by normal modes"}));
}

// Output, optimisation, aero and other solvers' cards, unselected MPC sets and unknown PARAMs: warnings.
// Cards seflex does not know at all: refused.
TEST(CardUsage, CardsNoSolutionUsesAreWarnings) {
  const fem::Model m = test::read_deck(deck("SPC = 1\nLOAD = 7\n",
                                            "DESVAR,1,T,1.,0.,2.\nCAERO1,5,6\nPLOTEL,8,1,2\nDEBUG,1,2\nECHOON\nECHOOFF\n"
                                            "MPC,4,2,3,1.,3,3,-1.\nPARAM,POST,-1\nPARAM,SOLLIB,SPARSE\n"));
  const auto u = usage(m, Solution::Statics);
  EXPECT_FALSE(u.refused());
  EXPECT_TRUE(mentions(find(u, "DESVAR")->reason, {"design optimisation"}));
  EXPECT_TRUE(mentions(find(u, "CAERO1")->reason, {"aeroelastic"}));
  EXPECT_TRUE(mentions(find(u, "PLOTEL")->reason, {"output"}));
  // the echo of the bulk data on and off (flyswatter.bdf): output control, nothing to refuse
  EXPECT_TRUE(mentions(find(u, "ECHOON")->reason, {"output"}));
  EXPECT_TRUE(mentions(find(u, "ECHOOFF")->reason, {"output"}));
  EXPECT_TRUE(mentions(find(u, "DEBUG")->reason, {"another solver"}));
  EXPECT_TRUE(mentions(find(u, "MPC")->reason, {"MPC set 4 not selected"}));
  EXPECT_TRUE(mentions(find(u, "PARAM")->reason, {"parameters seflex does not use: POST, SOLLIB"}));
  EXPECT_EQ(find(u, "PARAM")->count, 2u);
  // a card seflex does not know is refused (tests/solutions/unknown_cards_test.cpp), unless asked to go on
  const fem::Model x = test::read_deck(deck("SPC = 1\nLOAD = 7\n", "XYZCARD,1\n"));
  const solutions::CardUsage refused = usage(x, Solution::Statics);
  const CardUse* unknown = find(refused, "XYZCARD");
  EXPECT_EQ(unknown->kind, CardUse::Kind::Refused);
  EXPECT_TRUE(unknown->unknown_card);
  const auto ignored = solutions::check_card_usage(x, Solution::Statics, solutions::select_cases(x), solutions::kInterfaceNone, true);
  EXPECT_FALSE(ignored.refused());
  EXPECT_TRUE(mentions(find(ignored, "XYZCARD")->reason, {"a card seflex does not know; ignored (--ignore-unknown)"}));
  // inertia relief is refused in statics
  EXPECT_TRUE(mentions(refusal(test::read_deck(deck("SPC = 1\nLOAD = 7\n", "PARAM,INREL,-1\n")), Solution::Statics),
                       {"PARAM INREL", "inertia relief"}));
}

// A deck written for another solution runs as the command asks, with a word about it (Nastran would
// run its own SOL); the deck's own solution gets no such word.
TEST(CardUsage, DeckForAnotherSolutionIsSaidNotRefused) {
  const fem::Model m = test::read_deck(deck("SPC = 1\nLOAD = 7\nMETHOD = 1\n", ""));  // SOL 101 deck
  const auto modes = usage(m, Solution::NormalModes);
  EXPECT_FALSE(modes.refused());
  const CardUse* sol = find(modes, "executive control SOL");
  ASSERT_NE(sol, nullptr);
  EXPECT_EQ(sol->kind, CardUse::Kind::Unused);
  EXPECT_TRUE(mentions(solutions::describe(m, *sol), {"executive control SOL (deck.bdf", "the deck asks for linear statics (SOL 101)"}));
  for (const CardUse& e : usage(m, Solution::Statics).uses) EXPECT_NE(e.card, "executive control SOL");
}

}  // namespace
}  // namespace seflex

namespace seflex {
namespace {

/// A free flat 2 x 2 CQUAD4 plate in the x-y plane (grids 1-9, centre 5) with a CONM2 on the centre
/// grid; `inertia` is its CONM2 continuation (I11 I21 I22 I31 I32 I33), `more` extra bulk cards.
fem::Model plate_with_conm2(const std::string& inertia, const std::string& more) {
  std::string b = "SOL 103\nCEND\nMETHOD = 1\nBEGIN BULK\nEIGRL,1,,,12\nMAT1,1,7.e10,,0.3,2700.\nPSHELL,1,1,0.002,1,,1\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) b += "GRID," + std::to_string(1 + i + 3 * j) + ",," + std::to_string(0.5 * i) + "," + std::to_string(0.5 * j) + ",0.\n";
  b += "CQUAD4,1,1,1,2,5,4\nCQUAD4,2,1,2,3,6,5\nCQUAD4,3,1,4,5,8,7\nCQUAD4,4,1,5,6,9,8\n";
  b += "CONM2,10,5,0,0.5\n," + inertia + "\n" + more + "ENDDATA\n";
  return test::read_deck(b);
}

// Rotary inertia about a flat shell's normal rests on the drilling penalty alone (spurious modes,
// docs/fem.md "Shell sections"): a warning naming the CONM2, its line and PARAM K6ROT, for the
// solutions that use mass, and none when K6ROT is large, when the inertia is about in-plane axes
// only, or when a bar also reaches the grid.
TEST(CardUsage, ConmInertiaAboutAFlatShellNormalIsAWarning) {
  const fem::Model m = plate_with_conm2("1.e-4,0.,1.e-4,0.,0.,2.e-4", "");
  const solutions::CardUsage u = usage(m, Solution::NormalModes);
  const CardUse* e = find(u, "CONM2");
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->kind, CardUse::Kind::Approximated);
  EXPECT_EQ(e->first.line, 21u);
  EXPECT_TRUE(mentions(e->reason, {"normal of the flat shells at grid 5 (0.0002)", "PARAM K6ROT = 100", "spurious"}));
  for (const CardUse& use : usage(m, Solution::Statics).uses) EXPECT_NE(use.card, "CONM2") << use.reason;
  auto none = [](const fem::Model& q) {
    for (const CardUse& use : usage(q, Solution::NormalModes).uses)
      if (use.card == "CONM2") return false;
    return true;
  };
  EXPECT_TRUE(none(plate_with_conm2("1.e-4,0.,1.e-4,0.,0.,2.e-4", "PARAM,K6ROT,1.e5\n")));
  EXPECT_TRUE(none(plate_with_conm2("1.e-4,0.,1.e-4,0.,0.,0.", "")));
  EXPECT_TRUE(none(plate_with_conm2("1.e-4,0.,1.e-4,0.,0.,2.e-4",
                                    "PBAR,2,1,1.e-4,1.e-8,1.e-8,2.e-8\nCBAR,5,2,5,6,0.,0.,1.\n")));
  // The physics the warning stands for: with I33 = 10 kg m^2 and K6ROT = 100 the centre's drilling
  // rotation is a mode (2.8 Hz) below the plate's first elastic one (4.5 Hz); with K6ROT = 1e5 it is
  // 32x higher (stiffness 1000x), out of the low spectrum, and the elastic modes are unchanged.
  const auto low = solutions::solve_normal_modes(plate_with_conm2("1.e-4,0.,1.e-4,0.,0.,10.", ""));
  const auto high = solutions::solve_normal_modes(plate_with_conm2("1.e-4,0.,1.e-4,0.,0.,10.", "PARAM,K6ROT,1.e5\n"));
  const auto bare = solutions::solve_normal_modes(plate_with_conm2("1.e-4,0.,1.e-4,0.,0.,0.", ""));
  EXPECT_LT(low.cycles()(6), 0.7 * bare.cycles()(6));  // 2.76 Hz against 4.51 Hz
  for (int k = 6; k < 9; ++k) EXPECT_NEAR(high.cycles()(k) / bare.cycles()(k), 1.0, 1e-6) << "mode " << k + 1;
}

}  // namespace
}  // namespace seflex
