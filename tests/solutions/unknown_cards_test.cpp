// No solution runs on a deck with cards seflex does not know unless asked (issue 40): static, modes,
// buckling and reduce refuse with the list of those cards (card, count, first file:line) and the
// option that proceeds (--ignore-unknown); info lists them. A solve that leaves no free dof is
// refused, naming why. The refusal is the library's (solutions::require_usable, require_free_dofs),
// so that every caller of the solutions gets it. Also run under ASan + UBSan.
#include <gtest/gtest.h>

#include "nastran_test_util.hpp"
#include "seflex/solutions/normal_modes.hpp"
#include "seflex/solutions/statics.hpp"
#include "test_support.hpp"

namespace seflex {
namespace {

using test::mentions;

/// A clamped two-bar cantilever (grids 1-3, SPC set 1) with a tip FORCE (load set 7), EIGRL 1, and
/// `more` bulk data after it (the first line of `more` is line 16 with kCases).
std::string cantilever(const std::string& case_control, const std::string& more) {
  return "SOL 101\nCEND\n" + case_control + "BEGIN BULK\n" +
         "MAT1,1,7.e10,,0.3,2700.\nPBAR,1,1,1.e-4,2.e-8,2.e-8,4.e-8\n"
         "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,2.,0.,0.\n"
         "CBAR,1,1,1,2,0.,1.,0.\nCBAR,2,1,2,3,0.,1.,0.\nSPC1,1,123456,1\nFORCE,7,3,0,1.,0.,0.,1.\n" + more +
         "EIGRL,1,,,2\nENDDATA\n";
}

// Old COSMIC elements seflex does not know (the decks), after the cantilever.
const std::string kUnknown = "CQDMEM1,10,1,1,2,3\nCQUAD1,11,1,1,2,3,1\nCQDMEM1,12,1,1,2,3\n";
const std::string kCases = "SPC = 1\nLOAD = 7\nMETHOD = 1\n";

TEST(UnknownCards, SolutionsRefuseWithTheListAndTheOption) {
  const fem::Model m = test::read_deck(cantilever(kCases, kUnknown));
  const std::string expected =
      "deck.bdf:16: 2 kinds of card seflex does not know: CQDMEM1 (2 cards, first at deck.bdf:16), CQUAD1 (1 card, at "
      "deck.bdf:17); linear statics (SOL 101) does not run on a deck with cards it does not know (MSC Nastran stops on "
      "them too): correct or remove them, or give --ignore-unknown to run without them";
  try {
    solutions::solve_statics(m);
    ADD_FAILURE() << "solved";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), expected);
  }
  try {
    solutions::solve_normal_modes(m);
    ADD_FAILURE() << "solved";
  } catch (const InputError& e) {
    EXPECT_TRUE(mentions(e.what(), {"deck.bdf:16: 2 kinds of card seflex does not know", "normal modes (SOL 103) does not run"}));
  }
  // asked to: the same answer as the deck without them
  solutions::StaticOptions o;
  o.ignore_unknown_cards = true;
  const auto with = solutions::solve_statics(m, o);
  const auto without = solutions::solve_statics(test::read_deck(cantilever(kCases, "")));
  ASSERT_EQ(with.size(), 1u);
  EXPECT_EQ(with[0].u_g, without[0].u_g);
  solutions::ModesOptions mo;
  mo.ignore_unknown_cards = true;
  EXPECT_EQ(solutions::solve_normal_modes(m, mo).eigenvalues, solutions::solve_normal_modes(test::read_deck(cantilever(kCases, ""))).eigenvalues);
}

TEST(UnknownCards, EveryCommandRefusesButInfo) {
  test::TempDir dir;
  dir.write("deck.bdf", cantilever(kCases, kUnknown));
  const std::string list =
      "error: deck.bdf:16: 2 kinds of card seflex does not know: CQDMEM1 (2 cards, first at deck.bdf:16), CQUAD1 (1 card, "
      "at deck.bdf:17); ";
  const std::string tail =
      " does not run on a deck with cards it does not know (MSC Nastran stops on them too): correct or remove them, or "
      "give --ignore-unknown to run without them\n";
  const std::pair<std::string, std::string> commands[] = {
      {"static deck.bdf -o u.csv", "linear statics (SOL 101)"},
      {"modes deck.bdf --csv f.csv", "normal modes (SOL 103)"},
      {"reduce deck.bdf --interface 3 --modes 2 -o b.se", "the Craig-Bampton reduction"},
  };
  for (const auto& [command, solution] : commands) {
    const auto r = test::run_seflex(command, dir.path());
    EXPECT_EQ(r.exit_code, 3) << command;
    // the warnings of the cards the solution does not use come first; the error is the last line
    const std::string last = r.err.substr(r.err.rfind("error: "));
    EXPECT_EQ(last, list + solution + tail) << command;
  }
  // buckling: its preload subcase and its METHOD subcase
  dir.write("buckle.bdf", "SOL 105\nCEND\nSPC = 1\nSUBCASE 1\nLOAD = 7\nSUBCASE 2\nMETHOD = 1\nBEGIN BULK\n"
                          "CQDMEM1,10,1,1,2,3\nMAT1,1,7.e10,,0.3,2700.\nPBAR,1,1,1.e-4,2.e-8,2.e-8,4.e-8\n"
                          "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,2.,0.,0.\nCBAR,1,1,1,2,0.,1.,0.\n"
                          "CBAR,2,1,2,3,0.,1.,0.\nSPC1,1,123456,1\nFORCE,7,3,0,-1.,1.,0.,0.\nEIGRL,1,,,2\nENDDATA\n");
  const auto b = test::run_seflex("buckling buckle.bdf", dir.path());
  EXPECT_EQ(b.exit_code, 3);
  EXPECT_EQ(b.err.substr(b.err.rfind("error: ")),
            "error: buckle.bdf:9: a card seflex does not know: CQDMEM1 (1 card, at buckle.bdf:9); buckling (SOL 105)" + tail);
  const auto bi = test::run_seflex("buckling buckle.bdf --ignore-unknown", dir.path());
  EXPECT_EQ(bi.exit_code, 0) << bi.err;
  // info lists them: among the refusals of the deck's SOL; without a SOL, saying what a solution does
  const auto info = test::run_seflex("info deck.bdf", dir.path());
  EXPECT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("  refused (the solution stops with an error)\n"
                          "    CQDMEM1: 2 cards, first at deck.bdf:16: a card seflex does not know\n"
                          "    CQUAD1: 1 card, first at deck.bdf:17: a card seflex does not know\n"),
            std::string::npos)
      << info.out;
  std::string no_sol = cantilever(kCases, kUnknown);
  no_sol.erase(0, no_sol.find("CEND"));
  dir.write("nosol.bdf", no_sol);
  const auto info2 = test::run_seflex("info nosol.bdf", dir.path());
  EXPECT_EQ(info2.exit_code, 0) << info2.err;
  EXPECT_NE(info2.out.find("CQDMEM1: 2 cards, first at nosol.bdf:15: a card seflex does not know: static, modes, "
                           "buckling and reduce refuse the deck (--ignore-unknown runs them without it)"),
            std::string::npos)
      << info2.out;
  // --ignore-unknown: a warning per kind, and the solution
  const auto s = test::run_seflex("static deck.bdf -o u.csv --ignore-unknown", dir.path());
  EXPECT_EQ(s.exit_code, 0) << s.err;
  EXPECT_NE(s.err.find("warning: CQDMEM1: 2 cards, first at deck.bdf:16: a card seflex does not know; ignored "
                       "(--ignore-unknown)\nwarning: CQUAD1: 1 card, first at deck.bdf:17: a card seflex does not know; "
                       "ignored (--ignore-unknown)\n"),
            std::string::npos)
      << s.err;
  const auto red = test::run_seflex("reduce deck.bdf --interface 3 --modes 2 -o b.se --ignore-unknown", dir.path());
  EXPECT_EQ(red.exit_code, 0) << red.err;
}

// A deck whose elements are all unknown: with --ignore-unknown nothing is left to solve, and the
// solution says why instead of writing zero displacements or an empty table.
TEST(UnknownCards, NoFreeDofIsRefusedNamingWhy) {
  test::TempDir dir;
  dir.write("cosmic.bdf", "SOL 101\nCEND\nLOAD = 7\nMETHOD = 1\nBEGIN BULK\nGRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\n"
                          "GRID,3,,1.,1.,0.\nCQDMEM1,10,1,1,2,3\nCTRAPRG,11,1,2,3\nFORCE,7,3,0,1.,0.,0.,1.\n"
                          "EIGRL,1,,,2\nENDDATA\n");
  const std::string why =
      "has nothing to solve: no free dof (the model has no element with stiffness: AUTOSPC removed all 18 dofs; the "
      "cards seflex does not know (CQDMEM1, CTRAPRG) were left out); expected elements seflex models "
      "(docs/nastran-support.md)\n";
  const auto s = test::run_seflex("static cosmic.bdf --ignore-unknown", dir.path());
  EXPECT_EQ(s.exit_code, 3);
  EXPECT_EQ(s.err.substr(s.err.rfind("error: ")), "error: cosmic.bdf: linear statics (SOL 101) " + why);
  const auto m = test::run_seflex("modes cosmic.bdf --ignore-unknown", dir.path());
  EXPECT_EQ(m.exit_code, 3);
  EXPECT_EQ(m.err.substr(m.err.rfind("error: ")), "error: cosmic.bdf: normal modes (SOL 103) " + why);
  // every dof constrained: a rod held at both ends in all six components. Normal modes have nothing to
  // find; statics gives the SPC forces (here the reaction to the load: 1 N in x at grid 2)
  const fem::Model held = test::read_deck(
      "SOL 103\nCEND\nSPC = 1\nLOAD = 7\nMETHOD = 1\nBEGIN BULK\nMAT1,1,7.e10,,0.3,2700.\nPROD,1,1,1.e-4\n"
      "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nCROD,1,1,1,2\nSPC1,1,123456,1,2\nFORCE,7,2,0,1.,1.,0.,0.\nEIGRL,1,,,2\n"
      "ENDDATA\n");
  try {
    solutions::solve_normal_modes(held);
    ADD_FAILURE() << "solved";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "deck.bdf: normal modes (SOL 103) has nothing to solve: no free dof (every one of "
                                     "the 12 dofs is constrained: 12 by SPC/SPC1 or GRID PS); expected a structure that "
                                     "can deform");
  }
  const auto reactions = solutions::solve_statics(held);
  ASSERT_EQ(reactions.size(), 1u);
  EXPECT_EQ(reactions[0].n_free, 0);
  EXPECT_EQ(reactions[0].q_g(6), -1.0);  // grid 2, T1
  // a model with no grid at all
  const fem::Model empty = test::read_deck("SOL 101\nCEND\nBEGIN BULK\nMAT1,1,7.e10,,0.3\nENDDATA\n");
  try {
    solutions::solve_statics(empty);
    ADD_FAILURE() << "solved";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "deck.bdf: linear statics (SOL 101) has nothing to solve: no free dof (the model has no GRID or SPOINT)");
  }
}

}  // namespace
}  // namespace seflex
