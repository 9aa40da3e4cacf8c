// What pyNastran's public decks (models/, issue 14) write and seflex reads: bulk data replication
// ('=', '==', '*x', '=n'), part superelements (BEGIN SUPER: read as parts and assembled, fem/parts.hpp),
// SUBCASE = n, continuation markers matched on columns 2-8, PARAM in the case control over the bulk
// data, TFLAG as a real, COSMIC's CBAR flag F, MAT1 NU above 0.5, fluid grids and PFLUID solids,
// rigid elements numbered apart, elements on properties or materials seflex does not model (left
// out, listed, refused by solutions), SPOINT twice and implied by scalar elements, 0 for "none" in
// PA/PB/PS, PSOLID STRESS as an integer, indented free-field continuations (ADAPT).
// Each tolerance: what is read (numbers), what is listed, and where a solution refuses, the message.
#include <gtest/gtest.h>

#include "nastran_test_util.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/solutions/card_usage.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

using test::mentions;
using test::read_deck;
using test::read_error;

const fem::UnsupportedCard* listed(const fem::Model& m, const std::string& name) {
  for (const auto& u : m.unsupported)
    if (u.name == name) return &u;
  return nullptr;
}

/// The error a linear statics run gives (require_usable), "" if it would run.
std::string statics_refusal(const fem::Model& m) {
  const auto cases = solutions::select_cases(m);
  try {
    solutions::require_usable(m, solutions::check_card_usage(m, solutions::Solution::Statics, cases));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// A statics deck: a clamped CBAR (grids 1, 2) with a tip force, and `more` bulk data.
std::string statics_deck(const std::string& more, const std::string& case_control = "") {
  return "SOL 101\nCEND\nSPC = 1\nLOAD = 7\n" + case_control +
         "BEGIN BULK\nMAT1,1,7.e10,,0.3,2700.\nPBAR,1,1,1.e-4,2.e-8,2.e-8,4.e-8\n"
         "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nCBAR,1,1,1,2,0.,1.,0.\nSPC1,1,123456,1\nFORCE,7,2,0,1.,0.,0.,1.\n" +
         more + "ENDDATA\n";
}

// ---------------------------------------------------------------------------------------------
// Replication (MSC QRG, "Format of Bulk Data Entries"; decks mne7a, dbxdra7, v10111, superelement)

TEST(PublicDecks, ReplicationMakesTheSameCardsAsWrittenOut) {
  // mne7a_model1.dat: "GRID, 1,, 0.0, 0.0, 0.0" / "=,*11,,*.10,==" / "=9": 11 grids 11 apart, x += 0.1
  const fem::Model r = read_deck("GRID, 1,, 0.0, 0.0, 0.0\n=,*11,,*.10,==\n=9\n");
  ASSERT_EQ(r.grids.size(), 11u);
  for (std::size_t k = 0; k < 11; ++k) {
    EXPECT_EQ(r.grids[k].id, 1 + 11 * static_cast<int>(k));
    double x = 0.0;  // the same sums in the same order as the reader's
    for (std::size_t j = 0; j < k; ++j) x += 0.1;
    EXPECT_EQ(r.grids[k].x.x(), x) << k;
    EXPECT_EQ(r.grids[k].x.y(), 0.0);
  }
  EXPECT_NEAR(r.grids[10].x.x(), 1.0, 1e-15);
  // '*(x)' with parentheses, '=' per field, '==' copying the rest, fixed format; the element lines too
  const std::string fixed = test::fixed_line({"GRID", "101", "", "48.97", "-78.87", "0.", "", "3"}) +
                            "=       *(1)    =       =       *(12.5) ==\n=(2)\n"
                            "CROD,11,5,101,102\n=,*(1),=,*(1),*(1)\n"
                            "PROD,5,1,1.e-4\nMAT1,1,7.e10,,0.3\n";
  const fem::Model f = read_deck(fixed);
  ASSERT_EQ(f.grids.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(f.grids[k].id, 101 + static_cast<int>(k));
    EXPECT_EQ(f.grids[k].x.x(), 48.97);
    EXPECT_NEAR(f.grids[k].x.y(), -78.87 + 12.5 * static_cast<double>(k), 1e-12);
    EXPECT_EQ(f.grids[k].ps, 0b100);  // component 3, copied by '=='
  }
  ASSERT_EQ(f.rods.size(), 2u);
  EXPECT_EQ(f.rods[1].id, 12);
  EXPECT_EQ(f.rods[1].pid, 5);
  EXPECT_EQ(f.rods[1].ga, 102);
  EXPECT_EQ(f.rods[1].gb, 103);
}

TEST(PublicDecks, ReplicationIncrementsABlankFieldFromZeroAndDropsFieldsAfterTheLine) {
  // dbxdra7.bdf: a blank CD incremented by *(1) gives CD = 1 (the grids before it have CD = 1)
  const fem::Model m = read_deck("CORD2R,1,,0.,0.,0.,0.,0.,1.,\n,1.,0.,0.\n"
                                 "GRID,123,,25.,-60.4,0.,,456\n=,*(1),=,=,*(14.8),=,*(1)\n");
  ASSERT_EQ(m.grids.size(), 2u);
  EXPECT_EQ(m.grids[0].cd, 0);
  EXPECT_EQ(m.grids[1].cd, 1);
  EXPECT_EQ(m.grids[1].ps, 0);  // PS not on the '=' line: left out
  EXPECT_NEAR(m.grids[1].x.y(), -45.6, 1e-12);
}

TEST(PublicDecks, ReplicationErrorsNameTheLineAndTheField) {
  EXPECT_TRUE(mentions(read_error("=,*1,=\n"), {"deck.bdf:1: replication '=' without a card before it"}));
  EXPECT_TRUE(mentions(read_error("GRID,1,,0.,0.,0.\n=3\n"),
                       {"deck.bdf:2: replication '=3' does not follow a '=' replication line"}));
  EXPECT_TRUE(mentions(read_error("GRID,1,,0.,0.,0.\n=,*1.5,=,=\n"),
                       {"deck.bdf:2: replication of GRID 1, field 2: '*1.5' increments '1'; expected an integer increment"}));
  EXPECT_TRUE(mentions(read_error("GRID,1,,0.,0.,0.\n=,*a\n"), {"deck.bdf:2: replication of GRID 1, field 2: got '*a'"}));
  EXPECT_TRUE(mentions(read_error("GRID,1,,0.,0.,0.\n=,*1,=\n=(0)\n"), {"deck.bdf:3: replication '=(0)'", "1 <= n"}));
}

// ---------------------------------------------------------------------------------------------
// Part superelements (see101*, flyswatter, elafor_4)

TEST(PublicDecks, PartSuperelementsAreReadAsPartsAndAssembled) {
  // part 1 continues the bar (its grid 2 is the residual's, by location; its CBAR 1, MAT1 1 and PBAR 1
  // clash with the residual's: renumbered 11); part 2 holds a grid of its own
  const std::string part = "BEGIN SUPER = 1\nGRID,2,,1.,0.,0.\nGRID,3,,2.,0.,0.\nMAT1,1,7.e10,,0.3,2700.\n"
                           "PBAR,1,1,1.e-4,2.e-8,2.e-8,4.e-8\nCBAR,1,1,2,3,0.,1.,0.\n"
                           "begin bulk super=2\nGRID,78,,0.,0.,9.\n";
  const fem::Model m = read_deck(statics_deck(part));
  ASSERT_EQ(m.grids.size(), 4u);  // 1 and 2, part 1's 3, part 2's 78 (part 1's 2 is the residual's)
  ASSERT_EQ(m.bars.size(), 2u);
  EXPECT_EQ(m.bars[1].id, 11);
  EXPECT_EQ(m.bars[1].ga, 2);
  EXPECT_EQ(m.bars[1].pid, 11);
  ASSERT_EQ(m.parts.size(), 2u);
  EXPECT_EQ(m.parts[0].boundary_grids, 1u);
  EXPECT_EQ(m.parts[0].begin.line, 13u);
  EXPECT_EQ(listed(m, "BEGIN SUPER"), nullptr);
  EXPECT_EQ(statics_refusal(m), "");
  // parts before BEGIN BULK (flyswatter_renumber.bdf, as pyNastran writes them): they end the case
  // control, and the residual's bulk data after BEGIN BULK is read (it was taken for case control,
  // the parts lost unsaid); a part's PARAM is not the residual's (listed)
  const fem::Model first = read_deck(statics_deck("", "BEGIN SUPER=1\nPARAM,WTMASS,.5\nGRID,1,,5.,5.,5.\n"));
  ASSERT_EQ(first.parts.size(), 1u);
  EXPECT_EQ(first.parts[0].begin.line, 5u);
  ASSERT_EQ(first.grids.size(), 3u);
  EXPECT_EQ(first.grids[0].x.x(), 0.0);
  EXPECT_EQ(first.grids[2].id, 11);  // part 1's grid 1, renumbered
  EXPECT_EQ(first.grids[2].x_basic.z(), 5.0);
  EXPECT_EQ(fem::param_number(first, "WTMASS", 1.0), 1.0);
  EXPECT_NE(listed(first, "PARAM of a part superelement other than the residual's (the residual's value or the default used)"), nullptr);
  // flyswatter's parts: PARAM AUTOSPC YES (the default the residual uses) and the residual's WTMASS:
  // the same model, nothing listed; AUTOSPC NO or another WTMASS would be
  const std::string part_repeats = "BEGIN SUPER=1\nPARAM,AUTOSPC,YES\nPARAM,WTMASS,.5\nPARAM,K6ROT,100.\nGRID,1,,5.,5.,5.\n";
  const fem::Model same = read_deck(statics_deck("PARAM,WTMASS,.5\n", part_repeats));
  EXPECT_EQ(listed(same, "PARAM of a part superelement other than the residual's (the residual's value or the default used)"), nullptr);
  for (const char* other : {"PARAM,AUTOSPC,NO\n", "PARAM,K6ROT,10.\n", "PARAM,WTMASS,.4\n"}) {
    const fem::Model differs = read_deck(statics_deck("PARAM,WTMASS,.5\n", std::string("BEGIN SUPER=1\n") + other + "GRID,1,,5.,5.,5.\n"));
    EXPECT_NE(listed(differs, "PARAM of a part superelement other than the residual's (the residual's value or the default used)"), nullptr) << other;
  }
}

// ---------------------------------------------------------------------------------------------
// Case control and continuations

TEST(PublicDecks, SubcaseWithAnEqualsSign) {
  // ZONA's decks (aero/zona/ztran.bdf): "SUBCASE = 1"
  const fem::Model m = read_deck("SOL 101\nCEND\nSUBCASE = 3\n  LOAD = 7\nBEGIN BULK\nGRID,1,,0.,0.,0.\nENDDATA\n");
  ASSERT_EQ(m.case_control.subcases.size(), 1u);
  EXPECT_EQ(m.case_control.subcases[0].id, 3);
}

TEST(PublicDecks, ContinuationMarkersMatchOnColumnsTwoToEight) {
  // plate_with_circular_hole/a101x.dat: field 10 "CORD1", continuation "+ORD1"
  const std::string deck = test::fixed_line({"CORD2C", "1", "", "0.", "0.", "0.", "0.", "0.", "1."}, 8, "CORD1") +
                           test::fixed_line({"+ORD1", "1.", "0.", "0."}) + "GRID,1,1,2.,90.,3.\n";
  const fem::Model m = read_deck(deck);
  ASSERT_EQ(m.coords.size(), 1u);
  EXPECT_NEAR(m.grids[0].x_basic.x(), 0.0, 1e-12);
  EXPECT_NEAR(m.grids[0].x_basic.y(), 2.0, 1e-12);
  EXPECT_NEAR(m.grids[0].x_basic.z(), 3.0, 1e-12);
  // columns 2-8 that differ are still an error
  const std::string bad = test::fixed_line({"CORD2C", "1", "", "0.", "0.", "0.", "0.", "0.", "1."}, 8, "+CORD1") +
                          test::fixed_line({"+CORD2", "1.", "0.", "0."});
  EXPECT_TRUE(mentions(read_error(bad), {"deck.bdf:2: continuation '+CORD2' does not match '+CORD1'"}));
}

TEST(PublicDecks, IndentedFreeFieldContinuations) {
  // ADAPT (p-elements, other/cc508a.bdf): "        errtol=.1,PART=TIP,ELSET=1" continues the card
  const fem::Model m = read_deck("GRID,1,,0.,0.,0.\nADAPT,  101,    ,    , 210\n        errtol=.1,PART=TIP,ELSET=1\n"
                                 "        206, 207\nGRID,2,,1.,0.,0.\n");
  EXPECT_EQ(m.grids.size(), 2u);
  ASSERT_NE(listed(m, "ADAPT"), nullptr);
  EXPECT_EQ(listed(m, "ADAPT")->count, 1u);
  // on a card seflex reads, which field the first one is would be a guess: an error
  EXPECT_TRUE(mentions(read_error("GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nRBE2,9,1,123456,2,\n        3, 4\n"),
                       {"deck.bdf:4: free-field continuation of RBE2 9 with data in columns 1-8", "start the line with a comma"}));
}

TEST(PublicDecks, FreeFieldTrailingCommaLargeFieldNameAndAFixedCardAfterALongLine) {
  // conedg01e.bdf: "CORD2R, 5, , 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, +C1," continued by "+C1, ..."
  const fem::Model m = read_deck("CORD2R, 5, , 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, +C1,\n+C1, 0.0, 1.0, 0.0\nGRID,1,5,1.,2.,3.\n");
  ASSERT_EQ(m.coords.size(), 1u);
  EXPECT_EQ(m.coords[0].abc[7], 1.0);
  EXPECT_NEAR(m.grids[0].x_basic.x(), -2.0, 1e-12);  // x' = basic y: (1, 2, 3) in 5 is (-2, 1, 3)
  EXPECT_NEAR(m.grids[0].x_basic.y(), 1.0, 1e-12);
  // se_test_n11.asm: "CORD2R *" (a blank before the large-field '*')
  const fem::Model l = read_deck(test::fixed_line({"CORD2R *", "5", "", "0.", "0."}, 16) +
                                 test::fixed_line({"*", "0.", "0.", "0.", "1."}, 16) + test::fixed_line({"*", "0.", "1.", "0."}, 16) +
                                 "GRID,1,5,1.,2.,3.\n");
  ASSERT_EQ(l.coords.size(), 1u);
  EXPECT_NEAR(l.grids[0].x_basic.x(), -2.0, 1e-12);
  // tb5pfstt.bdf: the fields of a long free-field line must not go to a fixed-format card after it
  const fem::Model t = read_deck("GRID,1,,0.,0.,0.\nPFASTT,1000,K,51,61,10251,,,,1,2\nTEMPD    111     20.\n");
  ASSERT_EQ(t.default_temperatures.size(), 1u);
  EXPECT_EQ(t.default_temperatures[0].sid, 111);
  EXPECT_EQ(t.default_temperatures[0].t, 20.0);
}

TEST(PublicDecks, CaseControlParamTakesPrecedenceOverTheBulkData) {
  // flyswatter.bdf: PARAM,WTMASS,.00259 in the case control, param,wtmass,.002588 in the bulk data
  const fem::Model m = read_deck(statics_deck("PARAM,WTMASS,.002588\n", "PARAM,WTMASS,.00259\n"));
  EXPECT_EQ(fem::param_number(m, "WTMASS", 1.0), 0.00259);
  // as in Nastran: not an approximation (nothing listed as unsupported), a warning naming both cards
  EXPECT_EQ(listed(m, "PARAM in the bulk data overridden by the case control"), nullptr);
  ASSERT_EQ(m.read_warnings.size(), 1u);
  EXPECT_TRUE(mentions(m.read_warnings[0], {"deck.bdf:14: PARAM WTMASS 0.002588 in the bulk data not used: the case control's PARAM WTMASS 0.00259 (deck.bdf:",
                                            ") takes precedence, as in Nastran"}));
  // a parameter seflex does not use may differ between subcases (htrussx.bdf: PARAM,EST)
  EXPECT_NO_THROW(read_deck("SOL 101\nCEND\nSUBCASE 1\nPARAM,EST,1\nSUBCASE 2\nPARAM,EST,-1\nBEGIN BULK\nGRID,1,,0.,0.,0.\nENDDATA\n"));
  // one it uses may not
  EXPECT_TRUE(mentions(read_error("PARAM,WTMASS,.1\nPARAM,WTMASS,.2\nGRID,1,,0.,0.,0.\n"),
                       {"deck.bdf:2: PARAM WTMASS: a second value (the first, at deck.bdf:1, differs)"}));
}

// ---------------------------------------------------------------------------------------------
// Field forms

TEST(PublicDecks, TflagWrittenAsAReal) {
  const std::string shells = test::base_deck();
  // ha145z.bdf: TFLAG 0.0 -> 0 (listed); dbxdra2.bdf: .63 (a thickness a column to the left?) -> refused
  const fem::Model zero = read_deck(shells + "CQUAD4,1,1,1,2,3,4\n,,,0.0,.1,.2,.3,.4\n");
  EXPECT_EQ(zero.shells[0].tflag, 0);
  EXPECT_EQ(zero.shells[0].t[3], 0.4);
  EXPECT_NE(listed(zero, "CQUAD4/CTRIA3 TFLAG written as a real (0. or 1.)"), nullptr);
  const fem::Model one = read_deck(shells + "CQUAD4,1,1,1,2,3,4\n,,,1.,.5,.5,.5,.5\n");
  EXPECT_EQ(one.shells[0].tflag, 1);
  const fem::Model frac = read_deck(statics_deck("PSHELL,2,1,0.002,1\nGRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\n"
                                                 "CQUAD4,5,2,1,2,3,4\n,,,.63,.67,,.53\n"));
  EXPECT_NE(listed(frac, "CQUAD4/CTRIA3 TFLAG a fraction"), nullptr);
  EXPECT_EQ(frac.shells[0].t[0], 0.67);
  EXPECT_TRUE(mentions(statics_refusal(frac), {"deck.bdf:16: CQUAD4/CTRIA3 TFLAG a fraction"}));
  EXPECT_TRUE(mentions(read_error(shells + "CQUAD4,1,1,1,2,3,4\n,,,2,.1,.2,.3,.4\n"), {"field 4 (TFLAG): got integer '2'; expected 0, 1 or blank"}));
}

TEST(PublicDecks, CosmicOrientationFlagInTheOfftField) {
  // pt145.bdf: "CBAR 1 1 1 2 .0 .0 1.0 1" (COSMIC: F = 1, X1-X3 a vector)
  const fem::Model m = read_deck("MAT1,1,7.e10,,0.3\nPBAR,1,1,1.e-4,2.e-8,2.e-8\nGRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\n"
                                 "GRID,3,,0.,0.,1.\nCBAR,1,1,1,2,.0,.0,1.0,1\nCBAR,2,1,1,2,3,,,2\n");
  EXPECT_EQ(m.bars[0].offt, "GGG");
  EXPECT_EQ(m.bars[0].v.z(), 1.0);
  EXPECT_EQ(m.bars[1].offt, "GGG");
  EXPECT_EQ(m.bars[1].g0, 3);
  // COSMIC's F = 1 / 2 is MSC's GGG (the vector or G0 in GA's displacement system, offsets at the
  // grids): read exactly, nothing listed; the same bar as with OFFT blank
  EXPECT_TRUE(m.unsupported.empty());
  const fem::Model blank = read_deck("MAT1,1,7.e10,,0.3\nPBAR,1,1,1.e-4,2.e-8,2.e-8\nGRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\n"
                                     "GRID,3,,0.,0.,1.\nCBAR,1,1,1,2,.0,.0,1.0\nCBAR,2,1,1,2,3\n");
  EXPECT_EQ(blank.bars[0].offt, m.bars[0].offt);
  EXPECT_EQ(blank.bars[1].offt, m.bars[1].offt);
  // F = 2 says G0, but X1-X3 is a vector: an error
  EXPECT_TRUE(mentions(read_error("GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nCBAR,1,1,1,2,.0,.0,1.0,2\n"),
                       {"deck.bdf:3: CBAR 1, field 9 (OFFT): got integer '2'", "COSMIC's flag F: 1 with a vector X1-X3, 2 with G0"}));
}

TEST(PublicDecks, ZeroForNoPinFlagsOrPermanentConstraints) {
  const fem::Model m = read_deck("MAT1,1,7.e10,,0.3\nPBAR,1,1,1.e-4,2.e-8,2.e-8\nGRID,1,,0.,0.,0.,,0\nGRID,2,,1.,0.,0.\n"
                                 "CBAR,1,1,1,2,0.,1.,0.\n,0,0\n");
  EXPECT_EQ(m.grids[0].ps, 0);
  EXPECT_EQ(m.bars[0].pa, 0);
  EXPECT_EQ(m.bars[0].pb, 0);
}

TEST(PublicDecks, PsolidStressAsAnInteger) {
  // gpst17.bdf: PSOLID 10 ... STRESS = 1 (GAUSS)
  const fem::Model m = read_deck("MAT1,1,7.e10,,0.3\nPSOLID,10,1,,,1\n");
  EXPECT_EQ(m.solid_props[0].stress, "1");
  EXPECT_TRUE(mentions(read_error("MAT1,1,7.e10,,0.3\nPSOLID,10,1,,,5\n"), {"PSOLID 10, field 6 (STRESS): got integer '5'; expected 0/GRID, 1/GAUSS or blank"}));
}

// ---------------------------------------------------------------------------------------------
// Read for seflex info, refused by solutions

TEST(PublicDecks, PoissonRatioAboveOneHalfOnRodsIsAWarningOnShellsARefusal) {
  // freedlm.bdf: MAT1 3 2.06+7 580000. 16.7586 (NU = E/2G - 1 of an equivalent plate material), used
  // by its PROD and PBARL cards only: rods and bars take E and G, so it runs with a warning
  const fem::Model m = read_deck(statics_deck("MAT1,3,2.06+7,580000.,16.7586\nPROD,5,3,1.e-4\n"));
  EXPECT_EQ(m.mat1[1].nu, 16.7586);
  EXPECT_EQ(m.mat1[1].G, 580000.);  // as given, not E / 2 (1 + NU)
  EXPECT_TRUE(m.unsupported.empty());
  ASSERT_EQ(m.read_warnings.size(), 1u);
  EXPECT_EQ(m.read_warnings[0], "deck.bdf:13: MAT1 3 NU = 16.7586 is above 0.5 (the QRG's range is -1 < NU <= 0.5); only "
                                "rods, bars and beams use it, which take E and G, not NU: read as given");
  EXPECT_EQ(statics_refusal(m), "");
  // on a shell (or a solid, a shear panel, a composite ply) NU is used: refused, naming the MAT1 card
  const fem::Model s = read_deck(statics_deck("MAT1,3,2.06+7,580000.,16.7586\nPSHELL,5,1,.01,3\n"));
  EXPECT_TRUE(mentions(statics_refusal(s), {"deck.bdf:13: MAT1 NU above 0.5", "seflex does not model MAT1 NU above 0.5"}));
  ASSERT_EQ(s.read_warnings.size(), 1u);
  EXPECT_TRUE(mentions(s.read_warnings[0], {"deck.bdf:13: MAT1 3 NU = 16.7586", "PSHELL 5 uses it"}));
  EXPECT_TRUE(mentions(read_error("MAT1,7,2.1+11,,-1.\n"), {"MAT1 7, field 5 (NU): got real '-1.'; expected -1 < NU <= 0.5"}));
}

TEST(PublicDecks, OffsetDefinitionWithoutOffsetsIsAWarning) {
  // rigid_rbe2.bdf, cbush_test.bdf: MDLPRM OFFDEF LROFF in decks with no element offset
  const fem::Model m = read_deck(statics_deck("MDLPRM,OFFDEF,LROFF\n"));
  EXPECT_TRUE(m.unsupported.empty());
  ASSERT_EQ(m.read_warnings.size(), 1u);
  EXPECT_EQ(m.read_warnings[0], "deck.bdf:13: MDLPRM OFFDEF: no element of the deck has an offset (CBAR/CBEAM WA/WB, "
                                "shell ZOFFS, CBUSH OCID, CONM2 X): nothing for it to define; not used");
  EXPECT_EQ(statics_refusal(m), "");
  // a CBAR with an offset: what OFFDEF defines is there, and seflex does not model OFFDEF: listed
  const fem::Model o = read_deck(statics_deck("MDLPRM,OFFDEF,LROFF\nGRID,3,,2.,0.,0.\nCBAR,2,1,2,3,0.,1.,0.\n,,,0.,0.,.1\n"));
  EXPECT_NE(listed(o, "MDLPRM OFFDEF (model parameter not used)"), nullptr);
  EXPECT_TRUE(o.read_warnings.empty());
}

TEST(PublicDecks, FluidGridsAreListedAndRefused) {
  const fem::Model m = read_deck(statics_deck("GRID,3,,0.,1.,0.,-1\n"));
  EXPECT_EQ(m.grids[2].cd, 0);
  EXPECT_TRUE(mentions(statics_refusal(m), {"deck.bdf:13: GRID CD = -1 (fluid)"}));
  const fem::Model g = read_deck("GRDSET,,,,,,-1\nGRID,3,,0.,1.,0.\n");
  ASSERT_NE(listed(g, "GRID CD = -1 (fluid)"), nullptr);
  EXPECT_TRUE(mentions(read_error("GRID,3,,0.,1.,0.,-2\n"), {"GRID 3, field 7 (CD): got integer '-2'; expected a coordinate system id >= 0, blank or -1"}));
}

TEST(PublicDecks, RigidElementsAreNumberedApart) {
  // aerobeam.bdf: CONM2 111 and RBAR 111; dbxdra7.bdf: CBEAM 1001 and RBAR 1001
  const std::string base = "MAT1,1,7.e10,,0.3\nPBAR,1,1,1.e-4,2.e-8,2.e-8\nGRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\n"
                           "CBAR,5,1,1,2,0.,1.,0.\nCONM2,6,2,,1.\n";
  const fem::Model m = read_deck(base + "RBAR,5,1,2,123456\nRBE2,6,1,123,2\n");
  EXPECT_EQ(m.rbars.size(), 1u);
  EXPECT_EQ(m.rbe2.size(), 1u);
  EXPECT_TRUE(mentions(read_error(base + "RBAR,5,1,2,123456\nRBE2,5,1,123,2\n"),
                       {"deck.bdf:8: RBE2 5, field 2 (EID): duplicate rigid element id, first defined at deck.bdf:7 (RBAR)"}));
  EXPECT_TRUE(mentions(read_error(base + "CROD,6,1,1,2\n"), {"CROD 6, field 2 (EID): duplicate element id"}));
}

TEST(PublicDecks, ElementsOnUnsupportedMaterialsOrPropertiesAreLeftOutAndRefused) {
  const std::string hexa = "GRID,11,,0.,0.,1.\nGRID,12,,1.,0.,1.\nGRID,13,,1.,1.,1.\nGRID,14,,0.,1.,1.\n"
                           "GRID,15,,0.,0.,2.\nGRID,16,,1.,0.,2.\nGRID,17,,1.,1.,2.\nGRID,18,,0.,1.,2.\n"
                           "CHEXA,40,4,11,12,13,14,15,16,\n,17,18\n";
  // htflw47.bdf: PSOLID on a MAT4 (heat transfer only)
  const fem::Model heat = read_deck(statics_deck(hexa + "PSOLID,4,9\nMAT4,9,204.\n"));
  EXPECT_TRUE(heat.solids.empty());
  EXPECT_TRUE(heat.solid_props.empty());
  ASSERT_NE(listed(heat, "PSOLID on MAT4 (left out)"), nullptr);
  ASSERT_NE(listed(heat, "CHEXA on PSOLID on MAT4 (left out)"), nullptr);
  EXPECT_EQ(listed(heat, "CHEXA on PSOLID on MAT4 (left out)")->first.line, 21u);
  EXPECT_TRUE(mentions(statics_refusal(heat), {"deck.bdf:21: CHEXA on PSOLID on MAT4 (left out)", "seflex does not model"}));
  // the bar stays: its mass is still there for seflex info
  EXPECT_EQ(heat.bars.size(), 1u);
  // nx/composite_solids: CHEXA on a PCOMPS
  const fem::Model pcomps = read_deck(statics_deck(hexa + "PCOMPS,4,,,,,,,\n,1,1,.5,0.\n"));
  EXPECT_TRUE(pcomps.solids.empty());
  EXPECT_NE(listed(pcomps, "CHEXA on PCOMPS (left out)"), nullptr);
  // fsi.bdf: a fluid PSOLID (FCTN = PFLUID) on a MAT10
  const fem::Model fluid = read_deck(statics_deck(hexa + "PSOLID,4,9,,,,,PFLUID\nMAT10,9,,1.2,340.\n"));
  EXPECT_TRUE(fluid.solids.empty());
  EXPECT_NE(listed(fluid, "PSOLID FCTN = PFLUID"), nullptr);
  EXPECT_NE(listed(fluid, "CHEXA on PSOLID FCTN = PFLUID (left out)"), nullptr);
  // bwb: a PBEAML on a MAT8
  const fem::Model beam = read_deck(statics_deck("MAT8,8,1.e10,1.e9,.3,1.e9\nPBEAML,3,8,,ROD\n,.01\nCBEAM,3,3,1,2,0.,1.,0.\n"));
  EXPECT_EQ(beam.bars.size(), 1u);
  EXPECT_EQ(beam.bars[0].id, 1);
  EXPECT_NE(listed(beam, "PBEAML on MAT8 (left out)"), nullptr);
  EXPECT_NE(listed(beam, "CBEAM on PBEAML on MAT8 (left out)"), nullptr);
  EXPECT_TRUE(mentions(statics_refusal(beam), {"PBEAML on MAT8 (left out)"}));
  // bwb_saero_trim.bdf: PBEAML 5 and 999 on MAT8 that no CBEAM uses (Simcenter Nastran ran the deck:
  // bwb_saero_trim.f06): left out with a warning, nothing refused
  const fem::Model unused = read_deck(statics_deck("MAT8,8,1.e10,1.e9,.3,1.e9\nPBEAML,3,8,,ROD\n,.01\n"));
  EXPECT_TRUE(unused.unsupported.empty());
  ASSERT_EQ(unused.read_warnings.size(), 1u);
  EXPECT_EQ(unused.read_warnings[0], "deck.bdf:14: PBEAML 3 on MAT8: no element uses it; left out (seflex does not model it)");
  EXPECT_EQ(statics_refusal(unused), "");
  // contact/model1_sim1-solution_1.bdf: a CTETRA with some of its mid-edge grids (G5 = 0 and G7-G10
  // blank: straight edges; tests/fem/solid_partial_test.cpp): read, used by solutions
  const fem::Model tetra = read_deck(statics_deck(hexa.substr(0, hexa.find("CHEXA")) + "PSOLID,4,1\nCTETRA,41,4,11,12,13,15,0,17\n"));
  ASSERT_EQ(tetra.solids.size(), 1u);
  EXPECT_EQ(tetra.solids[0].nnode, 5);
  EXPECT_EQ(tetra.solids[0].g[4], 17);
  EXPECT_EQ(tetra.solids[0].missing_mid, 0b111101);
  EXPECT_TRUE(tetra.unsupported.empty());
  EXPECT_EQ(statics_refusal(tetra), "");
  // a MID or PID that no card defines is still an error
  EXPECT_TRUE(mentions(read_error(hexa + "PSOLID,4,9\n"), {"PSOLID 4, field 3 (MID): references MAT1 9, which is not defined"}));
  EXPECT_TRUE(mentions(read_error(hexa), {"CHEXA 40, field 3 (PID): references property 4, which is not defined"}));
}

TEST(PublicDecks, ScalarPointsTwiceOrImpliedByScalarElements) {
  // freq_sine/good_sine.dat: SPOINT 1000 twice; dbxdra2.bdf: CELAS3 on a point no SPOINT lists
  const fem::Model m = read_deck("SPOINT,1000\nSPOINT,1000,1001\nPELAS,1,100.\nCELAS3,5,1,0,1302\nCELAS4,6,50.,1302,1303\n");
  ASSERT_EQ(m.spoints.size(), 4u);
  EXPECT_EQ(m.spoints[2].id, 1302);
  EXPECT_EQ(m.spoints[3].id, 1303);
  // Nastran accepts it (good_sine.op2 holds Nastran's results of that deck): a warning, nothing unsupported
  EXPECT_TRUE(m.unsupported.empty());
  ASSERT_EQ(m.read_warnings.size(), 1u);
  EXPECT_EQ(m.read_warnings[0], "deck.bdf:2: SPOINT 1000 given again (first at deck.bdf:1): one scalar point kept, as Nastran does");
  // a grid id on CELAS3 is still an error
  EXPECT_TRUE(mentions(read_error("GRID,7,,0.,0.,0.\nPELAS,1,100.\nCELAS3,5,1,7\n"), {"deck.bdf:3: CELAS3 5, field 4 (S1): references point 7, which is not an SPOINT; expected a scalar point (it is a GRID: use CELAS1 or CELAS2)"}));
}

}  // namespace
}  // namespace seflex
