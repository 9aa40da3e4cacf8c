// Every command prints what the deck holds that its solution does not use (warnings on stderr, count
// and first file:line per card) and refuses what it needs and cannot use; RBE3/RBAR/MPC models reduce;
// the Guyan header; statics of several subcases.
#include <gtest/gtest.h>

#include <sstream>

#include "seflex/io/superelement_file.hpp"
#include "test_support.hpp"

namespace seflex {
namespace {

/// A frame: two cantilevers along x (grids 1-4 and 11-14, clamped at 1 and 11 by SPC set 1) joined
/// by a cross bar 4-14, carrying a mass (CONM2 on grid 100) through an RBE3 on grids 3, 5, 13, 14
/// (5 hangs on 4 by an RBAR), with an MPC (set 3) tying the T3 of grids 12 and 2; a PLOADX1 in an unselected load set, a DESVAR, an
/// EIGRL that METHOD does not select.
std::string frame_deck(const std::string& case_control) {
  return "SOL 101\nCEND\n" + case_control +
         "BEGIN BULK\n"
         "MAT1,1,7.e10,,0.3,2700.\n"
         "PBAR,1,1,4.e-4,2.e-8,3.e-8,4.e-8\n"
         "GRID,1,,0.,0.,0.\nGRID,2,,0.5,0.,0.\nGRID,3,,1.,0.,0.\nGRID,4,,1.5,0.,0.\nGRID,5,,1.7,0.,0.1\n"
         "GRID,11,,0.,1.,0.\nGRID,12,,0.5,1.,0.\nGRID,13,,1.,1.,0.\nGRID,14,,1.5,1.,0.\n"
         "GRID,100,,1.6,0.5,0.2\n"
         "CBAR,1,1,1,2,0.,0.,1.\nCBAR,2,1,2,3,0.,0.,1.\nCBAR,3,1,3,4,0.,0.,1.\n"
         "CBAR,11,1,11,12,0.,0.,1.\nCBAR,12,1,12,13,0.,0.,1.\nCBAR,13,1,13,14,0.,0.,1.\nCBAR,20,1,4,14,0.,0.,1.\n"
         "RBE3,50,,100,123456,1.,123,3,5\n,13,14\n"
         "RBAR,51,4,5,123456\n"
         "CONM2,60,100,,3.,,,,\n,.01,,.02,,,.03\n"
         "MPC,3,12,3,1.,2,3,-1.\n"
         "SPC1,1,123456,1,11\n"
         "FORCE,7,100,,10.,0.,0.,1.\nFORCE,8,100,,10.,0.,1.,0.\n"
         "PLOADX1,9,1,5.\n"
         "DESVAR,1,T,1.,0.,2.\n"
         "EIGRL,2,,,4\n"
         "ENDDATA\n";
}

TEST(CardUsageCli, StaticPrintsWarningsAndSolvesEverySubcase) {
  test::TempDir dir;
  dir.write("frame.bdf", frame_deck("SPC = 1\nMPC = 3\nSUBCASE 1\nLOAD = 7\nSUBCASE 2\nLOAD = 8\n"));
  const auto r = test::run_seflex("static frame.bdf -o u.csv --system global", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* w : {"warning: PLOADX1: 1 card, first at frame.bdf:",
                        "load set 9 not selected by any subcase linear statics (SOL 101) runs",
                        "warning: DESVAR: 1 card, first at frame.bdf:", "design optimisation data are not used",
                        "warning: EIGRL: 1 card", "eigenvalue methods are not used by linear statics"})
    EXPECT_NE(r.err.find(w), std::string::npos) << w << "\n" << r.err;
  EXPECT_EQ(r.err.find("error"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("2 subcases"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("subcase 2: LOAD 8, SPC 1, MPC 3"), std::string::npos) << r.out;
  // CSV: subcase column, both subcases; the MPC ties grid 12's and grid 2's T3
  std::istringstream csv(test::read_file(dir / "u.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "subcase,grid,t1,t2,t3,r1,r2,r3");
  std::map<std::pair<int, int>, std::vector<double>> rows;
  while (std::getline(csv, line)) {
    std::vector<double> v;
    std::istringstream f(line);
    for (std::string x; std::getline(f, x, ',');) v.push_back(std::stod(x));
    rows[{static_cast<int>(v[0]), static_cast<int>(v[1])}] = v;
  }
  EXPECT_EQ(rows.size(), 2u * 10u);
  EXPECT_NEAR(rows.at({1, 12})[4], rows.at({1, 2})[4], 1e-15);
  EXPECT_GT(std::abs(rows.at({1, 2})[4]), 0.0);

  // the unselected PLOADX1 selected: refused, naming the card and line
  dir.write("bad.bdf", frame_deck("SPC = 1\nLOAD = 9\n"));
  const auto bad = test::run_seflex("static bad.bdf", dir.path());
  EXPECT_EQ(bad.exit_code, 3);
  EXPECT_NE(bad.err.find("error: bad.bdf:34: PLOADX1: load set 9 selected by the case control holds them, and seflex does "
                         "not apply PLOADX1 loads; linear statics (SOL 101) cannot run without it"),
            std::string::npos)
      << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad_displacements.csv"));
}

TEST(CardUsageCli, InfoClassifiesForTheDecksSolConvertAndModesWarn) {
  test::TempDir dir;
  dir.write("frame.bdf", frame_deck("SPC = 1\nLOAD = 9\nMETHOD = 2\n"));
  const auto info = test::run_seflex("info frame.bdf", dir.path());
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("card use by linear statics (SOL 101), the deck's SOL"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("refused (the solution stops with an error)\n    PLOADX1: 1 card, first at frame.bdf:35"),
            std::string::npos)
      << info.out;
  EXPECT_NE(info.out.find("RBE3"), std::string::npos);
  EXPECT_NE(info.out.find("RBAR"), std::string::npos);

  const auto modes = test::run_seflex("modes frame.bdf", dir.path());
  ASSERT_EQ(modes.exit_code, 0) << modes.err;
  EXPECT_NE(modes.err.find("warning: PLOADX1: 1 card, first at frame.bdf:35: loads are not used by normal modes (SOL 103)"),
            std::string::npos)
      << modes.err;

  const auto convert = test::run_seflex("convert frame.bdf -o out.bdf", dir.path());
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  EXPECT_NE(convert.err.find("warning: PLOADX1: 1 card, first at frame.bdf:35: not written"), std::string::npos)
      << convert.err;
  const std::string written = test::read_file(dir / "out.bdf");
  for (const char* card : {"RBE3,50", "RBAR,51", "MPC,3,12,3,1.,2,3,-1."})
    EXPECT_NE(written.find(card), std::string::npos) << card << "\n" << written;
}

// seflex reduce on a model with RBE3, RBAR and MPC: with every fixed-interface mode kept the reduced
// model reproduces the full model's free-free frequencies (Craig-Bampton is then exact); the warnings travel in the .se file and seflex export prints them again. An RBE3 reference
// grid as an interface node is refused with the reason.
TEST(CardUsageCli, ReduceAcceptsRbe3RbarMpcAndExportRepeatsTheWarnings) {
  test::TempDir dir;
  dir.write("frame.bdf", frame_deck("MPC = 3\n"));  // free-free: no SPC selected
  const auto r = test::run_seflex("reduce frame.bdf --interface 1,11 --modes 1000 --compare 6 -o f.se", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: SPC/SPC1: 2 cards, first at frame.bdf:"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("MPC set 3"), std::string::npos) << r.out;
  // the comparison table: every elastic frequency agrees to round-off
  std::istringstream out(r.out.substr(r.out.find("full FE (Hz)")));
  std::string line;
  std::getline(out, line);
  int rows = 0, rigid = 0;
  while (std::getline(out, line) && !line.empty()) {
    std::istringstream f(line);
    int mode;
    double red, full;
    std::string rel;
    f >> mode >> red >> full >> rel;
    if (rel == "(rigid)") {
      ++rigid;
      continue;
    }
    ++rows;
    EXPECT_LT(std::abs(std::stod(rel)), 1e-8) << line;
  }
  // 5 rigid-body modes: the MPC (equal T3 at y = 0 and y = 1) forbids the rotation about x
  EXPECT_EQ(rigid, 5);
  EXPECT_EQ(rows, 7);
  const se::Superelement s = io::load_superelement(dir / "f.se");
  ASSERT_FALSE(s.source_warnings.empty());
  const auto e = test::run_seflex("export f.se --op4 f.op4", dir.path());
  ASSERT_EQ(e.exit_code, 0) << e.err;
  EXPECT_NE(e.err.find("warning (reduction of frame.bdf): PLOADX1: 1 card"), std::string::npos) << e.err;

  const auto ref = test::run_seflex("reduce frame.bdf --interface 100,1 -o g.se", dir.path());
  EXPECT_EQ(ref.exit_code, 3);
  EXPECT_NE(ref.err.find("interface node 100: components 123456 are the dependent reference of RBE3 50 (frame.bdf:"),
            std::string::npos)
      << ref.err;
  EXPECT_NE(ref.err.find("make the reference grid independent with UM"), std::string::npos) << ref.err;
}

// seflex modes on a deck with ASET says so above the eigenvalue table.
TEST(CardUsageCli, ModesSaysGuyanReduction) {
  test::TempDir dir;
  dir.write("g.bdf", "SOL 103\nCEND\nMETHOD = 1\nSPC = 123\nBEGIN BULK\nEIGR,1,GIV,,,,10\nSPC1,123,26,101\n"
                     "GRDSET,,,,,,,1345\nGRID,101,,0.,0.,0.\nGRID,102,,10.,0.,0.\nGRID,103,,20.,0.,0.\n"
                     "CBAR,11,10,101,102,0.,1.,0.\nCBAR,12,10,102,103,0.,1.,0.\nPBAR,10,10,.01,.1,.1,.1\n"
                     "MAT1,10,1.+7,,.33,.1\nASET1,26,103\nPARAM,WTMASS,.002591\nENDDATA\n");
  const auto r = test::run_seflex("modes g.bdf", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Guyan reduction to the a-set: 2 a-set dofs (ASET/ASET1), 2 omitted dofs condensed statically"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("(Guyan reduction: eigenvalues of the 2-dof a-set of the ASET/ASET1 cards"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("2.413794E+07"), std::string::npos) << r.out;  // MYSTRAN's GUYAN-03 (normal_modes_test.cpp)
}

}  // namespace
}  // namespace seflex
