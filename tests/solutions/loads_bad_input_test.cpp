// Bad PLOAD2, GRAV, RFORCE, TEMP, TEMPD, TEMPRB input and thermal selections: each refused with an
// InputError naming file:line, card, field and what was expected (reader, card usage or load
// assembly); unselected sets are warnings. Also run under ASan + UBSan.
#include <gtest/gtest.h>

#include "nastran_test_util.hpp"
#include "seflex/solutions/card_usage.hpp"
#include "seflex/solutions/statics.hpp"
#include "test_support.hpp"

namespace seflex {
namespace {

using test::mentions;
using test::read_error;

/// A clamped two-bar cantilever (grids 1-3, CBAR 1-2) and a CQUAD4 10 on grids 1, 2, 5, 4 (line 15
/// with one case-control line); the cards under test follow on line 17 + case-control lines.
std::string bulk() {
  return "MAT1,1,7.e10,,0.3,2700.,2.3e-5,20.\nPBAR,1,1,1.e-4,2.e-8,2.e-8,4.e-8\nPSHELL,2,1,0.002,1\n"
         "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,2.,0.,0.\nGRID,4,,0.,1.,0.\nGRID,5,,1.,1.,0.\n"
         "CBAR,1,1,1,2,0.,1.,0.\nCBAR,2,1,2,3,0.,1.,0.\nCQUAD4,10,2,1,2,5,4\nSPC1,1,123456,1\n";
}

std::string deck(const std::string& case_control, const std::string& more) {
  return "SOL 101\nCEND\nSPC = 1\n" + case_control + "BEGIN BULK\n" + bulk() + more + "ENDDATA\n";
}

/// The InputError of solving the statics of `text` ("" and a failure if it solves).
std::string solve_error(const std::string& text) {
  try {
    solutions::solve_statics(test::read_deck(text));
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "solved without error";
  return "";
}

TEST(LoadsBadInput, ReaderNamesCardAndField) {
  EXPECT_TRUE(
      mentions(read_error(deck("", "PLOAD2,5,1.\n")), {"deck.bdf:17:", "PLOAD2 5", "EID1", "at least one element id"}));
  EXPECT_TRUE(mentions(read_error(deck("", "PLOAD2,5,1.,10,THRU,4\n")), {"PLOAD2 5", "EID2", "greater than 10"}));
  EXPECT_TRUE(mentions(read_error(deck("", "PLOAD2,5,1.,10,11,THRU,14\n")), {"PLOAD2 5", "THRU after more than one"}));
  EXPECT_TRUE(mentions(read_error(deck("", "PLOAD2,5,1,10\n")), {"PLOAD2 5", "field 3 (P)", "expected a real"}));
  EXPECT_TRUE(mentions(read_error(deck("", "GRAV,3,,9.81,0.,0.,0.\n")), {"GRAV 3", "N1", "nonzero component"}));
  EXPECT_TRUE(mentions(read_error(deck("", "GRAV,3,,9.81,0.,0.,1.,2\n")), {"GRAV 3", "MB", "superelements"}));
  EXPECT_TRUE(mentions(read_error(deck("", "RFORCE,4,1,,1.,0.,0.,0.\n")), {"RFORCE 4", "R1", "rotation axis"}));
  EXPECT_TRUE(mentions(read_error(deck("", "RFORCE,4,1,,1.,0.,0.,1.,3\n")), {"RFORCE 4", "METHOD", "1, 2 or blank"}));
  EXPECT_TRUE(
      mentions(read_error(deck("", "RFORCE,4,1,,1.,0.,0.,1.,,+R\n+R,0.,,7\n")), {"deck.bdf:18: RFORCE 4, field 4 (IDRF): got integer '7'; expected 0 or blank (RFORCE on an element set "
                                 "is not supported)"}));
  EXPECT_TRUE(mentions(read_error(deck("", "TEMP,7,1,20.,2\n")), {"TEMP 7", "T2", "expected a real"}));
  EXPECT_TRUE(mentions(read_error(deck("", "TEMPD,7\n")), {"deck.bdf:17: TEMPD 7, field 3 (T1): blank; expected a real number"}));
  EXPECT_TRUE(mentions(read_error(deck("", "TEMPRB,7,1,20.\n")), {"deck.bdf:17: TEMPRB 7, field 5 (TB): blank; expected a real number"}));
}

TEST(LoadsBadInput, SelectedLoadReferencesAreChecked) {
  // PLOAD2 listing a bar, or an element that does not exist (THRU would skip them)
  EXPECT_TRUE(mentions(solve_error(deck("LOAD = 5\n", "PLOAD2,5,1.,10,2\n")),
                       {"deck.bdf:18:", "PLOAD2 5", "element 2 is a CBAR; expected a shell: CQUAD4, CTRIA3, CQUADR, CTRIAR, CQUAD8 or CTRIA6"}));
  EXPECT_TRUE(mentions(solve_error(deck("LOAD = 5\n", "PLOAD2,5,1.,99\n")), {"PLOAD2 5", "element 99 is not defined"}));
  // GRAV/RFORCE in a system that does not exist or is not rectangular, RFORCE about a missing grid
  const std::string cyl = "CORD2C,8,,0.,0.,0.,0.,0.,1.,+C\n+C,1.,0.,0.\n";
  EXPECT_TRUE(mentions(solve_error(deck("LOAD = 3\n", "GRAV,3,6,9.81,0.,0.,1.\n")), {"deck.bdf:18: GRAV 3, field 3 (CID): references coordinate system 6, which is not defined"}));
  EXPECT_TRUE(mentions(solve_error(deck("LOAD = 3\n", cyl + "GRAV,3,8,9.81,0.,0.,1.\n")),
                       {"GRAV 3, field 3 (CID): references coordinate system 8, which is not rectangular; expected a "
                        "rectangular system (CORD1R/CORD2R) or 0"}));
  EXPECT_TRUE(mentions(solve_error(deck("LOAD = 4\n", cyl + "RFORCE,4,,8,1.,0.,0.,1.\n")),
                       {"RFORCE 4, field 4 (CID): references coordinate system 8, which is not rectangular"}));
  EXPECT_TRUE(
      mentions(solve_error(deck("LOAD = 4\n", "RFORCE,4,77,,1.,0.,0.,1.\n")), {"deck.bdf:18: RFORCE 4, field 3 (G): references GRID 77, which is not defined"}));
  // an unselected GRAV/RFORCE/PLOAD2 set is a warning, whatever it references; the deck runs
  const fem::Model w = test::read_deck(
      deck("LOAD = 3\n", "GRAV,3,,9.81,0.,0.,1.\nGRAV,4,6,1.,0.,0.,1.\nRFORCE,5,77,,1.,0.,0.,1.\nPLOAD2,6,1.,2\n"));
  const auto u = solutions::check_card_usage(w, solutions::Solution::Statics, solutions::select_cases(w));
  EXPECT_FALSE(u.refused());
  std::size_t unselected = 0;
  for (const auto& e : u.uses)
    unselected += e.reason.find(" not selected by any subcase") != std::string::npos &&
                  (e.card == "GRAV" || e.card == "RFORCE" || e.card == "PLOAD2");
  EXPECT_EQ(unselected, 3u);
  EXPECT_NO_THROW(solutions::solve_static(w));
  // a LOAD combining a set no load card defines
  EXPECT_TRUE(mentions(solve_error(deck("LOAD = 9\n", "GRAV,3,,9.81,0.,0.,1.\nLOAD,9,1.,1.,3,1.,6\n")),
                       {"deck.bdf:19: LOAD: LOAD 9 (selected by the global case control) references load set 6, which no load "
                        "card defines; linear statics (SOL 101) cannot run without it"}));
}

TEST(LoadsBadInput, ThermalSelections) {
  const std::string bars_only = "TEMPRB,7,1,30.,30.\nTEMPRB,7,2,30.,30.\n";
  // a selected set that no temperature card defines
  EXPECT_TRUE(
      mentions(solve_error(deck("TEMPERATURE(LOAD) = 8\n", bars_only)),
               {"case control TEMPERATURE(LOAD)", "TEMPERATURE(LOAD) = 8 selects no TEMP, TEMPD or TEMPRB card"}));
  // grid temperatures that heat the shell (its MAT1 has ALPHA): its thermal load is computed
  EXPECT_NO_THROW(solutions::solve_statics(test::read_deck(deck("TEMP(LOAD) = 7\n", "TEMPD,7,50.\n"))));
  // ... but not the thermal moment of a PSHELL MID4 with thermal expansion: refused, naming the shell
  const std::string mid4 = "MAT1,4,7.e9,,0.3,0.,1.e-5,20.\nPSHELL,3,1,0.002,1,,,,,+P\n+P,,,4\n"
                           "GRID,7,,0.,2.,0.\nGRID,8,,1.,2.,0.\nCQUAD4,11,3,4,5,8,7\n";
  EXPECT_TRUE(mentions(solve_error(deck("TEMP(LOAD) = 7\n", mid4 + "TEMPD,7,50.\n")),
                       {"deck.bdf:23: CQUAD4", "thermal load set 7 gives a temperature to shells whose PSHELL MID4",
                        "does not compute the thermal moment of MID4"}));
  // TEMPRB on the shell
  EXPECT_TRUE(mentions(solve_error(deck("TEMP(LOAD) = 7\n", bars_only + "TEMPRB,7,10,30.,30.\n")),
                       {"TEMPRB 7", "element 10 is not a CBAR, CBEAM, CROD, CTUBE or CONROD"}));
  // a bar without TEMPRB whose grid has no temperature
  EXPECT_TRUE(mentions(solve_error(deck("TEMP(LOAD) = 7\n", "TEMPRB,7,1,30.,30.\nTEMP,7,3,25.\n")),
                       {"CBAR 2", "GRID 2 has no temperature in thermal load set 7"}));
  // the shell at TREF is fine, the bars get their load; TEMP(INIT) and an unselected set warn
  const fem::Model ok =
      test::read_deck(deck("TEMP(LOAD) = 7\nTEMP(INIT) = 9\n", "TEMPD,7,20.\nTEMP,7,3,80.\nTEMPD,9,0.\nTEMPD,12,5.\n"));
  const auto u = solutions::check_card_usage(ok, solutions::Solution::Statics, solutions::select_cases(ok));
  EXPECT_FALSE(u.refused());
  bool init = false, unselected = false;
  for (const auto& e : u.uses) {
    init = init || (e.card == "case control TEMPERATURE(INIT)" && e.reason.find("TREF") != std::string::npos);
    unselected =
        unselected || (e.card == "TEMPD" && e.reason.find("thermal load sets 9, 12 not selected") != std::string::npos);
  }
  EXPECT_TRUE(init);
  EXPECT_TRUE(unselected);
  EXPECT_NO_THROW(solutions::solve_static(ok));
}

// Shells of a PCOMP or of MAT8/MAT2 materials: their ply/material expansion coefficients are used
// (MYSTRAN's VD0114 subcase 2, a heated [0/45/-45/90]s PCOMP, ran once with no load at all, then was
// refused; now it is computed): a set that heats them runs, with or without expansion coefficients.
TEST(LoadsBadInput, ThermalSetsOnCompositeShellsRun) {
  const std::string pcomp = "MAT8,8,1.81+11,1.03+10,.28,7.17+9,5.+9,4.+9,1600.\n,0.02-6,22.5-6\nPCOMP,3\n,8,.001,0.,,8,.001,90.\n"
                            "GRID,7,,0.,2.,0.\nGRID,8,,1.,2.,0.\nCQUAD4,11,3,4,5,8,7\n";
  const auto s = solutions::solve_static(test::read_deck(deck("TEMP(LOAD) = 7\n", pcomp + "TEMP,7,7,80.\nTEMPD,7,20.\n")));
  EXPECT_GT(s.u_g.cwiseAbs().maxCoeff(), 0.0);  // the unsymmetric [0/90] curls
  const std::string mat8_pshell = "MAT8,8,1.81+11,1.03+10,.28,7.17+9,5.+9,4.+9,1600.\nPSHELL,3,8,.002,8\n"
                                  "GRID,7,,0.,2.,0.\nGRID,8,,1.,2.,0.\nCQUAD4,11,3,4,5,8,7\n";
  EXPECT_NO_THROW(solutions::solve_static(
      test::read_deck(deck("TEMP(LOAD) = 7\n", mat8_pshell + "TEMPRB,7,1,30.,30.\nTEMPRB,7,2,30.,30.\nTEMP,7,8,80.\nTEMPD,7,20.\n"))));
}

TEST(LoadsBadInput, CommandLineExitsThree) {
  test::TempDir dir;
  dir.write("bad.bdf", deck("LOAD = 5\n", "PLOAD2,5,1.,2\n"));
  const auto r = test::run_seflex("static bad.bdf", dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("error: bad.bdf:18: PLOAD2 5"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace seflex
