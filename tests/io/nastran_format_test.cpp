// The bulk-data format rules of the MSC Nastran QRG ("Format of Bulk Data Entries"): small, large and
// free field, continuations, comments, tabs, CRLF, sections, INCLUDE, ENDDATA, unsupported cards.
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <fstream>

#include "nastran_test_util.hpp"
#include "seflex/fem/components.hpp"
#include "seflex/fem/finalize.hpp"
#include "test_support.hpp"

using namespace seflex;
using seflex::test::base_deck;
using seflex::test::fixed_line;
using seflex::test::mentions;
using seflex::test::read_deck;
using seflex::test::read_error;

namespace {

const fem::Grid& grid(const fem::Model& m, int id) { return m.grids.at(m.grid_index.at(id)); }

void expect_grid(const fem::Model& m, int id, double x, double y, double z, int cd, const char* ps) {
  const fem::Grid& g = grid(m, id);
  EXPECT_DOUBLE_EQ(g.x.x(), x) << "GRID " << id;
  EXPECT_DOUBLE_EQ(g.x.y(), y) << "GRID " << id;
  EXPECT_DOUBLE_EQ(g.x.z(), z) << "GRID " << id;
  EXPECT_EQ(g.cd, cd) << "GRID " << id;
  EXPECT_EQ(fem::component_string(g.ps), ps) << "GRID " << id;
}

}  // namespace

TEST(NastranFormat, SmallLargeAndFreeFieldGiveTheSameGrid) {
  const std::string small = fixed_line({"GRID", "7", "", "1.5", "-2-3", "7.1+10", "", "12 456"});
  const std::string large = fixed_line({"GRID*", "7", "", "1.5", "-2-3"}, 16, "*G7") +  //
                            fixed_line({"*G7", "7.1+10", "", "12 456"}, 16);
  const std::string free_ = "GRID,7,,1.5,-2-3,7.1+10,,12 456\n";
  for (const std::string& deck : {small, large, free_}) {
    const fem::Model m = read_deck(deck);
    ASSERT_EQ(m.grids.size(), 1u) << deck;
    expect_grid(m, 7, 1.5, -2e-3, 7.1e10, 0, "12456");
  }
}

TEST(NastranFormat, LargeFieldContinuationMayBeSmallField) {
  // A large-field first line holds fields 2-5; a small-field continuation then starts at field 2 of
  // the next logical line (fields 6-9 of the first stay blank).
  const std::string deck = base_deck() + fixed_line({"CQUAD4*", "11", "1", "1", "2"}, 16) +
                           fixed_line({"*", "3", "4", "", ""}, 16) + fixed_line({"+", "", "", "1", ".001", ".002", ".003", ".004"});
  const fem::Model m = read_deck(deck);
  ASSERT_EQ(m.shells.size(), 1u);
  const fem::Shell& s = m.shells[0];
  EXPECT_EQ(s.g[3], 4);
  EXPECT_EQ(s.tflag, 1);
  EXPECT_DOUBLE_EQ(s.t[0], 0.001);
  EXPECT_DOUBLE_EQ(s.t[3], 0.004);
}

TEST(NastranFormat, ExplicitAndImplicitContinuations) {
  const std::string deck = base_deck() +
      // explicit: +name in field 10 matched by field 1 of the next line
      fixed_line({"CONM2", "101", "1", "", "2.0"}, 8, "+M101") + fixed_line({"+M101", "1.", "", "2.", "", "", "3."}) +
      // implicit: blank field 1
      fixed_line({"CONM2", "102", "2", "", "2.0"}) + fixed_line({"", "4.", "", "5.", "", "", "6."}) +
      // a bare '+' and a comment line between card and continuation
      fixed_line({"CONM2", "103", "3", "", "2.0"}) + "$ comment between\n" + fixed_line({"+", "7.", "", "8.", "", "", "9."}) +
      // free field: continuation starting with a comma, and one starting with +name
      "CONM2,104,4,,2.0,,,,,+F\n+F,10.,,11.,,,12.\n" + "CONM2,105,4,,2.0\n,13.,,14.,,,15.\n";
  const fem::Model m = read_deck(deck);
  ASSERT_EQ(m.conm2.size(), 5u);
  const double i11[5] = {1, 4, 7, 10, 13}, i22[5] = {2, 5, 8, 11, 14}, i33[5] = {3, 6, 9, 12, 15};
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_DOUBLE_EQ(m.conm2[k].I11, i11[k]) << k;
    EXPECT_DOUBLE_EQ(m.conm2[k].I22, i22[k]) << k;
    EXPECT_DOUBLE_EQ(m.conm2[k].I33, i33[k]) << k;
  }
}

TEST(NastranFormat, MismatchedContinuationMarkersAreAnError) {
  const std::string deck = base_deck() + fixed_line({"CONM2", "101", "1", "", "2.0"}, 8, "+A") +
                           fixed_line({"+B", "1.", "", "2.", "", "", "3."});
  EXPECT_TRUE(mentions(read_error(deck), {"deck.bdf:8", "'+B'", "'+A'", "CONM2 101", "matching"}));
}

TEST(NastranFormat, OrphanContinuationIsAnError) {
  const std::string deck = "+X      1.      2.\n" + base_deck();
  EXPECT_TRUE(mentions(read_error(deck), {"deck.bdf:1", "continuation", "without a card"}));
}

TEST(NastranFormat, CommentsAndField10) {
  // '$' comments whole-line and trailing; text in field 10 that is no continuation is ignored
  // (the validation deck ALL-ELEM-TEST-GIV.DAT has a '1' there on GRID 1013).
  const std::string deck = "$ a comment\n" + fixed_line({"GRID", "1", "", "1.", "2.", "3."}, 8, "1") +
                           "GRID    2               4.      5.      6.      $ trailing comment\n" +
                           "GRID,3,,7.,8.,9. $ free-field with comment, with a comma\n";
  const fem::Model m = read_deck(deck);
  ASSERT_EQ(m.grids.size(), 3u);
  expect_grid(m, 1, 1, 2, 3, 0, "");
  expect_grid(m, 2, 4, 5, 6, 0, "");
  expect_grid(m, 3, 7, 8, 9, 0, "");
}

TEST(NastranFormat, TabsExpandToEightColumnStops) {
  const fem::Model m = read_deck("GRID\t1\t\t1.5\t2.5\t3.5\t\t123\nGRID\t2\t\t1.\t2.\t3.\n");
  expect_grid(m, 1, 1.5, 2.5, 3.5, 0, "123");
  expect_grid(m, 2, 1, 2, 3, 0, "");
}

TEST(NastranFormat, CrLfLineEnds) {
  const fem::Model m = read_deck("BEGIN BULK\r\nGRID    1               1.      2.      3.\r\n+       \r\nENDDATA\r\n");
  expect_grid(m, 1, 1, 2, 3, 0, "");
}

TEST(NastranFormat, TextBeyondColumn80IsIgnored) {
  const std::string deck = fixed_line({"GRID", "1", "", "1.", "2.", "3."}, 8, "        ") ;
  std::string line = deck.substr(0, deck.size() - 1);
  line.resize(80, ' ');
  line += "123456 beyond column 80\n";
  expect_grid(read_deck(line), 1, 1, 2, 3, 0, "");
}

TEST(NastranFormat, LowerCaseNamesAndFreeFieldLargeField) {
  const fem::Model m = read_deck("grid,1,,1.,2.,3.\nGRID*,2,,4.,5.\n*,6.,,3\n");
  expect_grid(m, 1, 1, 2, 3, 0, "");
  expect_grid(m, 2, 4, 5, 6, 0, "3");
}

TEST(NastranFormat, ThruListsAndEmbeddedBlanks) {
  std::string deck = base_deck() + "GRID,5,,2.,0.,0.\nGRID,6,,3.,0.,0.\n" +
                     fixed_line({"SPC1", "9", "12 456", "1", "THRU", "4"}) + fixed_line({"ASET1", "123", "2", "THRU", "5"}) +
                     fixed_line({"BSET1", "3", "1", "6"}) + "SPOINT,101,THRU,103,107\n";
  const fem::Model m = read_deck(deck);
  ASSERT_EQ(m.spcs.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(m.spcs[k].grid, k + 1);
    EXPECT_EQ(fem::component_string(m.spcs[k].c), "12456");
    EXPECT_EQ(m.spcs[k].sid, 9);
  }
  ASSERT_EQ(m.aset.size(), 4u);
  EXPECT_EQ(m.aset.front().grid, 2);
  EXPECT_EQ(m.aset.back().grid, 5);
  ASSERT_EQ(m.bset.size(), 2u);
  EXPECT_EQ(m.bset[1].grid, 6);
  ASSERT_EQ(m.spoints.size(), 4u);
  EXPECT_EQ(m.spoints[2].id, 103);
  EXPECT_EQ(m.spoints[3].id, 107);
}

TEST(NastranFormat, ExecutiveAndCaseControl) {
  const std::string deck =
      "ID TEST\nSOL 103\nTIME 10\nCEND\n"
      "TITLE = A Title, kept as written\n"
      "SUBT = the subtitle\n"
      "LABEL = global label\n"
      "ECHO = NONE\n"
      "SET 1 = 1, 2,\n   3, 4\n"
      "SPC = 1\n"
      "METH(STRUCTURE) = 7\n"
      "K2GG = KAAX\n"
      "PARAM,WTMASS,2.59-3\n"
      "SUBCASE 10\n  LOAD = 5\n  LABEL = first\n"
      "SUBC 20\n  SPC = 2\n  METHOD = 7\n"
      "BEGIN BULK\n" +
      base_deck() + "SPC1,1,123,1\nSPC1,2,123,2\nFORCE,5,3,,1.,0.,0.,1.\nEIGRL,7,,,4\n"
      "DMIG,KAAX,0,6,1,0\nDMIG,KAAX,1,1,,1,1,5.\nENDDATA\nGRID,99,,1.,1.,1.\n";
  const fem::Model m = read_deck(deck);
  const auto& cc = m.case_control;
  EXPECT_EQ(cc.sol.value_or(""), "103");
  EXPECT_EQ(cc.title, "A Title, kept as written");
  EXPECT_EQ(cc.subtitle, "the subtitle");
  EXPECT_EQ(cc.global.label, "global label");
  EXPECT_EQ(cc.global.spc.value_or(0), 1);
  EXPECT_EQ(cc.global.method.value_or(0), 7);
  ASSERT_EQ(cc.global.k2gg.size(), 1u);
  EXPECT_EQ(cc.global.k2gg[0], "KAAX");
  ASSERT_EQ(cc.subcases.size(), 2u);
  EXPECT_EQ(cc.subcases[0].id, 10);
  EXPECT_EQ(cc.subcases[0].load.value_or(0), 5);
  EXPECT_EQ(cc.subcases[0].spc.value_or(0), 1);  // inherited from the global selection
  EXPECT_EQ(cc.subcases[0].label, "first");
  EXPECT_EQ(cc.subcases[1].spc.value_or(0), 2);
  EXPECT_FALSE(cc.subcases[1].load.has_value());
  EXPECT_EQ(cc.subcases[1].k2gg.size(), 1u);
  EXPECT_DOUBLE_EQ(fem::param_number(m, "WTMASS", 1.0), 2.59e-3);
  EXPECT_EQ(m.grids.size(), 4u);  // GRID 99 after ENDDATA is not read
  ASSERT_EQ(m.dmigs.size(), 1u);
  EXPECT_EQ(m.dmigs[0].form, 6);
  ASSERT_EQ(m.dmigs[0].entries.size(), 1u);
  EXPECT_DOUBLE_EQ(m.dmigs[0].entries[0].value, 5.0);
}

TEST(NastranFormat, DeckWithoutBeginBulkIsBulkData) {
  const fem::Model m = read_deck("$ bulk data only\nGRID,1,,1.,2.,3.\n");
  EXPECT_EQ(m.grids.size(), 1u);
  EXPECT_FALSE(m.case_control.sol.has_value());
}

TEST(NastranFormat, UnsupportedCardsAreListedOnceWithCountAndFirstLine) {
  const std::string deck = base_deck() + "PLOADX1,1,1,1.\nCQUAD,5,1,1,2,3,4\n,7,8\nPLOADX1,2,1,1.\nDEBUG,1\n";
  const fem::Model m = read_deck(deck);
  ASSERT_EQ(m.unsupported.size(), 3u);
  EXPECT_EQ(m.unsupported[0].name, "PLOADX1");
  EXPECT_EQ(m.unsupported[0].count, 2u);
  EXPECT_EQ(m.unsupported[0].first.line, 7u);
  EXPECT_EQ(m.unsupported[1].name, "CQUAD");
  EXPECT_EQ(m.unsupported[1].first.line, 8u);
  EXPECT_EQ(m.unsupported[2].name, "DEBUG");
  EXPECT_EQ(m.card_counts.at("GRID"), 4u);
  EXPECT_EQ(m.card_counts.count("PLOADX1"), 0u);
}

TEST(NastranFormat, IncludeRelativeQuotedAndSplit) {
  test::TempDir dir;
  dir.write("sub/grids.bdf", "GRID,1,,0.,0.,0.\nINCLUDE 'more/grids2.bdf'\n");  // relative to sub/
  dir.write("sub/more/grids2.bdf", "GRID,2,,1.,0.,0.\n");
  dir.write("long name/props.bdf", "MAT1,1,2.1+11,,0.3\n");
  const auto main = dir.write("main.bdf",
                              "SOL 103\nCEND\nBEGIN BULK\n"
                              "INCLUDE sub\\grids.bdf\n"  // a Windows path separator
                              "INCLUDE 'long name/\n"
                              "   props.bdf'\n"
                              "CROD,1,1,1,2\nPROD,1,1,1.\nENDDATA\n");
  const fem::Model m = io::read_nastran(main);
  EXPECT_EQ(m.grids.size(), 2u);
  EXPECT_EQ(m.mat1.size(), 1u);
  ASSERT_EQ(m.files.size(), 4u);
  EXPECT_EQ(std::filesystem::path(m.files[2]).filename(), "grids2.bdf");
  EXPECT_EQ(m.grids[1].ref.file, 2u);
  EXPECT_EQ(m.grids[1].ref.line, 1u);
}

TEST(NastranFormat, MixedFormatsGiveTheSameModelAsSmallField) {
  // The same model twice: all small field, then free field, large field and small field mixed with
  // every continuation style. Every card and field must agree.
  const std::string small =
      fixed_line({"GRID", "1", "", "0.", "0.", "0."}) + fixed_line({"GRID", "2", "", "1.", "0.", "0.", "", "456"}) +
      fixed_line({"GRID", "3", "", "1.", "1.", "0."}) + fixed_line({"GRID", "4", "", "0.", "1.", "0."}) +
      fixed_line({"MAT1", "1", "7.+10", "", ".33", "2700."}) +
      fixed_line({"PBAR", "10", "1", "1.-4", "2.-9", "3.-9", "4.-9", ".1"}, 8, "+P") +
      fixed_line({"+P", "", "", "", "", "", "", "", ""}, 8, "+Q") + fixed_line({"+Q", ".8", ".7"}) +
      fixed_line({"CBAR", "5", "10", "1", "2", "0.", "0.", "1."}, 8, "+C") + fixed_line({"+C", "", "56"}) +
      fixed_line({"PSHELL", "20", "1", ".002", "1", "", "1"}) +
      fixed_line({"CQUAD4", "6", "20", "1", "2", "3", "4", "30."}) +
      fixed_line({"CONM2", "7", "3", "", "5.", ".1", ".2", ".3"}, 8, "+M") + fixed_line({"+M", "1.", "", "2.", "", "", "3."}) +
      fixed_line({"SPC1", "1", "123", "1", "4"}) + fixed_line({"FORCE", "2", "3", "", "10.", "0.", "0.", "-1."});
  const std::string mixed =
      "GRID,1,,0.,0.,0.\n" + fixed_line({"GRID*", "2", "", "1.", "0."}, 16, "*A") + fixed_line({"*A", "0.", "", "456"}, 16) +
      "GRID    3               1.      1.      0.\n" + "grid,4,,0.,1.,0.\n" +
      "MAT1,1,7.+10,,.33,2700.\n" + "PBAR,10,1,1.-4,2.-9,3.-9,4.-9,.1\n,\n,.8,.7\n" +
      fixed_line({"CBAR*", "5", "10", "1", "2"}, 16) + fixed_line({"*", "0.", "0.", "1."}, 16) + "+,,56\n" +
      fixed_line({"PSHELL*", "20", "1", ".002", "1"}, 16) + fixed_line({"*", "", "1"}, 16) +
      "CQUAD4,6,20,1,2,3,4,30.\n" + "CONM2,7,3,,5.,.1,.2,.3,,+\n" + fixed_line({"+", "1.", "", "2.", "", "", "3."}) +
      "SPC1,1,123,1,4\n" + fixed_line({"FORCE*", "2", "3", "", "10."}, 16) + "*,0.,0.,-1.\n";
  const fem::Model a = read_deck(small), b = read_deck(mixed);
  ASSERT_EQ(a.grids.size(), b.grids.size());
  for (std::size_t i = 0; i < a.grids.size(); ++i) {
    EXPECT_EQ(a.grids[i].id, b.grids[i].id);
    EXPECT_EQ(a.grids[i].x, b.grids[i].x);
    EXPECT_EQ(a.grids[i].ps, b.grids[i].ps);
  }
  ASSERT_EQ(a.mat1.size(), 1u);
  ASSERT_EQ(b.mat1.size(), 1u);
  EXPECT_EQ(a.mat1[0].E, b.mat1[0].E);
  EXPECT_EQ(a.mat1[0].G, b.mat1[0].G);
  EXPECT_EQ(a.mat1[0].rho, b.mat1[0].rho);
  ASSERT_EQ(b.bar_props.size(), 1u);
  for (const auto* m : {&a, &b}) {
    const auto& p = m->bar_props[0];
    EXPECT_DOUBLE_EQ(p.A, 1e-4);
    EXPECT_DOUBLE_EQ(p.J, 4e-9);
    EXPECT_DOUBLE_EQ(p.nsm, 0.1);
    EXPECT_DOUBLE_EQ(p.K1, 0.8);
    EXPECT_DOUBLE_EQ(p.K2, 0.7);
    ASSERT_EQ(m->bars.size(), 1u);
    EXPECT_EQ(m->bars[0].v, Eigen::Vector3d(0, 0, 1));
    EXPECT_EQ(m->bars[0].pb, 0b110000);
    EXPECT_EQ(m->bars[0].pa, 0);
    ASSERT_EQ(m->shell_props.size(), 1u);
    EXPECT_EQ(m->shell_props[0].mid3, 1);
    EXPECT_DOUBLE_EQ(m->shell_props[0].t, 0.002);
    ASSERT_EQ(m->shells.size(), 1u);
    EXPECT_DOUBLE_EQ(m->shells[0].theta_deg, 30.0);
    ASSERT_EQ(m->conm2.size(), 1u);
    EXPECT_DOUBLE_EQ(m->conm2[0].x.z(), 0.3);
    EXPECT_DOUBLE_EQ(m->conm2[0].I33, 3.0);
    EXPECT_EQ(m->spcs.size(), 2u);
    ASSERT_EQ(m->point_loads.size(), 1u);
    EXPECT_EQ(m->point_loads[0].n, Eigen::Vector3d(0, 0, -1));
  }
}

// ---------------------------------------------------------------------------------------------
// Continuation markers: MSC's rule (QRG, "Format of Bulk Data Entries", continuation entries)
// compares columns 2-8 of field 10 with columns 2-8 of the continuation's field 1, whose column 1
// holds '+' (small field), '*' (large field) or a blank. Every combination below gives the CONM2 of
// ExplicitAndImplicitContinuations (I11, I22, I33 = 1, 2, 3).

namespace {

/// I11, I22, I33 of the one CONM2 of the deck.
std::array<double, 3> conm2_inertia(const std::string& card_lines) {
  const fem::Model m = read_deck(base_deck() + card_lines);
  EXPECT_EQ(m.conm2.size(), 1u) << card_lines;
  if (m.conm2.size() != 1) return {};
  return {m.conm2[0].I11, m.conm2[0].I22, m.conm2[0].I33};
}

const std::array<double, 3> k123 = {1.0, 2.0, 3.0};

}  // namespace

TEST(NastranFormat, ContinuationMarkersCompareColumnsTwoToEight) {
  // field 10 of the first line: as written (blank column 73 first), "+MRBRG1", or another first character
  const auto first = [&](const std::string& field10) { return fixed_line({"CONM2", "101", "1", "", "2.0"}, 8, field10); };
  const std::string data = "1.              2.                      3.";  // I11 I21 I22 I31 I32 I33, 8 columns each
  struct Case {
    const char* field10;
    const char* field1;  // the continuation's columns 1-8
  };
  const Case valid[] = {
      {" MRBRG1", "+MRBRG1"},  // the deck: column 73 blank, continued with '+'
      {" MRBRG1", " MRBRG1"},  // a blank first column on the continuation
      {"+MRBRG1", " MRBRG1"},
      {"XMRBRG1", "+MRBRG1"},  // any first character in field 10
      {"+MRBRG1", "+mrbrg1"},  // any case
      // forms seflex read before, unchanged
      {"+C1", "+C1"},
      {"CORD1", "+ORD1"},      // a101x.dat
      {"     +C1", "+C1"},     // right-justified in field 10
      {"", "+ANY"},            // a blank field 10
      {"+A", "+"},             // a bare '+'
      {"+A", ""},              // a blank field 1
  };
  for (const Case& c : valid) {
    std::string cont = c.field1;
    cont.resize(8, ' ');
    EXPECT_EQ(conm2_inertia(first(c.field10) + cont + data + "\n"), k123) << c.field10 << " / " << c.field1;
  }
  // a large-field continuation ('*', four 16-column fields a line) after field 10 " MRBRG1"
  EXPECT_EQ(conm2_inertia(first(" MRBRG1") + fixed_line({"*MRBRG1", "1.", "", "2.", ""}, 16) + fixed_line({"*", "", "3."}, 16)),
            k123);
  // a large-field first line: field 10 in columns 73-80 as well
  EXPECT_EQ(conm2_inertia(fixed_line({"CONM2*", "101", "1", "", "2.0"}, 16, " MRBRG1") + fixed_line({"*MRBRG1"}, 16) +
                          "+       " + data + "\n"),
            k123);
  // free field: a field's text starts in its first column (blanks around commas do not count)
  EXPECT_EQ(conm2_inertia("CONM2,101,1,,2.0,,,,,+F1\n+F1,1.,,2.,,,3.\n"), k123);
  EXPECT_EQ(conm2_inertia("CONM2,101,1,,2.0,,,,, +F1\n*F1,1.,,2.,\n*,,3.\n"), k123);
  EXPECT_EQ(conm2_inertia("CONM2,101,1,,2.0,,,,,XF1\n+F1,1.,,2.,,,3.\n"), k123);
  EXPECT_EQ(conm2_inertia("CONM2,101,1,,2.0\n,1.,,2.,,,3.\n"), k123);
}

TEST(NastranFormat, ContinuationMarkersThatDifferInColumnsTwoToEightAreAnError) {
  const auto first = [](const std::string& field10) { return fixed_line({"CONM2", "101", "1", "", "2.0"}, 8, field10); };
  EXPECT_EQ(read_error(base_deck() + first(" MRBRG1") + fixed_line({"+MRBRG2", "1.", "", "2.", "", "", "3."})),
            "deck.bdf:8: continuation '+MRBRG2' does not match 'MRBRG1' in field 10 of the line before (CONM2 101); "
            "expected matching continuation markers (the same text in columns 2-8 of both; the first column is not "
            "compared), or a blank one");
  EXPECT_TRUE(mentions(read_error(base_deck() + first("+A") + " B      1.\n"), {"deck.bdf:8: continuation 'B' does not match '+A'"}));
  EXPECT_TRUE(mentions(read_error(base_deck() + first("+A") + fixed_line({"*B", "1."}, 16)),
                       {"deck.bdf:8: continuation '*B' does not match '+A'"}));
  // free field: "MRBRG1" has "RBRG1" in columns 2-8, "+MRBRG1" has "MRBRG1"
  EXPECT_TRUE(mentions(read_error(base_deck() + "CONM2,101,1,,2.0,,,,,MRBRG1\n+MRBRG1,1.,,2.,,,3.\n"),
                       {"deck.bdf:8: continuation '+MRBRG1' does not match 'MRBRG1'"}));
}

TEST(NastranFormat, BlankFirstColumnContinuesTheCardBefore) {
  // " C1" in columns 1-8 is a continuation (column 1 blank), not a card named C1
  const fem::Model m = read_deck(base_deck() + fixed_line({"CONM2", "101", "1", "", "2.0"}, 8, "+C1") + " C1     " +
                                 "1.              2.                      3.\n");
  ASSERT_EQ(m.conm2.size(), 1u);
  EXPECT_EQ(m.conm2[0].I33, 3.0);
  EXPECT_TRUE(m.unsupported.empty());
  // INCLUDE and ENDDATA may be indented; they are not continuations
  test::TempDir dir;
  dir.write("grid.bdf", "GRID,5,,2.,0.,0.\n");
  const fem::Model n = io::read_nastran(dir.write("main.bdf", base_deck() + "   INCLUDE 'grid.bdf'\n  ENDDATA\nGRID,6,,3.,0.,0.\n"));
  EXPECT_EQ(n.grids.size(), 5u);  // 1-4 and 5; GRID 6 is after ENDDATA
}

// ---------------------------------------------------------------------------------------------
// INCLUDE as MSC Nastran finds the file (io/src/nastran_include.hpp)

TEST(NastranFormat, NestedIncludePathsAreRelativeToTheMainDeckFirst) {
  // Satellite_V02's layout: JOBS/QS/job.dat includes ../../INCLUDE/part.dat, which includes
  // ../../BULK/grids.blk meaning JOBS/QS/../../BULK (the main deck's folder), not INCLUDE/../../BULK
  test::TempDir dir;
  dir.write("BULK/grids.blk", "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\n");
  dir.write("INCLUDE/part.dat", "INCLUDE '../../BULK/grids.blk'\nINCLUDE 'local.blk'\n");
  dir.write("INCLUDE/local.blk", "GRID,3,,2.,0.,0.\n");  // found beside the including file only
  const auto main = dir.write("JOBS/QS/job.dat", "INCLUDE '../../INCLUDE/part.dat'\nCROD,1,1,1,2\nPROD,1,1,1.\nMAT1,1,1.,,0.3\n");
  const fem::Model m = io::read_nastran(main);
  EXPECT_EQ(m.grids.size(), 3u);
  EXPECT_TRUE(m.read_warnings.empty());
  ASSERT_EQ(m.files.size(), 4u);
  EXPECT_EQ(std::filesystem::path(m.files[2]).lexically_normal(), (dir.path() / "BULK/grids.blk").lexically_normal());
  EXPECT_EQ(std::filesystem::path(m.files[3]).lexically_normal(), (dir.path() / "INCLUDE/local.blk").lexically_normal());
}

TEST(NastranFormat, IncludeFoundInBothFoldersReadsTheMainDecksAndSaysSo) {
  test::TempDir dir;
  dir.write("sub/inner.bdf", "INCLUDE 'grids.bdf'\n");
  dir.write("grids.bdf", "GRID,1,,0.,0.,0.\n");      // beside the main deck: read
  dir.write("sub/grids.bdf", "GRID,1,,9.,0.,0.\n");  // beside the including file: differs
  const auto main = dir.write("main.bdf", "INCLUDE 'sub/inner.bdf'\n");
  const fem::Model m = io::read_nastran(main);
  ASSERT_EQ(m.grids.size(), 1u);
  EXPECT_EQ(m.grids[0].x.x(), 0.0);
  const std::string d = dir.path().string();
  ASSERT_EQ(m.read_warnings.size(), 1u);
  EXPECT_EQ(m.read_warnings[0], d + "/sub/inner.bdf:1: INCLUDE 'grids.bdf': read " + d +
                                    "/grids.bdf (relative to the main deck's folder, as MSC Nastran reads it); " + d +
                                    "/sub/grids.bdf (relative to the including file's folder) exists too and differs");
  // the same content in both places: nothing to say
  dir.write("sub/grids.bdf", "GRID,1,,0.,0.,0.\n");
  EXPECT_TRUE(io::read_nastran(main).read_warnings.empty());
}

TEST(NastranFormat, IncludeNotFoundNamesEveryPlaceTried) {
  test::TempDir dir;
  dir.write("sub/inner.bdf", "INCLUDE 'missing.bdf'\n");
  const auto main = dir.write("main.bdf", "GRID,1,,0.,0.,0.\nINCLUDE 'sub/inner.bdf'\n");
  const std::string d = dir.path().string();
  try {
    io::read_nastran(main);
    FAIL() << "read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), d + "/sub/inner.bdf:1: INCLUDE 'missing.bdf': the file does not exist; tried " + d +
                                         "/missing.bdf (relative to the main deck's folder) and " + d +
                                         "/sub/missing.bdf (relative to the including file's folder); expected a path "
                                         "relative to one of them, an absolute path, or SYMBOL:path");
  }
}

TEST(NastranFormat, IncludeLogicalSymbols) {
  test::TempDir dir;
  dir.write("data/bulk/grids.bdf", "GRID,1,,0.,0.,0.\n");
  dir.write("data/inc/part.dat", "INCLUDE 'BULKDIR:/\n      grids.bdf'\n");  // a symbolic name split over two lines
  const auto main = dir.write("job/main.bdf", "INCLUDE 'incdir:part.dat'\n");
  const std::string d = dir.path().string();
  io::NastranReadOptions o;
  // a value may use a symbol given before it ($NAME or ${NAME}); names in any case
  o.symbols = {{"DATA", d + "/data"}, {"BulkDir", "${DATA}/bulk"}, {"INCDIR", "$DATA/inc"}};
  EXPECT_EQ(io::read_nastran(main, o).grids.size(), 1u);
  // from the environment when no symbol is given
  ::setenv("SEFLEX_TEST_INCDIR", (d + "/data/inc").c_str(), 1);
  ::setenv("SEFLEX_TEST_DATA_DIR", (d + "/data").c_str(), 1);
  const auto env_main = dir.write("job/env.bdf", "INCLUDE 'SEFLEX_TEST_INCDIR:part.dat'\n");
  o.symbols = {{"BULKDIR", "$SEFLEX_TEST_DATA_DIR/bulk"}};  // an environment variable inside a value
  EXPECT_EQ(io::read_nastran(env_main, o).grids.size(), 1u);
  const auto error = [&](const std::string& text, const io::NastranReadOptions& opt) {
    try {
      io::read_nastran(dir.write("job/bad.bdf", text), opt);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("read");
  };
  const std::string bad = d + "/job/bad.bdf:1: INCLUDE ";
  EXPECT_EQ(error("INCLUDE 'NOSUCHSYMBOL_X:a.bdf'\n", {}),
            bad + "'NOSUCHSYMBOL_X:a.bdf': logical symbol NOSUCHSYMBOL_X is not defined; expected --symbol "
                  "NOSUCHSYMBOL_X=DIR (MSC Nastran: symbol=NOSUCHSYMBOL_X=DIR in an rc file) or an environment variable "
                  "NOSUCHSYMBOL_X");
  EXPECT_EQ(error("INCLUDE 'C:\\models\\a.bdf'\n", {}),
            bad + "'C:/models/a.bdf': 'C:' is a Windows drive; expected a path on this machine, or the drive mapped to "
                  "a folder: --symbol C=DIR");
  io::NastranReadOptions drive;
  drive.symbols = {{"C", d + "/data"}};
  EXPECT_EQ(error("INCLUDE 'C:\\bulk\\grids.bdf'\n", drive), "read");
  o.symbols = {{"INCDIR", d + "/data/inc"}};
  EXPECT_EQ(error("INCLUDE 'INCDIR:nothing.dat'\n", o),
            bad + "'INCDIR:nothing.dat': the file does not exist; tried " + d + "/data/inc/nothing.dat (logical symbol "
                  "INCDIR = " + d + "/data/inc)");
  io::NastranReadOptions undefined;
  undefined.symbols = {{"X", "$SEFLEX_NO_SUCH_VARIABLE/y"}};
  EXPECT_EQ(error("GRID,1,,0.,0.,0.\n", undefined),
            "logical symbol X=$SEFLEX_NO_SUCH_VARIABLE/y: $SEFLEX_NO_SUCH_VARIABLE is neither a logical symbol given "
            "before it nor an environment variable");
  ::unsetenv("SEFLEX_TEST_INCDIR");
  ::unsetenv("SEFLEX_TEST_DATA_DIR");
  // --symbol's parser
  EXPECT_EQ(io::parse_nastran_symbol("A_1=/x=y").value, "/x=y");
  for (const char* text : {"noequals", "=x", "1A=x", "A B=x"}) {
    try {
      io::parse_nastran_symbol(text);
      ADD_FAILURE() << text;
    } catch (const InputError& e) {
      EXPECT_TRUE(mentions(e.what(), {"expected NAME=FOLDER"})) << text;
    }
  }
}
