// seflex convert / io::write_nastran: a model written as a Nastran deck reads back to the same model
// (bitwise the same assembled K and M, the same node sets, and - written again - the same text), for
// the meshes/ decks, the validation decks, a deck using every card the writer knows, and gmsh models.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "gmsh_test_util.hpp"
#include "seflex/io/model_reader.hpp"
#include "seflex/io/nastran.hpp"
#include "seflex/io/nastran_writer.hpp"

using namespace seflex;

namespace {

/// The deck written for `m`, without its leading comment lines (which name the source files).
std::string deck_text(const fem::Model& m) {
  std::ostringstream out;
  io::write_nastran(m, out);
  std::string s = out.str();
  while (s.rfind("$ ", 0) == 0) s.erase(0, s.find('\n') + 1);
  return s;
}

/// Write `m`, read it back (through read_model, so $seflex sets count), check and return it.
fem::Model round_trip(const fem::Model& m) {
  test::TempDir dir;
  const auto path = dir / "out.bdf";
  io::write_nastran_file(m, path, false);
  fem::Model back = io::read_model(path);
  test::expect_same_matrices(m, back);
  EXPECT_EQ(back.node_sets, m.node_sets);
  EXPECT_EQ(deck_text(back), deck_text(m));  // a fixed point: nothing lost or changed on the way
  return back;
}

/// Every card and case-control command the writer knows, with non-default values in awkward forms
/// (Nastran exponents, blank fields taking defaults, MAT1 with one of E, G, NU blank).
const char* kAllCards = R"(SOL 103
CEND
TITLE = ROUND TRIP
SUBTITLE = EVERY CARD
METHOD = 1
SPC = 10
K2GG = KX
SUBCASE 1
  LABEL = FIRST
  LOAD = 20
SUBCASE 2
  SPC = 11
BEGIN BULK
PARAM,COUPMASS,1
PARAM,WTMASS,2.59-3
PARAM,GRDPNT,1
CORD2R,5,,0.1,0.2,0.3,0.1,0.2,1.3,+C
+C,1.1,0.2,0.3
CORD2C,6,5,0.,0.,0.,0.,0.,1.
,1.,0.,0.
CORD1R,7,1,2,3
GRID,1,,0.,0.,0.
GRID,2,5,0.9,-0.2,-0.3,6
GRID,3,,1.,1.,0.,6
GRID,4,6,1.5,30.,0.2
GRID,5,,0.,1.,0.,,3
GRID,6,,2.,0.,0.
GRID,7,,2.,1.,0.
GRID,8,,3.,1.,0.
GRID,9,,0.5,2.,0.
GRID,10,,1.,0.5,0.5
SPOINT,100,101
MAT1,1,7.1+10,,.3,2700.,2.3-5,20.,0.01
MAT1,2,2.1E11,8.E10,,7800.
MAT1,3,,2.6+10,0.3,1000.
MAT1,4,1.,0.1
MAT1,5,2.+11
PBAR,10,1,5.4-4,7.-8,6.-8,1.4-7,0.1,,+P
+P,,,,,,,,,+Q
+Q,0.8,0.9,1.-9
PBARL,11,2,,TUBE,,,,,+L
+L,0.05,0.04,0.2
PBEAM,12,1,1.-3,2.-7,3.-7,1.-8,4.-7,0.5
PBEAML,13,2,,BOX,,,,,+B
+B,0.1,0.08,0.005,0.004,0.
PROD,14,1,2.-4,1.-8,0.01,0.02
PSHELL,20,1,0.002,1,,1,,0.1
PSHELL,21,2,0.003,2,1.2,2,0.9,
,-0.001,0.002
PSHELL,22,1,0.002,1,,1,,,+S
+S,,,6
MAT2,6,1.+9,2.+8,0.,1.1+9,0.,3.+8,900.
MAT8,7,1.81+11,1.03+10,0.28,7.17+9,5.+9,,1600.
PCOMP,23,-0.001,0.5,,HILL,,,SYM
,7,1.25-4,0.,YES,,,45.,
,6,2.-4,-45.
PCOMPG,24,,,,,,,MEM
,101,7,0.001,30.,NO
,102,,,-30.
PELAS,30,1.+5,0.01,0.,31,2.+3
CBAR,1000,10,1,2,0.,0.,1.,,+A
+A,,456,0.,0.01,0.,0.,0.,0.02
CBAR,1001,11,2,6,5
CBEAM,1002,12,6,7,0.,0.,1.
CBEAM,1003,13,1,5,1.,0.,0.
CROD,1004,14,5,7
CONROD,1005,3,7,1,1.-4,1.-9,0.,0.3
CQUAD4,1006,20,1,2,3,5,30.,0.001
CQUAD4,1007,21,2,6,7,3,7,,+T
+T,,,1,0.9,1.,1.1,1.
CTRIA3,1008,20,5,3,9,,0.
CELAS1,1009,30,1,3,2,3
CELAS1,1010,31,100,,
CELAS2,1011,5.+4,3,2,,,0.02,0.1
RBE2,1012,7,123,8
CQUAD4,1019,23,1,2,3,5,0
CTRIA3,1020,24,5,3,9,15.
CQUAD4,1021,22,1,2,3,5
RBAR,1016,8,9,123456,,,,1.-5
RBAR,1018,1,9,1236,45,4,6
RBE3,1017,,10,123,1.,123,1,3
,5,2.5,123,6,7
,UM,10,12,1,3
,ALPHA,1.-5
CONM2,1013,6,0,2.5,0.01,0.,0.
,0.1,0.,0.2,0.,0.,0.3
CONM2,1014,4,-1,1.5,1.5,30.,0.2
CONM2,1015,3,5,0.5
SPC,10,1,123456,0.
SPC1,11,123,1
SPC,12,9,3,0.001
SPCADD,13,10,12
MPC,40,1,3,1.,2,3,-0.5
,,5,1,2.,6,2,1.
,,100,0,1.
MPCADD,41,40
OMIT,3,456
OMIT1,5,6,7
ASET,2,123
BSET,1,456
SUPORT,7,1
FORCE,20,6,0,100.,0.,1.,0.
MOMENT,21,7,5,2.,1.,0.,0.
LOAD,22,1.,2.,20,3.,21
EIGRL,1,0.,100.,10,,,,MASS
EIGR,2,LAN,,,,5,,,+E
+E,POINT,6,3
DMIG,KX,0,6,2,0
DMIG,KX,100,0,,100,0,1.+3,,+D
+D,101,0,-5.,
DMIG,KX,101,0,,101,0,2.+3
ENDDATA
)";

}  // namespace

TEST(NastranWriter, RoundTripsMeshesAndValidationDecks) {
  for (const auto& p : {test::meshes_dir() / "panel.bdf", test::meshes_dir() / "yoke.bdf",
                        test::validation_dir() / "mystran_cbar_cantilever_and_freefree_modes/BAR-FF-GIV.DAT",
                        test::validation_dir() / "mystran_craig_bampton_cbar_frame/CB-EXAMPLE-12.DAT",
                        test::validation_dir() / "mystran_mixed_cbar_crod_cquad4_ctria3_celas_modes/ALL-ELEM-TEST-GIV.DAT"}) {
    SCOPED_TRACE(p.string());
    const fem::Model m = io::read_model(p);
    const fem::Model back = round_trip(m);
    EXPECT_EQ(back.case_control.sol, m.case_control.sol);
    EXPECT_EQ(back.case_control.title, m.case_control.title);
    EXPECT_EQ(back.case_control.global.spc, m.case_control.global.spc);
    EXPECT_EQ(back.case_control.global.method, m.case_control.global.method);
  }
}

TEST(NastranWriter, RoundTripsEveryCard) {
  test::TempDir dir;
  const fem::Model m = io::read_model(dir.write("all.bdf", kAllCards));
  // every card is supported; the notes: PSHELL 21's Z1/Z2 (stress fibres, not used) and PCOMP 23's
  // MAT2 ply (rigid in transverse shear)
  ASSERT_EQ(m.unsupported.size(), 2u);
  EXPECT_EQ(m.unsupported[0].name.rfind("PSHELL Z1/Z2", 0), 0u) << m.unsupported[0].name;
  EXPECT_EQ(m.unsupported[1].name.rfind("PCOMP ply of MAT2", 0), 0u) << m.unsupported[1].name;
  const fem::Model back = round_trip(m);
  // Spot checks of values that only the writer's choices preserve.
  EXPECT_EQ(back.mat1[0].G, m.mat1[0].G);     // G blank: recomputed from E and NU
  EXPECT_EQ(back.mat1[1].nu, m.mat1[1].nu);   // NU blank: recomputed from E and G
  EXPECT_EQ(back.mat1[2].E, m.mat1[2].E);     // E blank
  EXPECT_EQ(back.mat1[3].nu, 4.0);            // NU = E / (2 G) - 1 = 4: only a blank NU reads back
  EXPECT_EQ(back.mat1[4].G, 0.0);             // E only: G = NU = 0 (QRG MAT1)
  EXPECT_EQ(back.bar_props[0].K1, 0.8);
  EXPECT_EQ(back.bar_props[0].I12, 1e-9);
  EXPECT_EQ(back.bar_props[1].dims, (std::vector<double>{0.05, 0.04}));
  EXPECT_EQ(back.bar_props[2].K1, 1.0);       // PBEAM default K1 = 1 written explicitly
  EXPECT_EQ(back.shell_props[1].z1, -0.001);
  EXPECT_EQ(back.shell_props[2].mid4, 6);
  ASSERT_EQ(back.mat2.size(), 1u);
  EXPECT_EQ(back.mat2[0].G22, 1.1e9);
  ASSERT_EQ(back.mat8.size(), 1u);
  EXPECT_EQ(back.mat8[0].G1z, 5e9);
  EXPECT_EQ(back.mat8[0].G2z, 0.0);  // blank stays blank (rigid)
  ASSERT_EQ(back.composite_props.size(), 2u);
  EXPECT_EQ(back.composite_props[0].lam, fem::CompositeProperty::Lam::Sym);
  EXPECT_EQ(back.composite_props[0].z0, -0.001);
  EXPECT_EQ(back.composite_props[0].ft, "HILL");
  ASSERT_EQ(back.composite_props[0].plies.size(), 3u);
  EXPECT_EQ(back.composite_props[0].plies[1].mid, 7);  // blank MID2: ply 1's, written explicitly
  EXPECT_EQ(back.composite_props[0].plies[2].theta_deg, -45.0);
  EXPECT_FALSE(back.composite_props[1].has_z0);
  EXPECT_EQ(back.composite_props[1].lam, fem::CompositeProperty::Lam::Mem);
  EXPECT_EQ(back.composite_props[1].plies.at(1).gplyid, 102);
  EXPECT_EQ(back.composite_props[1].plies.at(1).t, 0.001);
  EXPECT_EQ(back.shells[1].theta_is_mcid, true);
  EXPECT_EQ(back.shells[1].mcid, 7);
  EXPECT_EQ(back.shells[1].tflag, 1);
  EXPECT_EQ(back.bars[0].pb, m.bars[0].pb);
  EXPECT_EQ(back.bars[1].g0, 5);
  EXPECT_EQ(back.conm2[1].cid, -1);
  EXPECT_EQ(back.spcs.size(), m.spcs.size());
  EXPECT_EQ(back.spcs.back().d, 0.001);
  EXPECT_EQ(back.dmigs.at(0).entries.size(), 3u);
  ASSERT_EQ(back.rbars.size(), 2u);
  EXPECT_EQ(back.rbars[0].cmb, 0x3F);  // blank CMA, CMB: the complement of CNA, CNB
  EXPECT_EQ(back.rbars[0].alpha, 1e-5);
  EXPECT_EQ(back.rbars[1].cma, 8);     // CMA 4 as given
  ASSERT_EQ(back.rbe3.size(), 1u);
  EXPECT_EQ(back.rbe3[0].groups.size(), 2u);
  EXPECT_EQ(back.rbe3[0].groups[1].weight, 2.5);
  EXPECT_EQ(back.rbe3[0].groups[1].grids, (std::vector<int>{6, 7}));
  EXPECT_EQ(back.rbe3[0].um.size(), 2u);
  EXPECT_EQ(back.rbe3[0].alpha, 1e-5);
  ASSERT_EQ(back.mpcs.size(), 1u);
  EXPECT_EQ(back.mpcs[0].terms.size(), 5u);
  EXPECT_EQ(back.mpcs[0].terms[4].grid, 100);
  EXPECT_EQ(back.mpcadds.at(0).sets, std::vector<int>{40});
  EXPECT_EQ(back.omit.size(), 3u);
  EXPECT_EQ(back.eigen_methods.at(1).norm, "POINT");
  EXPECT_EQ(back.case_control.subcases.size(), 2u);
  EXPECT_EQ(back.case_control.subcases[0].label, "FIRST");
  EXPECT_EQ(back.case_control.subcases[1].spc, 11);
  EXPECT_EQ(back.case_control.global.k2gg, std::vector<std::string>{"KX"});
  double w = 0;
  for (const auto& p : back.params)
    if (p.name == "WTMASS") w = std::stod(p.values.at(0));
  EXPECT_EQ(w, 2.59e-3);
}

TEST(NastranWriter, RealsRoundTripExactly) {
  // Values that need all 17 significant digits, subnormal and huge magnitudes.
  test::TempDir dir;
  const std::string deck = "GRID,1,,0.1,0.30000000000000004,-1.2345678901234567e-300\n"
                           "GRID,2,,1.7976931348623157e308,4.9e-324,-0.\n";
  const fem::Model m = io::read_nastran(dir.write("r.bdf", deck));
  std::ostringstream out;
  io::write_nastran(m, out);
  const fem::Model back = io::read_nastran_text(out.str(), "back.bdf");
  ASSERT_EQ(m.grids.size(), 2u);
  ASSERT_EQ(back.grids.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(back.grids[i].x(k), m.grids[i].x(k)) << i << " " << k;
  EXPECT_EQ(back.grids[0].x(1), 0.30000000000000004);
  EXPECT_EQ(back.grids[1].x(1), 4.9e-324);
  EXPECT_TRUE(std::signbit(back.grids[1].x(2)));  // -0. stays negative (== cannot tell it from 0.)
}

TEST(GmshConvert, GmshModelRoundTripsThroughNastran) {
  io::ModelReadOptions o;
  o.parameters.push_back({"refine", 2});
  const fem::Model m = io::read_model(test::meshes_dir() / "panel.geo", o);
  const fem::Model back = round_trip(m);
  EXPECT_EQ(back.node_sets.at("interface_3d"), (std::vector<int>{1, 2, 3, 4}));
}

TEST(GmshConvert, CommandLine) {
  test::TempDir dir;
  const std::string out = (dir / "panel2.bdf").string();
  const std::string geo = (test::meshes_dir() / "panel.geo").string();
  auto r = test::run_seflex("convert '" + geo + "' -o '" + out + "' --set refine=2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("87 grids"), std::string::npos) << r.out;  // 9 x 9 + 6
  io::ModelReadOptions o;
  o.parameters.push_back({"refine", 2});
  test::expect_same_matrices(io::read_model(geo, o), io::read_model(out));

  // An existing file is not overwritten without --force, and is left as it was.
  const std::string before = test::read_file(out);
  r = test::run_seflex("convert '" + (test::meshes_dir() / "panel.bdf").string() + "' -o '" + out + "'");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("exists"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  EXPECT_EQ(test::read_file(out), before);
  r = test::run_seflex("convert '" + (test::meshes_dir() / "panel.bdf").string() + "' -o '" + out + "' --force");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  test::expect_same_matrices(io::read_model(test::meshes_dir() / "panel.bdf"), io::read_model(out));

  // Usage errors: no -o, a --set that is not NAME=VALUE.
  EXPECT_EQ(test::run_seflex("convert '" + geo + "'").exit_code, 2);
  EXPECT_EQ(test::run_seflex("convert '" + geo + "' -o x.bdf --set refine").exit_code, 2);
}
