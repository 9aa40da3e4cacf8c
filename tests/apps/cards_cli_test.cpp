// The new cards through the command line: `seflex info`, `static`, `modes`, `reduce` and `convert` on
// one deck (a CBUSH cantilever with CONM1, CMASS2, CELAS4 on a scalar point, a PBARL HAT bar with a
// PLOAD1, and an SPCD subcase). Static reference: the CBUSH hand result of bush_scalar_test.cpp,
// w_B = F / K2 + F (1 - S)^2 L^2 / K6 with S = 0.5, and the enforced displacement itself.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "test_support.hpp"

namespace seflex {
namespace {

const char* kDeck =
    "SOL 101\nCEND\nSPC = 1\nSUBCASE 1\n  LOAD = 2\nSUBCASE 2\n  LOAD = 3\nBEGIN BULK\n"
    "GRID,1,,0.,0.,0.\nGRID,2,,2.,0.,0.\nGRID,3,,2.,1.,0.\nGRID,4,,4.,1.,0.\nSPOINT,10\n"
    "SPC1,1,123456,1,3\nSPC1,1,3,4\nFORCE,2,2,,100.,0.,0.,1.\nSPCD,3,4,3,0.002\n"
    "PBUSH,70,K,1.e5,2.e4,3.e5,4.e5,5.e5,6.e3\nCBUSH,7,70,1,2,0.,0.,1.\n"
    "CONM1,8,2,,2.,,2.,,,\n,2.,0.1,,,0.1,,,\n,,0.1,,,,,,0.1\n"
    "CMASS2,9,0.5,2,1,,\nCELAS4,11,50.,10\nCMASS4,12,0.2,10\n"
    "MAT1,1,7.e10,,0.3,2700.\nPBARL,20,1,,HAT\n,0.05,0.003,0.04,0.015\nCBAR,21,20,3,4,0.,0.,1.\n"
    "PLOAD1,2,21,FZ,FR,0.,-50.,1.,-50.\nENDDATA\n";

TEST(CardsCli, InfoStaticModesReduceConvert) {
  test::TempDir dir;
  const auto deck = dir.write("cards.bdf", kDeck);
  const auto info = test::run_seflex("info cards.bdf", dir.path());
  ASSERT_EQ(info.exit_code, 0) << info.err;
  for (const char* s : {"CBUSH", "CONM1", "CMASS1-4", "CELAS3/CELAS4", "PLOAD1", "SPCD"}) EXPECT_NE(info.out.find(s), std::string::npos) << s;

  const auto st = test::run_seflex("static cards.bdf -o out.csv", dir.path());
  ASSERT_EQ(st.exit_code, 0) << st.err << st.out;
  const double w = 100.0 / 2e4 + 100.0 * 0.25 * 4.0 / 6e3;
  // two subcases: subcase,grid,t1,t2,t3,r1,r2,r3
  bool found1 = false, found2 = false;
  for (const auto& v : test::csv_rows(dir / "out.csv")) {
    ASSERT_EQ(v.size(), 8u);
    if (v[0] == 1 && v[1] == 2 && std::abs(v[4] - w) < 1e-9 * w) found1 = true;
    if (v[0] == 2 && v[1] == 4 && std::abs(v[4] - 0.002) < 1e-12) found2 = true;
  }
  EXPECT_TRUE(found1) << "CBUSH tip deflection " << w << " not in the CSV output\n" << st.out;
  EXPECT_TRUE(found2) << "SPCD value not in the CSV output\n" << st.out;

  const auto cv = test::run_seflex("convert cards.bdf -o back.bdf", dir.path());
  ASSERT_EQ(cv.exit_code, 0) << cv.err;
  const auto back = test::run_seflex("static back.bdf -o back.csv", dir.path());
  ASSERT_EQ(back.exit_code, 0) << back.err;

  const auto modes = test::run_seflex("modes cards.bdf --count 3", dir.path());
  EXPECT_EQ(modes.exit_code, 0) << modes.err;
  // a free component for the Craig-Bampton reduction: CBUSH hinge at interface grid 1, CONM1, HAT bar, CMASS2
  const auto free_deck = dir.write("free.bdf",
                                   "SOL 103\nCEND\nBEGIN BULK\nGRID,1,,0.,0.,0.\nGRID,2,,2.,0.,0.\nGRID,3,,4.,0.,0.\n"
                                   "PBUSH,70,K,1.e5,2.e4,3.e5,4.e5,5.e5,6.e3\nCBUSH,7,70,1,2,0.,0.,1.\n"
                                   "CONM1,8,2,,2.,,2.,,,\n,2.,0.1,,,0.1,,,\n,,0.1,,,,,,0.1\nCMASS2,9,0.5,3,1\n"
                                   "MAT1,1,7.e10,,0.3,2700.\nPBARL,20,1,,HAT\n,0.05,0.003,0.04,0.015\nCBAR,21,20,2,3,0.,0.,1.\n"
                                   "CONM2,22,3,,1.,,,,,\n,0.01,,0.01,,,0.01\nENDDATA\n");
  const auto red = test::run_seflex("reduce free.bdf --interface 1 --modes 2 -o b.se", dir.path());
  EXPECT_EQ(red.exit_code, 0) << red.err << red.out;
}

}  // namespace
}  // namespace seflex
