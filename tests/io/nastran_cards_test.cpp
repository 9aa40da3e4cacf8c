// Card by card: fields, blank-field defaults and the cross-card rules of the MSC Nastran QRG
// (GRDSET, BAROR/BEAMOR, PID = EID, MAT1's E/G/NU rule, PSHELL and PBEAM defaults), and coordinate
// systems resolved to basic against positions worked out by hand.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <sstream>

#include "nastran_test_util.hpp"
#include "seflex/fem/components.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/io/nastran_writer.hpp"

using namespace seflex;
using seflex::test::base_deck;
using seflex::test::fixed_line;
using seflex::test::mentions;
using seflex::test::read_deck;

namespace {

const fem::Grid& grid(const fem::Model& m, int id) { return m.grids.at(m.grid_index.at(id)); }

void expect_near(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tol = 1e-12) {
  EXPECT_LT((a - b).norm(), tol) << "got " << a.transpose() << ", expected " << b.transpose();
}

}  // namespace

TEST(NastranCards, GridAndGrdsetDefaults) {
  // GRDSET fills blank CP, CD and PS; explicit values (also an explicit 0) stay.
  const fem::Model m = read_deck(
      "CORD2R,5,,0.,0.,0.,0.,0.,1.\n,1.,0.,0.\n"
      "GRDSET,,5,,,,5,246\n"
      "GRID,1,,1.,2.,3.\n"
      "GRID,2,0,1.,2.,3.,0,13\n");
  const fem::Grid& g1 = grid(m, 1);
  EXPECT_EQ(g1.cp, 5);
  EXPECT_EQ(g1.cd, 5);
  EXPECT_EQ(fem::component_string(g1.ps), "246");
  const fem::Grid& g2 = grid(m, 2);
  EXPECT_EQ(g2.cp, 0);
  EXPECT_EQ(g2.cd, 0);
  EXPECT_EQ(fem::component_string(g2.ps), "13");
}

TEST(NastranCards, RectangularCylindricalAndSphericalSystems) {
  // CORD2R 1: origin (1,2,3), z along basic x, x-z plane through (1,2,4) -> e3 = (1,0,0),
  // e2 = e3 x (C-A) / |.| = (1,0,0) x (0,0,1) = (0,-1,0), e1 = e2 x e3 = (0,0,1).
  // CORD2C 2: origin (1,0,0), axes = basic. CORD2S 3: origin (0,0,10), axes = basic.
  // CORD2R 4 defined in the cylindrical system 2: A at (R,THETA,Z) = (1,90,0) -> basic (1,1,0).
  const fem::Model m = read_deck(
      "CORD2R,1,,1.,2.,3.,2.,2.,3.\n,1.,2.,4.\n"
      "CORD2C,2,,1.,0.,0.,1.,0.,1.\n,2.,0.,0.\n"
      "CORD2S,3,,0.,0.,10.,0.,0.,11.\n,1.,0.,10.\n"
      "CORD2R,4,2,1.,90.,0.,1.,90.,1.\n,2.,90.,0.\n"
      "GRID,1,1,1.,0.,0.\n"      // along e1 of system 1 -> (1,2,3) + (0,0,1)
      "GRID,2,2,2.,90.,1.,2\n"   // R=2, THETA=90, Z=1 about (1,0,0) -> (1,2,1)
      "GRID,3,3,1.,90.,90.,3\n"  // R=1, THETA=90 (from z), PHI=90 -> (0,1,10)
      "GRID,4,4,0.,0.,0.\n"      // origin of system 4 -> (1,1,0)
      "GRID,5,3,2.,0.,0.,3\n");  // on the polar axis -> (0,0,12)
  expect_near(grid(m, 1).x_basic, {1, 2, 4});
  expect_near(grid(m, 2).x_basic, {1, 2, 1});
  expect_near(grid(m, 3).x_basic, {0, 1, 10});
  expect_near(grid(m, 4).x_basic, {1, 1, 0});
  expect_near(grid(m, 5).x_basic, {0, 0, 12});
  // displacement axes: at grid 2 the cylindrical radial direction is basic y, tangential is -x
  const Eigen::Matrix3d a2 = fem::displacement_axes(m, 2, grid(m, 2).x_basic);
  expect_near(a2.col(0), {0, 1, 0});
  expect_near(a2.col(1), {-1, 0, 0});
  expect_near(a2.col(2), {0, 0, 1});
  // spherical at grid 3 (THETA = PHI = 90 deg): radial = y, polar = -z, azimuthal = -x
  const Eigen::Matrix3d a3 = fem::displacement_axes(m, 3, grid(m, 3).x_basic);
  expect_near(a3.col(0), {0, 1, 0});
  expect_near(a3.col(1), {0, 0, -1});
  expect_near(a3.col(2), {-1, 0, 0});
  // on the polar axis the azimuth 0 is used: radial = z, polar = x, azimuthal = y
  const Eigen::Matrix3d a5 = fem::displacement_axes(m, 3, grid(m, 5).x_basic);
  expect_near(a5.col(0), {0, 0, 1});
  expect_near(a5.col(1), {1, 0, 0});
  expect_near(a5.col(2), {0, 1, 0});
  // rectangular system 1: axes are its unit vectors
  const Eigen::Matrix3d a1 = fem::displacement_axes(m, 1, Eigen::Vector3d::Zero());
  expect_near(a1.col(0), {0, 0, 1});
  expect_near(a1.col(1), {0, -1, 0});
  expect_near(a1.col(2), {1, 0, 0});
  EXPECT_NEAR(a1.determinant(), 1.0, 1e-14);
}

TEST(NastranCards, Cord1DefinedByGridsInAnotherSystem) {
  // CORD1R 7 on grids 1 (origin), 2 (on z), 3 (in x-z plane); grid 2 is given in CORD2R 1, which is
  // basic shifted by (0,0,5): grid 2 basic = (0,0,5). So system 7 = basic; grid 10 in 7 at (1,2,3).
  const fem::Model m = read_deck(
      "CORD2R,1,,0.,0.,5.,0.,0.,6.\n,1.,0.,5.\n"
      "GRID,1,,0.,0.,0.\nGRID,2,1,0.,0.,0.\nGRID,3,,4.,0.,0.\n"
      "CORD1R,7,1,2,3\n"
      "GRID,10,7,1.,2.,3.\n");
  expect_near(grid(m, 2).x_basic, {0, 0, 5});
  expect_near(grid(m, 10).x_basic, {1, 2, 3});
}

TEST(NastranCards, CbarFieldsAndBarorDefaults) {
  const fem::Model m = read_deck(base_deck() +
                                 "BAROR,,30,,,0.,1.,0.,GOO\n"
                                 "PBAR,30,1,1.\nPBAR,40,1,1.\nPBAR,41,1,1.\n"
                                 "CBAR,41,,1,2\n"                                   // PID, vector, OFFT from BAROR
                                 "CBAR,42,40,1,3,4,,,BGG\n,123,456,.1,.2,.3,.4,.5,.6\n"  // G0, pins, offsets
                                 "CBAR,43,40,2,3,1.,2.\n");                          // X3 blank = 0
  ASSERT_EQ(m.bars.size(), 3u);
  const fem::Bar& b1 = m.bars[0];
  EXPECT_EQ(b1.pid, 30);
  EXPECT_FALSE(b1.has_g0);
  EXPECT_EQ(b1.v, Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(b1.offt, "GOO");
  const fem::Bar& b2 = m.bars[1];
  EXPECT_TRUE(b2.has_g0);
  EXPECT_EQ(b2.g0, 4);
  EXPECT_EQ(b2.offt, "BGG");
  EXPECT_EQ(fem::component_string(b2.pa), "123");
  EXPECT_EQ(fem::component_string(b2.pb), "456");
  EXPECT_EQ(b2.wa, Eigen::Vector3d(.1, .2, .3));
  EXPECT_EQ(b2.wb, Eigen::Vector3d(.4, .5, .6));
  EXPECT_EQ(m.bars[2].v, Eigen::Vector3d(1, 2, 0));
  EXPECT_EQ(m.bars[2].offt, "GOO");  // blank OFFT takes BAROR's
  // without BAROR: blank PID is the element id, blank OFFT is GGG
  const fem::Model n = read_deck(base_deck() + "PBAR,7,1,1.\nCBAR,7,,1,2,0.,0.,1.\n");
  EXPECT_EQ(n.bars[0].pid, 7);
  EXPECT_EQ(n.bars[0].offt, "GGG");
}

TEST(NastranCards, CbeamPbeamEndAAndTaper) {
  const fem::Model m = read_deck(base_deck() +
                                 "BEAMOR,,50,,,0.,0.,1.\n"
                                 "PBEAM,50,1,2.,3.,4.,.5,6.,.7\n"  // end A; no K line: K1 = K2 = 1 (QRG default)
                                 "PBEAM,51,1,2.,3.,4.,,6.\n,1.,1.\n,NO,1.,1.,3.,4.,,6.\n,.5,.6\n"  // taper + K line
                                 "CBEAM,60,,1,2\nCBEAM,61,51,2,3,0.,1.,0.\n");
  ASSERT_EQ(m.bar_props.size(), 2u);
  const fem::BarProperty& p = m.bar_props[0];
  EXPECT_EQ(p.source, fem::BarProperty::Source::PBEAM);
  EXPECT_DOUBLE_EQ(p.A, 2.0);
  EXPECT_DOUBLE_EQ(p.I1, 3.0);
  EXPECT_DOUBLE_EQ(p.I2, 4.0);
  EXPECT_DOUBLE_EQ(p.I12, 0.5);
  EXPECT_DOUBLE_EQ(p.J, 6.0);
  EXPECT_DOUBLE_EQ(p.nsm, 0.7);
  EXPECT_DOUBLE_EQ(p.K1, 1.0);
  EXPECT_DOUBLE_EQ(p.K2, 1.0);
  const fem::BarProperty& q = m.bar_props[1];
  EXPECT_DOUBLE_EQ(q.A, 2.0);  // end A, not the station's 1.0
  EXPECT_DOUBLE_EQ(q.K1, 0.5);
  EXPECT_DOUBLE_EQ(q.K2, 0.6);
  // the taper: end A and end B (X/XB = 1, A = 1; blank I12 and NSM are end A's), none unsupported
  EXPECT_TRUE(p.stations.empty());
  ASSERT_EQ(q.stations.size(), 2u);
  EXPECT_EQ(q.stations[0].x, 0.0);
  EXPECT_EQ(q.stations[0].A, 2.0);
  EXPECT_EQ(q.stations[1].x, 1.0);
  EXPECT_EQ(q.stations[1].A, 1.0);
  EXPECT_EQ(q.stations[1].I1, 3.0);
  EXPECT_EQ(q.stations[1].I2, 4.0);
  EXPECT_EQ(q.stations[1].I12, 0.0);
  EXPECT_EQ(q.stations[1].J, 6.0);
  EXPECT_TRUE(m.unsupported.empty());
  EXPECT_TRUE(m.bars[0].is_beam);
  EXPECT_EQ(m.bars[0].pid, 50);
  EXPECT_EQ(m.bars[0].v, Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(m.bars[1].pid, 51);
}

TEST(NastranCards, PbarContinuationsAndPbarlSection) {
  const fem::Model m = read_deck(base_deck() +
                                 "PBAR,11,1,.1,.2,.3,.4,.05\n,1.,1.,-1.,1.,-1.,-1.,1.,-1.\n,.85,.75,.01\n"
                                 "PBARL,12,1,,BAR\n,.2,.1,.3\n");
  const fem::BarProperty& p = m.bar_props[0];
  EXPECT_DOUBLE_EQ(p.A, .1);
  EXPECT_DOUBLE_EQ(p.I1, .2);
  EXPECT_DOUBLE_EQ(p.I2, .3);
  EXPECT_DOUBLE_EQ(p.J, .4);
  EXPECT_DOUBLE_EQ(p.nsm, .05);
  EXPECT_DOUBLE_EQ(p.K1, .85);
  EXPECT_DOUBLE_EQ(p.K2, .75);
  EXPECT_DOUBLE_EQ(p.I12, .01);
  const fem::BarProperty& l = m.bar_props[1];
  EXPECT_EQ(l.source, fem::BarProperty::Source::PBARL);
  EXPECT_EQ(l.section_type, "BAR");
  ASSERT_EQ(l.dims.size(), 2u);
  // BAR width b = DIM1 = .2 (z), height h = DIM2 = .1 (y): A = b h, I1 = b h^3/12, I2 = h b^3/12
  EXPECT_DOUBLE_EQ(l.A, .2 * .1);
  EXPECT_DOUBLE_EQ(l.I1, .2 * .1 * .1 * .1 / 12);
  EXPECT_DOUBLE_EQ(l.I2, .1 * .2 * .2 * .2 / 12);
  EXPECT_DOUBLE_EQ(l.nsm, .3);
}

TEST(NastranCards, ShellsAndPshellDefaults) {
  const fem::Model m = read_deck(base_deck() +
                                 "PSHELL,2,1,.01\n"                     // membrane only: MID2 blank
                                 "PSHELL,3,1,.02,1,,1,,.5\n,-.005,.004\n"  // Z1, Z2 given
                                 "CTRIA3,7,2,1,2,3,5\n,,,1,.5,.6,.7\n"   // MCID 5 (integer), TFLAG 1
                                 "CORD2R,5,,0.,0.,0.,0.,0.,1.\n,1.,0.,0.\n"
                                 "PSHELL,8,1,.01\nCQUAD4,8,,1,2,3,4,15.,.001\n");  // PID blank = EID
  // PSHELL 1 of base_deck: T = .002, MID2 = 1, everything else blank
  const fem::ShellProperty& p1 = m.shell_props[0];
  EXPECT_DOUBLE_EQ(p1.bend_ratio, 1.0);
  EXPECT_DOUBLE_EQ(p1.ts_t, 0.833333);
  EXPECT_EQ(p1.mid3, 0);
  EXPECT_DOUBLE_EQ(p1.z1, -.001);
  EXPECT_DOUBLE_EQ(p1.z2, .001);
  EXPECT_EQ(m.shell_props[1].mid2, 0);
  EXPECT_DOUBLE_EQ(m.shell_props[2].nsm, .5);
  EXPECT_DOUBLE_EQ(m.shell_props[2].z1, -.005);
  const fem::Shell& t = m.shells[0];
  EXPECT_EQ(t.nnode, 3);
  EXPECT_TRUE(t.theta_is_mcid);
  EXPECT_EQ(t.mcid, 5);
  EXPECT_EQ(t.tflag, 1);
  EXPECT_DOUBLE_EQ(t.t[2], .7);
  EXPECT_EQ(t.g[3], 0);
  const fem::Shell& q = m.shells[1];
  EXPECT_EQ(q.pid, 8);
  EXPECT_FALSE(q.theta_is_mcid);
  EXPECT_DOUBLE_EQ(q.theta_deg, 15.0);
  EXPECT_DOUBLE_EQ(q.zoffs, .001);
}

TEST(NastranCards, CompositeCardsMat8Mat2AndPshellMid4) {
  // PCOMP in small fixed format with a continuation, blank MID/T taken from the ply before (QRG
  // PCOMP remark 1), an empty ply slot skipped; PCOMPG in large field (one ply per logical line);
  // MAT8 with its continuation; MAT2; PSHELL with MID4.
  const std::string deck =
      base_deck() +
      fixed_line({"MAT8", "8", "181.+9", "10.3+9", ".28", "7.17+9", "5.+9", "", "1600."}, 8, "+M8") +
      fixed_line({"+M8", "2.-8", "3.-5", "25.", "1.5+9"}, 8, "+M9") + fixed_line({"+M9", ".01"}) +
      "MAT2,9,1.+9,2.+8,0.,1.1+9,0.,3.+8,900.,+A\n+A,1.-5,2.-5,3.-6,15.\n" +
      fixed_line({"PCOMP", "10", "-.001", ".5", "", "HILL", "", "", "SYM"}, 8, "+P1") +
      fixed_line({"+P1", "8", ".000125", "0.", "YES", "", "", "45.", ""}, 8, "+P2") +
      fixed_line({"+P2", "", "", "", "", "9", ".0002", "-45."}) +
      fixed_line({"PCOMPG*", "11", "", "", ""}, 16, "*G1") + fixed_line({"*G1", "", "", "", "MEM"}, 16, "*G2") +
      fixed_line({"*G2", "101", "8", ".001", "30."}, 16, "*G3") + fixed_line({"*G3", "NO", "", "", ""}, 16, "*G4") +
      fixed_line({"*G4", "102", "", "", "-30."}, 16) +
      "PSHELL,12,1,.002,1,,1,,,+S\n+S,,,9\n"
      "CQUAD4,20,10,1,2,3,4,0\n"
      "CTRIA3,21,11,1,2,3,15.\n"
      "CQUAD4,22,12,1,2,3,4\n";
  const fem::Model m = read_deck(deck);
  ASSERT_EQ(m.mat8.size(), 1u);
  const fem::Mat8& m8 = m.mat8[0];
  EXPECT_EQ(m8.id, 8);
  EXPECT_DOUBLE_EQ(m8.E1, 181e9);
  EXPECT_DOUBLE_EQ(m8.nu12, .28);
  EXPECT_DOUBLE_EQ(m8.G1z, 5e9);
  EXPECT_EQ(m8.G2z, 0.0);  // blank: rigid in transverse shear
  EXPECT_DOUBLE_EQ(m8.rho, 1600.);
  EXPECT_DOUBLE_EQ(m8.ge, .01);
  ASSERT_EQ(m.mat2.size(), 1u);
  EXPECT_DOUBLE_EQ(m.mat2[0].G22, 1.1e9);
  EXPECT_DOUBLE_EQ(m.mat2[0].G33, 3e8);
  EXPECT_DOUBLE_EQ(m.mat2[0].rho, 900.);
  // thermal expansion and its reference temperature (thermal loads of shells)
  EXPECT_DOUBLE_EQ(m8.a1, 2e-8);
  EXPECT_DOUBLE_EQ(m8.a2, 3e-5);
  EXPECT_DOUBLE_EQ(m8.tref, 25.);
  EXPECT_DOUBLE_EQ(m.mat2[0].a1, 1e-5);
  EXPECT_DOUBLE_EQ(m.mat2[0].a2, 2e-5);
  EXPECT_DOUBLE_EQ(m.mat2[0].a3, 3e-6);
  EXPECT_DOUBLE_EQ(m.mat2[0].tref, 15.);
  ASSERT_EQ(m.composite_props.size(), 2u);
  const fem::CompositeProperty& pc = m.composite_props[0];
  EXPECT_FALSE(pc.global);
  EXPECT_TRUE(pc.has_z0);
  EXPECT_DOUBLE_EQ(pc.z0, -.001);
  EXPECT_DOUBLE_EQ(pc.nsm, .5);
  EXPECT_EQ(pc.ft, "HILL");
  EXPECT_EQ(pc.lam, fem::CompositeProperty::Lam::Sym);
  ASSERT_EQ(pc.plies.size(), 3u);  // the all-blank slot is no ply
  EXPECT_EQ(pc.plies[1].mid, 8);    // blank MID2 and T2: ply 1's
  EXPECT_DOUBLE_EQ(pc.plies[1].t, .000125);
  EXPECT_DOUBLE_EQ(pc.plies[1].theta_deg, 45.);
  EXPECT_TRUE(pc.plies[0].sout);
  EXPECT_EQ(pc.plies[2].mid, 9);
  EXPECT_DOUBLE_EQ(pc.plies[2].theta_deg, -45.);
  const fem::CompositeProperty& pg = m.composite_props[1];
  EXPECT_TRUE(pg.global);
  EXPECT_FALSE(pg.has_z0);
  EXPECT_EQ(pg.lam, fem::CompositeProperty::Lam::Mem);
  ASSERT_EQ(pg.plies.size(), 2u);
  EXPECT_EQ(pg.plies[0].gplyid, 101);
  EXPECT_EQ(pg.plies[1].gplyid, 102);
  EXPECT_EQ(pg.plies[1].mid, 8);
  EXPECT_DOUBLE_EQ(pg.plies[1].t, .001);
  EXPECT_DOUBLE_EQ(pg.plies[1].theta_deg, -30.);
  EXPECT_EQ(m.shell_props[1].mid4, 9);
  // all of it is used; the one note says that the MAT2 ply is rigid in transverse shear
  ASSERT_EQ(m.unsupported.size(), 1u);
  EXPECT_EQ(m.unsupported[0].name.rfind("PCOMP ply of MAT2", 0), 0u) << m.unsupported[0].name;
  EXPECT_TRUE(m.shells[0].theta_is_mcid);
  EXPECT_EQ(m.shells[0].mcid, 0);
}

TEST(NastranCards, ShellPidDefaultMustExist) {
  EXPECT_TRUE(mentions(test::read_error(base_deck() + "CQUAD4,8,,1,2,3,4\n"), {"CQUAD4 8, field 3 (PID): references property 8"}));
}

TEST(NastranCards, Mat1WithTwoBlankConstantsSetsBothToZero) {
  // QRG MAT1 remark 4: if E and NU, or G and NU, are both blank, both are 0 (an E-only truss material).
  const fem::Model m = read_deck("MAT1,1,7.1+10\nMAT1,2,,2.7+10\n");
  EXPECT_DOUBLE_EQ(m.mat1[0].E, 7.1e10);
  EXPECT_EQ(m.mat1[0].G, 0.0);
  EXPECT_EQ(m.mat1[0].nu, 0.0);
  EXPECT_EQ(m.mat1[1].E, 0.0);
  EXPECT_DOUBLE_EQ(m.mat1[1].G, 2.7e10);
  EXPECT_EQ(m.mat1[1].nu, 0.0);
}

TEST(NastranCards, Mat1CompletesTheBlankConstant) {
  // QRG MAT1 remarks: G = E / (2 (1 + NU)); NU = E / (2 G) - 1; E = 2 (1 + NU) G.
  const fem::Model m = read_deck("MAT1,1,2.6,,.3\nMAT1,2,2.6,1.,\nMAT1,3,,1.,.3,7.8,1.2-5,20.,.02\nMAT1,4,1.,2.,3.-1\n");
  EXPECT_DOUBLE_EQ(m.mat1[0].G, 1.0);
  EXPECT_DOUBLE_EQ(m.mat1[1].nu, 0.3);
  EXPECT_DOUBLE_EQ(m.mat1[2].E, 2.6);
  EXPECT_DOUBLE_EQ(m.mat1[2].rho, 7.8);
  EXPECT_DOUBLE_EQ(m.mat1[2].alpha, 1.2e-5);
  EXPECT_DOUBLE_EQ(m.mat1[2].tref, 20.0);
  EXPECT_DOUBLE_EQ(m.mat1[2].ge, .02);
  // all three given: kept as written (Nastran only warns when they disagree)
  EXPECT_DOUBLE_EQ(m.mat1[3].E, 1.0);
  EXPECT_DOUBLE_EQ(m.mat1[3].G, 2.0);
  EXPECT_DOUBLE_EQ(m.mat1[3].nu, 0.3);
}

TEST(NastranCards, Conm2AllForms) {
  const fem::Model m = read_deck(base_deck() +
                                 "CORD2R,9,,0.,0.,0.,0.,0.,1.\n,1.,0.,0.\n"
                                 "CONM2,1,1,,2.5\n"
                                 "CONM2,2,2,-1,3.,4.,5.,6.\n,1.,.1,2.,.2,.3,3.\n"
                                 "CONM2,3,3,9,1.,.5\n");
  ASSERT_EQ(m.conm2.size(), 3u);
  EXPECT_EQ(m.conm2[0].cid, 0);
  EXPECT_DOUBLE_EQ(m.conm2[0].m, 2.5);
  const fem::Conm2& c = m.conm2[1];
  EXPECT_EQ(c.cid, -1);
  EXPECT_EQ(c.x, Eigen::Vector3d(4, 5, 6));
  EXPECT_DOUBLE_EQ(c.I11, 1.);
  EXPECT_DOUBLE_EQ(c.I21, .1);
  EXPECT_DOUBLE_EQ(c.I22, 2.);
  EXPECT_DOUBLE_EQ(c.I31, .2);
  EXPECT_DOUBLE_EQ(c.I32, .3);
  EXPECT_DOUBLE_EQ(c.I33, 3.);
  EXPECT_EQ(m.conm2[2].cid, 9);
}

TEST(NastranCards, SpringsRodsAndRigidElements) {
  const fem::Model m = read_deck(base_deck() +
                                 "SPOINT,100\n"
                                 "PELAS,10,1.5+4,.02,.75,11,2.5+4\n"
                                 "CELAS1,20,10,1,3,2,3\nCELAS1,21,11,100,,,\nCELAS2,22,7.,3,6,100,0,.01,.5\n"
                                 "PROD,30,1,2.,.5,.1,.2\nCROD,31,30,1,3\nCONROD,32,2,4,1,3.,,,.4\n"
                                 "RBE2,40,1,123456,2,THRU,4,1.2-5\n");
  ASSERT_EQ(m.spring_props.size(), 2u);
  EXPECT_DOUBLE_EQ(m.spring_props[0].k, 1.5e4);
  EXPECT_DOUBLE_EQ(m.spring_props[0].s, .75);
  EXPECT_EQ(m.spring_props[1].id, 11);
  EXPECT_DOUBLE_EQ(m.spring_props[1].k, 2.5e4);
  ASSERT_EQ(m.springs.size(), 3u);
  EXPECT_EQ(m.springs[0].c2, 3);
  EXPECT_EQ(m.springs[1].g1, 100);
  EXPECT_EQ(m.springs[1].g2, 0);  // grounded
  EXPECT_TRUE(m.springs[2].inline_property);
  EXPECT_DOUBLE_EQ(m.springs[2].k, 7.);
  EXPECT_EQ(m.springs[2].c1, 6);
  EXPECT_DOUBLE_EQ(m.springs[2].ge, .01);
  EXPECT_DOUBLE_EQ(m.rod_props[0].C, .1);
  EXPECT_EQ(m.rods[0].pid, 30);
  EXPECT_TRUE(m.rods[1].inline_property);
  EXPECT_EQ(m.rods[1].mid, 1);
  EXPECT_DOUBLE_EQ(m.rods[1].A, 3.);
  EXPECT_DOUBLE_EQ(m.rods[1].nsm, .4);
  ASSERT_EQ(m.rbe2.size(), 1u);
  EXPECT_EQ(m.rbe2[0].gm, (std::vector<int>{2, 3, 4}));
  EXPECT_EQ(fem::component_string(m.rbe2[0].cm), "123456");
}

TEST(NastranCards, ConstraintsLoadsAndSets) {
  const fem::Model m = read_deck(base_deck() +
                                 "SPC,1,1,123,.5,2,3\nSPC1,2,456,3\nSPCADD,3,1,2\n"
                                 "FORCE,10,2,,100.,1.,0.,0.\nMOMENT,11,3,,5.,0.,0.,1.\nLOAD,12,2.,1.5,10,-1.,11\n"
                                 "ASET,1,123,2,456\nBSET,3,1\nSUPORT,4,123456\n");
  ASSERT_EQ(m.spcs.size(), 3u);
  EXPECT_DOUBLE_EQ(m.spcs[0].d, .5);
  EXPECT_EQ(m.spcs[1].grid, 2);
  EXPECT_EQ(fem::component_string(m.spcs[1].c), "3");
  EXPECT_EQ(m.spcadds[0].sets, (std::vector<int>{1, 2}));
  ASSERT_EQ(m.point_loads.size(), 2u);
  EXPECT_EQ(m.point_loads[1].kind, fem::PointLoad::Kind::Moment);
  EXPECT_DOUBLE_EQ(m.point_loads[0].scale, 100.);
  ASSERT_EQ(m.load_combinations.size(), 1u);
  EXPECT_DOUBLE_EQ(m.load_combinations[0].s, 2.);
  ASSERT_EQ(m.load_combinations[0].terms.size(), 2u);
  EXPECT_DOUBLE_EQ(m.load_combinations[0].terms[1].first, -1.);
  EXPECT_EQ(m.load_combinations[0].terms[1].second, 11);
  EXPECT_EQ(m.aset.size(), 2u);
  EXPECT_EQ(fem::component_string(m.aset[1].c), "456");
  EXPECT_EQ(m.bset.size(), 1u);
  EXPECT_EQ(m.suport[0].c, 0b111111);
}

// RBAR, RBE3 (groups, UM, ALPHA), MPC (scalar point term, continuation), MPCADD, OMIT, OMIT1;
// SPC1 THRU marks its ids; a line with only '&' is listed, not a card; case-control selections seflex
// does not use are kept per subcase (global ones inherited).
TEST(NastranCards, MultipointConstraintsAndOmitSets) {
  const fem::Model m = read_deck("SOL 101\nCEND\nTEMP(INIT) = 5\nSUBCASE 1\nDLOAD = 7\nSUBCASE 2\nTEMPERATURE(LOAD) = 6\n"
                                 "BEGIN BULK\n" + base_deck() +
                                 "SPOINT,100\nGRID,9,,5.,5.,5.\n"
                                 "RBAR,50,1,2,123,456\nRBAR,51,1,3,123456,,,12\n"
                                 "RBE3,52,,9,1236,1.5,123,1,2,+R\n+R,3,.5,456,4,UM,1,12,4\n,6,ALPHA,2.-5\n"
                                 "MPC,7,1,3,2.,2,1,-1.5\n,,100,,4.\nMPCADD,8,7\n"
                                 "OMIT,1,456\nOMIT1,3,2,THRU,4\nSPC1,3,123,1,2,THRU,40\n&\n");
  ASSERT_EQ(m.rbars.size(), 2u);
  EXPECT_EQ(fem::component_string(m.rbars[0].cma), "456");  // blank CMA, CMB: the complements
  EXPECT_EQ(fem::component_string(m.rbars[0].cmb), "123");
  EXPECT_EQ(fem::component_string(m.rbars[1].cmb), "12");
  EXPECT_EQ(m.rbars[1].cma, 0);
  ASSERT_EQ(m.rbe3.size(), 1u);
  const fem::Rbe3& r = m.rbe3[0];
  EXPECT_EQ(r.refgrid, 9);
  EXPECT_EQ(fem::component_string(r.refc), "1236");
  ASSERT_EQ(r.groups.size(), 2u);
  EXPECT_DOUBLE_EQ(r.groups[0].weight, 1.5);
  EXPECT_EQ(r.groups[0].grids, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(fem::component_string(r.groups[1].c), "456");
  EXPECT_EQ(r.groups[1].grids, std::vector<int>{4});
  ASSERT_EQ(r.um.size(), 2u);
  EXPECT_EQ(r.um[0].grid, 1);
  EXPECT_EQ(fem::component_string(r.um[0].c), "12");
  EXPECT_EQ(r.um[1].grid, 4);
  EXPECT_EQ(fem::component_string(r.um[1].c), "6");
  EXPECT_DOUBLE_EQ(r.alpha, 2e-5);
  ASSERT_EQ(m.mpcs.size(), 1u);
  ASSERT_EQ(m.mpcs[0].terms.size(), 3u);
  EXPECT_EQ(m.mpcs[0].terms[2].grid, 100);
  EXPECT_EQ(m.mpcs[0].terms[2].component, 0);
  EXPECT_DOUBLE_EQ(m.mpcs[0].terms[1].a, -1.5);
  EXPECT_EQ(m.mpcadds[0].sets, std::vector<int>{7});
  EXPECT_EQ(m.omit.size(), 4u);
  std::size_t thru = 0;
  for (const auto& e : m.spcs) thru += e.from_thru;
  EXPECT_EQ(m.spcs.size(), 40u);
  EXPECT_EQ(thru, 39u);  // 2 THRU 40; grid 1 listed on its own
  ASSERT_FALSE(m.unsupported.empty());
  EXPECT_EQ(m.unsupported.back().name, "'&'");
  const auto& cc = m.case_control;
  ASSERT_EQ(cc.subcases.size(), 2u);
  ASSERT_EQ(cc.subcases[0].other.size(), 2u);  // DLOAD, and TEMPERATURE(INIT) inherited
  EXPECT_EQ(cc.subcases[0].other[0].name, "DLOAD");
  EXPECT_EQ(cc.subcases[0].other[1].name, "TEMPERATURE(INIT)");
  // TEMPERATURE(LOAD) is the thermal load set; TEMP(INIT) is kept among the unused selections
  EXPECT_EQ(cc.subcases[1].temperature.value_or(0), 6);
  ASSERT_EQ(cc.subcases[1].other.size(), 1u);
  EXPECT_EQ(cc.subcases[1].other[0].name, "TEMPERATURE(INIT)");
  EXPECT_FALSE(cc.subcases[0].temperature.has_value());
  EXPECT_EQ(cc.subcases[1].ref.line, 6u);
}

// PLOAD2 (list, continued, THRU), GRAV, RFORCE (continuation RACC), TEMP, TEMPD, TEMPRB (with the
// element list of its third line); TEMPERATURE, TEMP(BOTH) and TEMP = n select the thermal set.
TEST(NastranCards, PressureInertiaAndThermalLoads) {
  const fem::Model m = read_deck(
      "SOL 101\nCEND\nTEMP = 3\nSUBCASE 1\nTEMPERATURE(BOTH) = 4\nSUBCASE 2\n"
      "BEGIN BULK\n" +
      base_deck() +
      "PLOAD2,1,-2.5,1,2,3,4,5,6\n,7\nPLOAD2,2,3.,10,THRU,20\n"
      "GRAV,5,3,9.81,0.,0.,-1.,-1\nRFORCE,6,4,2,10.,0.,1.,0.,2,+R\n+R,0.5,0\n"
      "TEMP,3,1,20.,2,30.,4,50.\nTEMPD,3,10.,4,-5.\n"
      "TEMPRB,3,8,1.,2.,3.,4.,5.,6.\n,,,,,,,,\n,9,11,THRU,13\n");
  ASSERT_EQ(m.pressure_loads.size(), 2u);
  EXPECT_EQ(m.pressure_loads[0].elements, (std::vector<int>{1, 2, 3, 4, 5, 6, 7}));
  EXPECT_DOUBLE_EQ(m.pressure_loads[0].p, -2.5);
  EXPECT_TRUE(m.pressure_loads[1].thru);
  EXPECT_EQ(m.pressure_loads[1].elements, (std::vector<int>{10, 20}));
  ASSERT_EQ(m.gravity_loads.size(), 1u);
  EXPECT_EQ(m.gravity_loads[0].cid, 3);
  EXPECT_EQ(m.gravity_loads[0].n, Eigen::Vector3d(0, 0, -1));
  ASSERT_EQ(m.rotational_loads.size(), 1u);
  const fem::RotationalLoad& r = m.rotational_loads[0];
  EXPECT_EQ(r.grid, 4);
  EXPECT_EQ(r.cid, 2);
  EXPECT_DOUBLE_EQ(r.a, 10.0);
  EXPECT_EQ(r.method, 2);
  EXPECT_DOUBLE_EQ(r.racc, 0.5);
  ASSERT_EQ(m.grid_temperatures.size(), 3u);
  EXPECT_EQ(m.grid_temperatures[2].grid, 4);
  EXPECT_DOUBLE_EQ(m.grid_temperatures[2].t, 50.0);
  ASSERT_EQ(m.default_temperatures.size(), 2u);
  EXPECT_EQ(m.default_temperatures[1].sid, 4);
  EXPECT_DOUBLE_EQ(m.default_temperatures[1].t, -5.0);
  ASSERT_EQ(m.bar_temperatures.size(), 5u);  // 8, then 9, 11, 12, 13
  EXPECT_EQ(m.bar_temperatures[4].element, 13);
  EXPECT_DOUBLE_EQ(m.bar_temperatures[4].tp2b, 6.0);
  // RFORCE METHOD 2 is read with the stated approximation
  bool noted = false;
  for (const auto& u : m.unsupported) noted = noted || u.name.rfind("RFORCE METHOD 2", 0) == 0;
  EXPECT_TRUE(noted);
  const auto& cc = m.case_control;
  EXPECT_EQ(cc.global.temperature.value_or(0), 3);
  EXPECT_EQ(cc.subcases[0].temperature.value_or(0), 4);
  EXPECT_EQ(cc.subcases[1].temperature.value_or(0), 3);  // inherited
  // seflex convert writes them back: the same cards read again
  std::ostringstream out;
  io::write_nastran(m, out);
  const fem::Model w = read_deck(out.str());
  ASSERT_EQ(w.pressure_loads.size(), 2u);
  EXPECT_EQ(w.pressure_loads[0].elements, m.pressure_loads[0].elements);
  EXPECT_EQ(w.pressure_loads[1].elements, m.pressure_loads[1].elements);
  EXPECT_TRUE(w.pressure_loads[1].thru);
  ASSERT_EQ(w.gravity_loads.size(), 1u);
  EXPECT_EQ(w.gravity_loads[0].n, m.gravity_loads[0].n);
  ASSERT_EQ(w.rotational_loads.size(), 1u);
  EXPECT_DOUBLE_EQ(w.rotational_loads[0].racc, 0.5);
  EXPECT_EQ(w.rotational_loads[0].method, 2);
  EXPECT_EQ(w.grid_temperatures.size(), 3u);
  EXPECT_EQ(w.default_temperatures.size(), 2u);
  ASSERT_EQ(w.bar_temperatures.size(), 5u);
  EXPECT_DOUBLE_EQ(w.bar_temperatures[4].tp2b, 6.0);
  EXPECT_EQ(w.case_control.subcases[0].temperature.value_or(0), 4);
}

TEST(NastranCards, EigenMethodsParamsAndDmig) {
  const fem::Model m = read_deck(base_deck() +
                                 "EIGRL,1,.1,100.,6,,,,MAX\n"
                                 "EIGR,2,MGIV,,,1,24\n,POINT,3,2\n"
                                 "PARAM,WTMASS,2.591-3\nPARAM,GRDPNT,3\nPARAM,COUPMASS,1\nPARAM,AUTOSPC,yes\n"
                                 "SPOINT,101\n"
                                 "DMIG*   KXX             0               6               2\n"
                                 "DMIG*   KXX             1               1\n"
                                 "*       1               1               1.5D+3\n"
                                 "*       101             0               -2.0D-1\n");
  ASSERT_EQ(m.eigen_methods.size(), 2u);
  const auto& l = m.eigen_methods[0];
  EXPECT_FALSE(l.is_eigr);
  EXPECT_DOUBLE_EQ(l.f1.value_or(0), .1);
  EXPECT_DOUBLE_EQ(l.f2.value_or(0), 100.);
  EXPECT_EQ(l.nd.value_or(0), 6);
  EXPECT_EQ(l.norm, "MAX");
  const auto& r = m.eigen_methods[1];
  EXPECT_TRUE(r.is_eigr);
  EXPECT_EQ(r.method, "MGIV");
  EXPECT_FALSE(r.f1.has_value());
  EXPECT_EQ(r.nd.value_or(0), 24);
  EXPECT_EQ(r.norm, "POINT");
  EXPECT_EQ(r.norm_grid, 3);
  EXPECT_EQ(r.norm_component, 2);
  EXPECT_DOUBLE_EQ(fem::param_number(m, "WTMASS", 1.), 2.591e-3);
  EXPECT_DOUBLE_EQ(fem::param_number(m, "GRDPNT", -1.), 3.);
  EXPECT_DOUBLE_EQ(fem::param_number(m, "K6ROT", 100.), 100.);  // absent: the fallback
  EXPECT_EQ(m.params.back().values.at(0), "YES");
  ASSERT_EQ(m.dmigs.size(), 1u);
  const fem::Dmig& d = m.dmigs[0];
  EXPECT_EQ(d.name, "KXX");
  EXPECT_EQ(d.tin, 2);
  ASSERT_EQ(d.entries.size(), 2u);
  EXPECT_DOUBLE_EQ(d.entries[0].value, 1500.);
  EXPECT_EQ(d.entries[1].gi, 101);
  EXPECT_EQ(d.entries[1].ci, 0);
  EXPECT_DOUBLE_EQ(d.entries[1].value, -0.2);
}
