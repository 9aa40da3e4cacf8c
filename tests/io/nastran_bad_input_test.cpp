// Bad Nastran input: every case must throw InputError whose message names the file, line, card,
// field and what was expected - and the seflex command must exit with status 3 without crashing.
// These tests also run under AddressSanitizer + UndefinedBehaviorSanitizer in CI.
#include <gtest/gtest.h>

#include <fstream>

#include "nastran_test_util.hpp"
#include "test_support.hpp"

using namespace seflex;
using seflex::test::base_deck;
using seflex::test::fixed_line;
using seflex::test::mentions;
using seflex::test::read_deck;
using seflex::test::read_error;

namespace {

/// Write `text` to a deck, run `seflex info` on it: exit 3, one "error:" line naming `parts`.
void expect_cli_input_error(const std::string& text, std::initializer_list<std::string> parts) {
  test::TempDir dir;
  const auto deck = dir.write("bad.bdf", text);
  const auto r = test::run_seflex("info '" + deck.string() + "'");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_TRUE(mentions(r.err, parts));
}

}  // namespace

TEST(NastranBadInput, TruncatedCard) {
  EXPECT_TRUE(mentions(read_error(base_deck() + "CQUAD4,1,1,1,2,3\n"),
                       {"deck.bdf:7: CQUAD4 1, field 7 (G4): blank; expected an integer > 0"}));
  EXPECT_TRUE(mentions(read_error(base_deck() + "CBAR    1       1       1\n"), {"deck.bdf:7: CBAR 1, field 5 (GB): blank"}));
  EXPECT_TRUE(mentions(read_error("GRID\n"), {"deck.bdf:1: GRID, field 2 (ID): blank; expected an integer > 0"}));
}

TEST(NastranBadInput, WrongFieldTypes) {
  EXPECT_TRUE(mentions(read_error(base_deck() + fixed_line({"CQUAD4", "1", "1.", "1", "2", "3", "4"})),
                       {"deck.bdf:7: CQUAD4 1, field 3 (PID): got real '1.'", "expected an integer"}));
  EXPECT_TRUE(mentions(read_error("GRID,1,,abc,0.,0.\n"), {"deck.bdf:1: GRID 1, field 4 (X1): got text 'abc'", "expected a real"}));
  EXPECT_TRUE(mentions(read_error("GRID,1,,1,0.,0.\n"), {"field 4 (X1): got integer '1'", "decimal point"}));
  EXPECT_TRUE(mentions(read_error("GRID,1,,1.2.3,0.,0.\n"), {"field 4 (X1): got '1.2.3', which is not a number"}));
  EXPECT_TRUE(mentions(read_error("GRID,1,,0.,0.,0.,,1237\n"), {"field 8 (PS): got integer '1237'", "component numbers 1-6"}));
  EXPECT_TRUE(mentions(read_error("GRID,1,,0.,0.,0.,,1123\n"), {"component 1 repeated"}));
  EXPECT_TRUE(mentions(read_error("GRID,-4,,0.,0.,0.\n"), {"GRID -4, field 2 (ID): got integer '-4'; expected an integer > 0"}));
  EXPECT_TRUE(mentions(read_error("GRID,1,,0.,0.,0.\nGRID,99999999999,,0.,0.,0.\n"), {"deck.bdf:2", "99999999999", "not a number"}));
  // a field on a continuation line: the message names that line
  EXPECT_TRUE(mentions(read_error(base_deck() + "CONM2,5,1,,1.\n,1.,,x\n"), {"deck.bdf:8: CONM2 5, field 4 (I22): got text 'x'"}));
}

// References of the cards of case-control sets (SPC, LOAD, METHOD ...) and PARAM GRDPNT's grid are
// checked when a solution selects them (tests/solutions/card_usage_test.cpp), not when the deck is read.
TEST(NastranBadInput, MissingReferences) {
  const std::string d = base_deck();
  EXPECT_TRUE(mentions(read_error(d + "CQUAD4,9,1,1,2,3,77\n"),
                       {"deck.bdf:7: CQUAD4 9, field 7 (G4): references grid 77, which is not defined"}));
  EXPECT_TRUE(mentions(read_error(d + "CQUAD4,9,5,1,2,3,4\n"), {"CQUAD4 9, field 3 (PID): references property 5", "PSHELL"}));
  // the property is there but seflex does not read its card: the element is left out and listed
  // (every solution refuses it: tests/solutions/public_deck_tolerance_test.cpp)
  const fem::Model left_out = test::read_deck(d + "CQUAD4,9,5,1,2,3,4\nPCOMPX,5,,,\n");
  EXPECT_TRUE(left_out.shells.empty());
  bool listed = false;
  for (const auto& u : left_out.unsupported) listed = listed || (u.name == "CQUAD4 on PCOMPX (left out)" && u.first.line == 7);
  EXPECT_TRUE(listed);
  EXPECT_TRUE(mentions(read_error(d + "PSHELL,2,8,.1\n"), {"deck.bdf:7: PSHELL 2, field 3 (MID1): references material 8, which is not defined"}));
  EXPECT_TRUE(mentions(read_error(d + "GRID,9,3,0.,0.,0.\n"), {"GRID 9, field 3 (CP): references coordinate system 3"}));
  EXPECT_TRUE(mentions(read_error(d + "CONM2,9,1,4,1.\n"), {"CONM2 9, field 4 (CID): references coordinate system 4"}));
  EXPECT_TRUE(mentions(read_error(d + "CBAR,9,1,1,2,0.,0.,1.\n"), {"CBAR 9, field 3 (PID): references property 1", "PBAR or PBARL"}));
  EXPECT_TRUE(mentions(read_error(d + "CORD2R,3,7,0.,0.,0.,0.,0.,1.\n,1.,0.,0.\n"), {"CORD2R 3, field 3 (RID): references coordinate system 7"}));
  EXPECT_TRUE(mentions(read_error(d + "CORD1R,3,1,2,44\n"), {"CORD1R 3, G3: references grid 44"}));
  EXPECT_TRUE(mentions(read_error(d + "CBAR,9,9,1,2\nPBAR,9,1,1.\n"), {"CBAR 9, field 6 (X1/G0): blank and no BAROR"}));
  EXPECT_TRUE(mentions(read_error(d + "CBEAM,9,9,1,2,0.,0.,1.\nPBAR,9,1,1.\n"), {"CBEAM 9, field 3 (PID): references PBAR 9", "PBEAM"}));
}

TEST(NastranBadInput, DuplicateIds) {
  const std::string d = base_deck();
  EXPECT_TRUE(mentions(read_error(d + "GRID,3,,5.,5.,5.\n"),
                       {"deck.bdf:7: GRID 3, field 2 (ID): duplicate grid id, first defined at deck.bdf:5"}));
  EXPECT_TRUE(mentions(read_error(d + "CQUAD4,5,1,1,2,3,4\nCONM2,5,1,,1.\n"), {"deck.bdf:8: CONM2 5", "duplicate element id", "deck.bdf:7"}));
  EXPECT_TRUE(mentions(read_error(d + "PROD,1,1,1.\n"), {"PROD 1", "duplicate property id", "deck.bdf:2"}));
  EXPECT_TRUE(mentions(read_error(d + "MAT1,1,1.,,.3\n"), {"MAT1 1", "duplicate material id"}));
  EXPECT_TRUE(mentions(read_error(d + "SPOINT,3\n"), {"deck.bdf:7: SPOINT 3: the id is also a GRID (at deck.bdf:5); expected grid and scalar point ids to be distinct"}));
  EXPECT_TRUE(mentions(read_error(d + "EIGRL,1,,,3\nEIGR,1,LAN\n"), {"EIGR 1", "duplicate method id"}));
  EXPECT_TRUE(mentions(read_error(d + "PARAM,WTMASS,1.\nPARAM,WTMASS,2.\n"), {"deck.bdf:8: PARAM WTMASS", "a second value"}));
  EXPECT_TRUE(mentions(read_error(d + "GRDSET,,1\nGRDSET,,2\n"), {"deck.bdf:8: GRDSET", "a second GRDSET", "deck.bdf:7"}));
}

// The same inside a part (BEGIN SUPER): its cards name the first card's file from the part's own
// model, which once held no file names (a fuzz finding: `seflex info` crashed with SIGSEGV).
TEST(NastranBadInput, SecondBarDefaultsInAPart) {
  const std::string d = base_deck() + "BEGIN SUPER = 2\nGRID,20,,1.,0.,0.\n";
  EXPECT_TRUE(mentions(read_error(d + "BAROR,,,,,1.,0.,0.\nBAROR,,,,,1.,0.,0.\n"),
                       {"deck.bdf:10: BAROR", "a second BAROR", "(the first is at deck.bdf:9)"}));
  EXPECT_TRUE(mentions(read_error(d + "GRDSET,,1\nGRDSET,,2\n"), {"deck.bdf:10: GRDSET", "a second GRDSET", "deck.bdf:9"}));
  expect_cli_input_error(d + "BEAMOR,,,,,1.,0.,0.\nBEAMOR,,,,,1.,0.,0.\n", {"a second BEAMOR"});
}

TEST(NastranBadInput, IncludeCycleAndMissingInclude) {
  test::TempDir dir;
  dir.write("a.bdf", "GRID,1,,0.,0.,0.\nINCLUDE 'b.bdf'\n");
  dir.write("b.bdf", "$ b\nINCLUDE 'a.bdf'\n");
  EXPECT_TRUE(mentions([&] {
    try {
      io::read_nastran(dir / "a.bdf");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  }(), {"b.bdf:2: INCLUDE 'a.bdf' is an include cycle (a.bdf -> b.bdf -> a.bdf)"}));
  dir.write("c.bdf", "GRID,1,,0.,0.,0.\nINCLUDE 'missing.bdf'\n");
  dir.write("d.bdf", "GRID,1,,0.,0.,0.\nINCLUDE 'unterminated.bdf\n");
  dir.write("e.bdf", "GRID,1,,0.,0.,0.\nINCLUDE sub\n");
  std::filesystem::create_directories(dir / "sub");
  auto error_of = [&](const char* name) {
    try {
      io::read_nastran(dir / name);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_TRUE(mentions(error_of("c.bdf"), {"c.bdf:2: INCLUDE 'missing.bdf'", "does not exist"}));
  EXPECT_TRUE(mentions(error_of("d.bdf"), {"d.bdf:2: INCLUDE", "no closing quote"}));
  EXPECT_TRUE(mentions(error_of("e.bdf"), {"e.bdf:2: INCLUDE 'sub'", "directory"}));
  EXPECT_TRUE(mentions(error_of("nonexistent.bdf"), {"nonexistent.bdf: no such file"}));
  dir.write("f.bdf", "GRID,1,,0.,0.,0.\nINCLUDE '/dev/zero'\n");  // never read an endless device
  EXPECT_TRUE(mentions(error_of("f.bdf"), {"f.bdf:2: INCLUDE '/dev/zero'", "not a regular file"}));
  expect_cli_input_error("INCLUDE 'bad.bdf'\n", {"bad.bdf:1: INCLUDE 'bad.bdf' is an include cycle"});
}

TEST(NastranBadInput, BinaryGarbageNulBytesHugeLinesEmptyFiles) {
  EXPECT_TRUE(mentions(read_error(std::string("GRID,1,,0.,0.,0.\nGRID,2\0,,0.,0.,0.\n", 34)),
                       {"deck.bdf:2, column 7: a NUL byte (0x00); expected text"}));
  std::string garbage;
  for (int i = 0; i < 4096; ++i) garbage += static_cast<char>((i * 7919 + 13) % 256);
  EXPECT_TRUE(mentions(read_error(garbage), {"deck.bdf:", "expected text"}));
  const std::string huge = "GRID,1,,0.,0.,0.\n" + std::string(10 * 1024 * 1024, 'x') + "\n";
  EXPECT_TRUE(mentions(read_error(huge), {"deck.bdf:2: line is 10485760 characters long; expected at most 65536"}));
  EXPECT_TRUE(mentions(read_error(""), {"deck.bdf: no bulk data cards"}));
  EXPECT_TRUE(mentions(read_error("$ only a comment\n\n   \n"), {"no bulk data cards"}));
  EXPECT_TRUE(mentions(read_error("SOL 103\nCEND\nTITLE = x\n"), {"no BEGIN BULK reached"}));
  EXPECT_TRUE(mentions(read_error("SOL 103\nBEGIN BULK\nGRID,1,,0.,0.,0.\n"), {"deck.bdf:2: BEGIN BULK before CEND"}));
  expect_cli_input_error(garbage, {"bad.bdf:", "expected text"});
  expect_cli_input_error(huge, {"bad.bdf:2: line is 10485760 characters long"});
  expect_cli_input_error("", {"no bulk data cards"});
}

// The line scanner skips eight clean bytes at a time (nastran_lines.cpp): a control character or a
// '$' at any column of a long fixed-format line is still found at its own column.
TEST(NastranBadInput, EveryColumnOfALongLineIsChecked) {
  std::string line = fixed_line({"GRID", "1", "", "0.", "1.5", "2.5"});
  line.pop_back();  // the newline
  ASSERT_EQ(line.size(), 43u);
  for (std::size_t k = 0; k < line.size(); ++k) {
    std::string bad = line;
    bad[k] = '\x01';
    EXPECT_TRUE(mentions(read_error(fixed_line({"GRID", "7", "", "0.", "0.", "0."}) + bad + "\n"),
                         {"deck.bdf:2, column " + std::to_string(k + 1) + ": a control character (0x01)"}))
        << k;
  }
  for (const std::size_t k : {24u, 32u, 40u, 43u}) {  // a comment from column k + 1: later fields blank
    const fem::Model m = read_deck(line.substr(0, k) + "$ the rest is a comment\n");
    ASSERT_EQ(m.grids.size(), 1u) << k;
    EXPECT_EQ(m.grids[0].x.y(), k >= 40 ? 1.5 : 0.0) << k;
    EXPECT_EQ(m.grids[0].x.z(), k >= 43 ? 2.5 : 0.0) << k;
  }
  EXPECT_TRUE(mentions(read_error(line + "\x7f\n"), {"deck.bdf:1, column 44: a control character (0x7F)"}));
}

TEST(NastranBadInput, MalformedLines) {
  EXPECT_TRUE(mentions(read_error("GRID,1,,0.,0.,0.\n=,*1.,,*1.\n"), {"deck.bdf:2: replication of GRID 1, field 2: '*1.' increments '1'"}));
  EXPECT_TRUE(mentions(read_error("GRID,1,,0.,0.,0.\n==,*1\n"), {"deck.bdf:2: replication '=='", "expected '=' or a repeat count"}));
  // a free-field line may hold several card lines (reader tolerance, issue 14), up to 32 of them
  EXPECT_TRUE(mentions(read_error("GRID,1" + std::string(300, ',') + "\n"), {"deck.bdf:1: free-field line has 302 fields; expected at most 257"}));
  EXPECT_TRUE(mentions(read_error("SOL 1\nCEND\nBEGIN BULK\nGRID,1,,0.,0.,0.\nBEGIN AUXMODEL=1\n"), {"deck.bdf:5", "BEGIN AUXMODEL=1", "inside the bulk data"}));
  EXPECT_TRUE(mentions(read_error(base_deck() + "SPC1,1,123,4,THRU,2\n"), {"SPC1 1, field 6 (G): got integer '2' after THRU; expected an id greater than 4"}));
  EXPECT_TRUE(mentions(read_error(base_deck() + "SPC1,1,123,1,THRU,2000000000\n"), {"SPC1 1", "more than 10000000 ids"}));
  EXPECT_TRUE(mentions(read_error("SOL 103\nCEND\nSPC = ALL\nBEGIN BULK\n" + base_deck()), {"deck.bdf:3: case control SPC: got 'ALL'; expected a set id"}));
}

TEST(NastranBadInput, InconsistentCards) {
  const std::string d = base_deck();
  EXPECT_TRUE(mentions(read_error("MAT1,7,,,0.3\n"), {"MAT1 7, field 3 (E): blank, and G is blank too; expected E or G"}));
  EXPECT_TRUE(mentions(read_error("MAT1,7,2.1+11,,-1.7\n"), {"MAT1 7, field 5 (NU): got real '-1.7'; expected -1 < NU <= 0.5"}));
  EXPECT_TRUE(mentions(read_error(d + "PBARL,5,1,,NACA\n,1.,1.,.1,.1\n"), {"PBARL 5, field 5 (TYPE): got text 'NACA'", "ROD, TUBE, BAR, BOX, I, TUBE2, T, T1"}));
  EXPECT_TRUE(mentions(read_error(d + "PBARL,5,1,,BOX\n,1.,1.,.6,.1\n"), {"deck.bdf:8: PBARL 5, field 2 (DIM1): BOX section", "DIM3 = 0.6"}));
  EXPECT_TRUE(mentions(read_error(d + "PBARL,5,1,,TUBE\n,1.,1.\n"), {"TUBE section: DIM2 (inner radius 1)"}));
  EXPECT_TRUE(mentions(read_error(d + "CBAR,9,9,1,2,0.,0.,0.\nPBAR,9,1,1.\n"), {"CBAR 9, field 6 (X1): the orientation vector (X1, X2, X3) is zero"}));
  EXPECT_TRUE(mentions(read_error(d + "CBAR,9,9,1,2,1\nPBAR,9,1,1.\n"), {"CBAR 9, field 6 (G0): orientation grid 1 is an end of the element"}));
  EXPECT_TRUE(mentions(read_error(d + "CBAR,9,9,1,1,3\n"), {"CBAR 9, field 5 (GB): grid 1 repeats GA"}));
  EXPECT_TRUE(mentions(read_error(d + "CBAR,9,9,1,2,0.,0.,1.,GXG\n"), {"CBAR 9, field 9 (OFFT): got text 'GXG'"}));
  EXPECT_TRUE(mentions(read_error(d + "CORD2R,3,,0.,0.,0.,0.,0.,0.\n,1.,0.,0.\n"), {"CORD2R 3: points A and B coincide"}));
  EXPECT_TRUE(mentions(read_error(d + "CORD2R,3,,0.,0.,0.,0.,0.,1.\n,0.,0.,5.\n"), {"CORD2R 3: point C lies on the z axis"}));
  EXPECT_TRUE(mentions(read_error(d + "CORD1R,3,1,2,2\n"), {"CORD1R 3, field 3 (G1A): the three grids 1, 2, 2 are not distinct"}));
  EXPECT_TRUE(mentions(read_error(d + "CELAS2,9,1.,1,7\n"), {"CELAS2 9, field 5 (C1): got integer '7'"}));
  EXPECT_TRUE(mentions(read_error(d + "SPOINT,20\nCELAS2,9,1.,20,3\n"), {"CELAS2 9, field 4 (G1): scalar point 20 with component 3"}));
  EXPECT_TRUE(mentions(read_error(d + "PARAM,WTMASS,-1.\n"), {"PARAM WTMASS, field 3 (V1): got -1.; expected a mass factor > 0"}));
  EXPECT_TRUE(mentions(read_error(d + "RBE2,9,1,123456,2,1\n"), {"RBE2 9", "the independent grid 1 is also dependent"}));
  EXPECT_TRUE(mentions(read_error(d + "RBAR,9,1,2,123,12\n"),
                       {"deck.bdf:7: RBAR 9, field 5 (CNA): 5 independent components in CNA and CNB; expected six"}));
  EXPECT_TRUE(mentions(read_error(d + "RBAR,9,1,2,123456,,1\n"), {"RBAR 9, field 7 (CMA)", "both independent (CNA) and dependent"}));
  EXPECT_TRUE(mentions(read_error(d + "RBAR,9,1,1,123456\n"), {"RBAR 9, field 4 (GB): the same grid as GA"}));
  EXPECT_TRUE(mentions(read_error(d + "MPC,9,1,3,0.,2,3,1.\n"), {"MPC 9, field 5 (A1): 0.0; expected a nonzero coefficient"}));
  EXPECT_TRUE(mentions(read_error(d + "MPC,9,1,7,1.\n"), {"MPC 9, field 4 (C1): got integer '7'", "one component 1-6"}));
  EXPECT_TRUE(mentions(read_error(d + "RBE3,9,,1,123\n"), {"RBE3 9, field 6 (WT1): blank; expected at least one weight"}));
  EXPECT_TRUE(mentions(read_error(d + "RBE3,9,,1,123,1,123,2\n"), {"RBE3 9, field 6 (WT1): got integer '1'", "weighting factor"}));
  EXPECT_TRUE(mentions(read_error(d + "RBE3,9,,1,123,1.,123\n"), {"RBE3 9", "no grid after the components"}));
  EXPECT_TRUE(mentions(read_error(d + "RBE3,9,,1,123,1.,123,2,3\n,UM,2\n"), {"deck.bdf:8: RBE3 9, field 4 (CMi): blank; expected component numbers 1-6 without repeats"}));
  EXPECT_TRUE(mentions(read_error(d + "RBE3,9,,1,123,-1.,123,2,3\n"), {"RBE3 9, field 6 (WTi): got real '-1.'", ">= 0"}));
  EXPECT_TRUE(mentions(read_error(d + "EIGRL,1,10.,5.\n"), {"EIGRL 1, field 4 (V2): got real '5.'; expected V2 >= V1"}));
  EXPECT_TRUE(mentions(read_error(d + "DMIG,K,0,6,3,0\n"), {"DMIG K, field 5 (TIN): got integer '3'", "complex matrices are not supported"}));
  EXPECT_TRUE(mentions(read_error(d + "CQUAD4,9,1,1,2,3,4,,,\n,,,2\n"), {"CQUAD4 9, field 4 (TFLAG): got integer '2'"}));
}

TEST(NastranBadInput, DeepCoordinateChainDoesNotOverflowTheStack) {
  // 20000 CORD2R each defined in the previous one, listed deepest first: resolved without recursion.
  // Each is the previous one shifted by 1 along its x axis, so the last origin is at x = 20000.
  std::string deck = "GRID,1,20000,0.,0.,0.\n";
  for (int i = 20000; i >= 1; --i)
    deck += "CORD2R," + std::to_string(i) + "," + std::to_string(i - 1) + ",1.,0.,0.,1.,0.,1.\n,2.,0.,0.\n";
  const fem::Model m = read_deck(deck);
  EXPECT_DOUBLE_EQ(m.grids[0].x_basic.x(), 20000.0);
  EXPECT_DOUBLE_EQ(m.grids[0].x_basic.y(), 0.0);
}

TEST(NastranBadInput, CommandLineReportsFileLineCardAndField) {
  expect_cli_input_error(base_deck() + "CQUAD4,9,1,1,2,3,77\n",
                         {"bad.bdf:7: CQUAD4 9, field 7 (G4): references grid 77, which is not defined"});
  const auto r = test::run_seflex("info /nonexistent/deck.bdf");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_TRUE(mentions(r.err, {"/nonexistent/deck.bdf: no such file"}));
}

TEST(NastranBadInput, CommandLineExitsThreeForEveryKindOfBadDeck) {
  const std::string d = base_deck();
  expect_cli_input_error(d + "CQUAD4,1,1,1,2,3\n", {"bad.bdf:7: CQUAD4 1, field 7 (G4): blank"});
  expect_cli_input_error(d + "CQUAD4,1,1.,1,2,3,4\n", {"bad.bdf:7: CQUAD4 1, field 3 (PID): got real '1.'"});
  expect_cli_input_error(d + "GRID,2,,9.,9.,9.\n", {"bad.bdf:7: GRID 2, field 2 (ID): duplicate grid id"});
  expect_cli_input_error(std::string("GRID,1,,0.,0.,0.\nGRID,2,,\0,0.,0.\n", 33), {"bad.bdf:2, column 9: a NUL byte"});
  expect_cli_input_error(d + "INCLUDE 'nowhere.bdf'\n", {"bad.bdf:7: INCLUDE 'nowhere.bdf'", "does not exist"});
  expect_cli_input_error(d + "CBAR,9,9,1,2,0.,0.,1.\n", {"bad.bdf:7: CBAR 9, field 3 (PID): references property 9"});
  // CRLF line ends are no error
  test::TempDir dir;
  std::string crlf;
  for (const char c : d + "CQUAD4,1,1,1,2,3,4\n") crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const auto deck = dir.write("crlf.bdf", crlf);
  const auto r = test::run_seflex("info '" + deck.string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(NastranBadInput, CompositeCardsAndShellMaterials) {
  const std::string d = base_deck();  // 6 lines: cards under test start at line 7
  // MAT8
  EXPECT_TRUE(mentions(read_error(d + "MAT8,8,,1.+9,.3\n"), {"deck.bdf:7: MAT8 8, field 3 (E1): blank", "expected a real"}));
  EXPECT_TRUE(mentions(read_error(d + "MAT8,8,1.+10,-1.+9,.3\n"),
                       {"deck.bdf:7: MAT8 8, field 4 (E2): got real '-1.+9'; expected a modulus > 0"}));
  EXPECT_TRUE(mentions(read_error(d + "MAT8,8,1.+9,1.+10,.5\n"),
                       {"MAT8 8, field 5 (NU12): got real '.5'; expected NU12^2 < E1/E2"}));
  EXPECT_TRUE(mentions(read_error(d + "MAT8,8,1.+10,1.+9,.3,1.+9,-5.\n"),
                       {"MAT8 8, field 7 (G1Z): got real '-5.'; expected a modulus > 0, or blank (rigid in transverse shear)"}));
  // PCOMP
  EXPECT_TRUE(mentions(read_error(d + "PCOMP,10\n"), {"deck.bdf:7: PCOMP 10: no plies; expected at least one ply (MID1 T1 ... on a continuation line)"}));
  EXPECT_TRUE(mentions(read_error(d + "PCOMP,10,,,,,,,\n,,.001,0.\n"),
                       {"deck.bdf:8: PCOMP 10, field 2 (MID1): blank; expected the material of the first ply"}));
  EXPECT_TRUE(mentions(read_error(d + "PCOMP,10,,,,,,,\n,1,.001,0.,,1,-.001\n"),
                       {"deck.bdf:8: PCOMP 10, field 7 (T2): got real '-.001'; expected a ply thickness > 0"}));
  EXPECT_TRUE(mentions(read_error(d + "PCOMP,10,,,,,,,FOO\n,1,.001\n"),
                       {"deck.bdf:7: PCOMP 10, field 9 (LAM): got text 'FOO'; expected blank, SYM, MEM, BEND, SMEAR or SMCORE"}));
  EXPECT_TRUE(mentions(read_error(d + "PCOMP,10,,,,,,,SMCORE\n,1,.001\n"),
                       {"PCOMP 10, field 9 (LAM): SMCORE with one ply; expected the face-sheet plies, then the core ply last"}));
  EXPECT_TRUE(mentions(read_error(d + "PCOMP,10,,,,,,,\n,1,.001,0.,MAYBE\n"),
                       {"PCOMP 10, field 5 (SOUT1): got text 'MAYBE'; expected YES, NO or blank"}));
  EXPECT_TRUE(mentions(read_error(d + "PCOMP,10,,,,,,,\n,1,.001,0.,,77\nCQUAD4,9,10,1,2,3,4\n"),
                       {"deck.bdf:7: PCOMP 10, MID2: references material 77, which is not defined; expected the id of a MAT1, MAT2 or MAT8 card"}));
  // PCOMPG: one ply per line, unique global ply ids, no SYM
  EXPECT_TRUE(mentions(read_error(d + "PCOMPG,11,,,,,,,SYM\n,1,1,.001\n"),
                       {"PCOMPG 11, field 9 (LAM): got text 'SYM'; expected blank, MEM, BEND, SMEAR or SMCORE (PCOMPG lists every ply)"}));
  EXPECT_TRUE(mentions(read_error(d + "PCOMPG,11\n,5,1,.001\n,5,1,.001\n"),
                       {"deck.bdf:9: PCOMPG 11, field 2 (GPLYID2): got integer '5', a repeated global ply id; expected unique GPLYIDs"}));
  EXPECT_TRUE(mentions(read_error(d + "PCOMPG,11\n,5,1,.001,0.,NO,7\n"),
                       {"deck.bdf:8: PCOMPG 11, field 7", "expected blank (PCOMPG takes one ply per line: GPLYID MID T THETA SOUT)"}));
  // materials of the right kind
  EXPECT_TRUE(mentions(read_error(d + "PSHELL,2,8,.1\n"),
                       {"deck.bdf:7: PSHELL 2, field 3 (MID1): references material 8, which is not defined; expected the id of a MAT1, MAT2 or MAT8 card"}));
  // a rod on a shell material is left out (listed as "PROD on MAT8 (left out)", refused by solutions)
  EXPECT_TRUE(test::read_deck(d + "MAT8,8,1.+10,1.+9,.3\nPROD,5,8,1.\nCROD,5,5,1,2\n").rods.empty());
  EXPECT_TRUE(mentions(read_error(d + "MAT8,1,1.+10,1.+9,.3\n"),
                       {"deck.bdf:7: MAT8 1, field 2 (MID): duplicate material id, first defined at deck.bdf:1 (MAT1); expected unique material ids across MAT1, MAT2, MAT8"}));
  EXPECT_TRUE(mentions(read_error(d + "PCOMP,1,,,,,,,\n,1,.001\n"),
                       {"deck.bdf:7: PCOMP 1, field 2 (PID): duplicate property id, first defined at deck.bdf:2 (PSHELL)"}));
}
