// CBUSH1D / PBUSH1D, the rod-type spring (QRG CBUSH1D, PBUSH1D): stiffness K along the element axis
// only (GA -> GB, or x of CID), damping C read and noted (statics and real modes ignore it, QRG
// PBUSH1D remark 2), mass M lumped half on each grid's translations. Checked against closed forms:
// the 12 x 12 stiffness k [n n^T, -n n^T; -n n^T, n n^T] on the translations of a skew element,
// the static stretch F/K, the frequency sqrt(K / (m + M/2)) of a mass on the spring, the total mass
// and its centre; the writer and back; refusals by their message. Also TABLEM1-4, the material
// tables: read, checked, written back, used by no solution.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <sstream>
#include <string>

#include "nastran_test_util.hpp"
#include "statics_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/mass_properties.hpp"
#include "seflex/io/nastran_writer.hpp"
#include "seflex/solutions/normal_modes.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

using test::num;

fem::Model round_trip(const fem::Model& m) {
  std::ostringstream out;
  io::write_nastran(m, out);
  return test::read_deck(out.str(), "converted.bdf");
}

Eigen::MatrixXd dense_K(const fem::Model& m) { return Eigen::MatrixXd(fem::assemble(m, fem::assembly_options(m)).K); }

// A spring from grid 1 at the origin to grid 2 at (1, 2, 2): axis n = (1, 2, 2)/3. K is
// k n n^T, -k n n^T on the translations of the two grids and nothing on their rotations.
TEST(Cbush1d, StiffnessOfASkewElementIsTheAxialSpring) {
  const double k = 5.0e4;
  const fem::Model m = test::read_deck("GRID,1,,0.,0.,0.\nGRID,2,,1.,2.,2.\nCBUSH1D,7,70,1,2\nPBUSH1D,70," + num(k) + "\n");
  const Eigen::Vector3d n(1.0 / 3, 2.0 / 3, 2.0 / 3);
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(12, 12);
  const Eigen::Matrix3d knn = k * n * n.transpose();
  expected.block<3, 3>(0, 0) = knn;
  expected.block<3, 3>(6, 6) = knn;
  expected.block<3, 3>(0, 6) = -knn;
  expected.block<3, 3>(6, 0) = -knn;
  EXPECT_LT((dense_K(m) - expected).norm(), 1e-14 * k);  // measured 0
  EXPECT_LT((dense_K(round_trip(m)) - expected).norm(), 1e-14 * k);
  ASSERT_EQ(m.bushes.size(), 1u);
  EXPECT_STREQ(fem::bush_card(m.bushes[0]), "CBUSH1D");
}

// Coincident grids: the axis is x of CID (QRG CBUSH1D remark 5); a rectangular system whose x is the
// basic y axis puts K on the y translations only. Grounded (GB blank): k on GA's y translation.
TEST(Cbush1d, AxisFromCidForCoincidentAndGroundedElements) {
  const double k = 300.0;
  const std::string cord = "CORD2R,4,,0.,0.,0.,0.,0.,1.\n,0.,1.,0.\n";  // z basic z, x along basic +y
  const fem::Model m = test::read_deck(cord + "GRID,1,,0.,0.,0.\nGRID,2,,0.,0.,0.\nCBUSH1D,7,70,1,2,4\nPBUSH1D,70,300.\n");
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(12, 12);
  expected(1, 1) = expected(7, 7) = k;
  expected(1, 7) = expected(7, 1) = -k;
  EXPECT_LT((dense_K(m) - expected).norm(), 1e-13 * k);  // measured 0
  const fem::Model g = test::read_deck(cord + "GRID,1,,0.,0.,0.\nCBUSH1D,7,70,1,,4\nPBUSH1D,70,300.\n");
  Eigen::MatrixXd expected_g = Eigen::MatrixXd::Zero(6, 6);
  expected_g(1, 1) = k;
  EXPECT_LT((dense_K(g) - expected_g).norm(), 1e-13 * k);
}

// Grid 1 held, grid 2 free along the axis only (its CD system has x along the axis, SPC 23456):
// statics stretch F/K; normal modes sqrt(K / (m + M/2)) with a CONM2 m at grid 2 and the element's
// mass M lumped half at each end.
TEST(Cbush1d, StretchAndFrequencyAgainstClosedForms) {
  const double k = 2.0e5, M = 3.0, mc = 1.5, F = 700.0;
  const std::string bulk = "CORD2R,5,,0.,0.,0.,2.,-2.,1.\n,1.,2.,2.\n"  // z (2, -2, 1)/3, x along (1, 2, 2)/3
                           "GRID,1,,0.,0.,0.\nGRID,2,,1.,2.,2.,5\nCBUSH1D,7,70,1,2\nPBUSH1D,70," +
                           num(k) + ",," + num(M) + "\nCONM2,9,2,," + num(mc) + "\nSPC1,1,123456,1\nSPC1,1,23456,2\n";
  const fem::Model s = test::read_deck("SOL 101\nCEND\nSPC = 1\nLOAD = 2\nBEGIN BULK\n" + bulk + "FORCE,2,2,5," + num(F) + ",1.,0.,0.\nENDDATA\n");
  const auto st = solutions::solve_static(s);
  EXPECT_NEAR(test::displacement(s, st, 2, 1), F / k, 1e-14 * F / k);  // measured 1.2e-16 relative
  const fem::Model f = test::read_deck("SOL 103\nCEND\nSPC = 1\nMETHOD = 1\nBEGIN BULK\n" + bulk + "EIGRL,1,,,1\nENDDATA\n");
  const auto modes = solutions::solve_normal_modes(f);
  ASSERT_EQ(modes.eigenvalues.size(), 1);
  const double w2 = k / (mc + M / 2);
  EXPECT_NEAR(modes.eigenvalues[0], w2, 1e-13 * w2);  // measured 6.5e-16 relative
  const auto back = solutions::solve_normal_modes(round_trip(f));
  ASSERT_EQ(back.eigenvalues.size(), 1);
  EXPECT_NEAR(back.eigenvalues[0], w2, 1e-13 * w2);
  // the element alone: mass M, its centre mid-way between the grids (CONM2 9 weighs in too)
  const fem::MassProperties mp = fem::mass_properties(f);
  EXPECT_NEAR(mp.mass, M + mc, 1e-14 * (M + mc));  // measured 0, the centre too
  const Eigen::Vector3d cg = (M / 2 * Eigen::Vector3d(0, 0, 0) + (M / 2 + mc) * Eigen::Vector3d(1, 2, 2)) / (M + mc);
  EXPECT_LT((mp.cg - cg).norm(), 1e-14);
}

// C is read, written back and noted (statics and real modes ignore damping); the nonlinear lines are
// noted (used by nonlinear solutions only: QRG PBUSH1D remark 3); SA, SE read and written back.
TEST(Cbush1d, DampingAndNonlinearLinesAreNoted) {
  const fem::Model m = test::read_deck("PBUSH1D,70,3000.,200.,300.,,0.5,0.25\n,SPRING,TABLE,43\n");
  ASSERT_EQ(m.bush_props.size(), 1u);
  const fem::BushProperty& p = m.bush_props[0];
  EXPECT_TRUE(p.one_d);
  EXPECT_EQ(p.k[0], 3000.0);
  EXPECT_EQ(p.b[0], 200.0);
  EXPECT_EQ(p.mass, 300.0);
  EXPECT_EQ(p.sa, 0.5);
  EXPECT_EQ(p.se, 0.25);
  ASSERT_EQ(m.unsupported.size(), 2u);
  EXPECT_EQ(m.unsupported[0].name, "PBUSH1D SPRING (nonlinear: linear solutions use K and C)");
  EXPECT_EQ(m.unsupported[1].name, "PBUSH1D C (viscous damping ignored: statics and real modes)");
  const fem::Model back = round_trip(m);
  EXPECT_EQ(back.bush_props[0].b[0], 200.0);
  EXPECT_EQ(back.bush_props[0].mass, 300.0);
  EXPECT_EQ(back.bush_props[0].se, 0.25);
}

TEST(Cbush1d, RefusalsNameCardFieldAndWhatWasExpected) {
  const std::string grids = "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\n";
  EXPECT_EQ(test::read_error("PBUSH1D,70\n"),
            "deck.bdf:1: PBUSH1D 70, field 3 (K): K and C blank; expected a stiffness K or a damping C (QRG PBUSH1D remark 1)");
  EXPECT_EQ(test::read_error("PBUSH1D,70,-1.\n"), "deck.bdf:1: PBUSH1D 70, field 3 (K): got real '-1.'; expected a stiffness >= 0");
  EXPECT_EQ(test::read_error("PBUSH1D,70,1.\n,DAMP,TABLE,43\n"),
            "deck.bdf:2: PBUSH1D 70, field 2 (keyword): got text 'DAMP'; expected SHOCKA, SPRING, DAMPER or GENER on a continuation line");
  EXPECT_EQ(test::read_error(grids + "CBUSH1D,7,70,1,2\nPBUSH,70,K,1.\n"),
            "deck.bdf:3: CBUSH1D 7, field 3 (PID): references property 70, a PBUSH card (deck.bdf:4); expected the id of a PBUSH1D card");
  EXPECT_EQ(test::read_error(grids + "CBUSH,7,70,1,2,,,,0\nPBUSH1D,70,1.\n"),
            "deck.bdf:3: CBUSH 7, field 3 (PID): references property 70, a PBUSH1D card (deck.bdf:4); expected the id of a PBUSH card");
  EXPECT_EQ(test::read_error(grids + "CBUSH1D,7,70,1,1\nPBUSH1D,70,1.\n"),
            "deck.bdf:3: CBUSH1D 7, field 5 (GB): GB is GA; expected a second grid or blank (grounded)");
  const fem::Model coincident = test::read_deck("GRID,1,,0.,0.,0.\nGRID,2,,0.,0.,0.\nCBUSH1D,7,70,1,2\nPBUSH1D,70,1.\n");
  EXPECT_TRUE(test::mentions(test::input_error([&] { dense_K(coincident); }),
                             {"deck.bdf:3", "CBUSH1D 7", "field 6 (CID)", "GA and GB coincide; expected a coordinate system"}));
}

// TABLEM1-4 (QRG): read, checked, kept and written back; used by no solution (a warning says so).
TEST(Tablem, ReadCheckedAndWrittenBack) {
  const fem::Model m = test::read_deck(
      "TABLEM1,42\n,0.,0.,5.,100.,SKIP,SKIP,30.,400.\n,ENDT\nTABLEM2,43,10.\n,0.,1.,5.,2.,ENDT\n"
      "TABLEM3,44,0.,0.1\n,30.,1.,5.,2.,ENDT\nTABLEM4,45,0.,0.1,0.,1.\n,1.,2.,3.,ENDT\n");
  ASSERT_EQ(m.material_tables.size(), 4u);
  EXPECT_EQ(m.material_tables[0].values, (std::vector<double>{0., 0., 5., 100., 30., 400.}));
  EXPECT_EQ(m.material_tables[1].x[0], 10.0);
  EXPECT_EQ(m.material_tables[2].x[1], 0.1);
  EXPECT_EQ(m.material_tables[3].values, (std::vector<double>{1., 2., 3.}));
  EXPECT_TRUE(m.unsupported.empty());
  ASSERT_FALSE(m.read_warnings.empty());
  EXPECT_EQ(m.read_warnings.back(),
            "deck.bdf:1: TABLEM1 42 and 3 more TABLEMi: read; seflex models no temperature-dependent material (MATTi), so no card uses them");
  const fem::Model back = round_trip(m);
  ASSERT_EQ(back.material_tables.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(back.material_tables[i].type, m.material_tables[i].type);
    EXPECT_EQ(back.material_tables[i].x, m.material_tables[i].x);
    EXPECT_EQ(back.material_tables[i].values, m.material_tables[i].values);
  }
  EXPECT_EQ(test::read_error("TABLEM1,42\n,0.,0.,5.,100.\n"), "deck.bdf:1: TABLEM1 42: has no ENDT; expected its table to end with ENDT");
  EXPECT_EQ(test::read_error("TABLEM3,44,0.,0.\n,0.,1.,ENDT\n"),
            "deck.bdf:1: TABLEM3 44, field 4 (X2): got real '0.'; expected a real other than 0 (it divides x)");
  EXPECT_EQ(test::read_error("TABLEM4,45,0.,1.,2.,1.\n,1.,ENDT\n"),
            "deck.bdf:1: TABLEM4 45, field 5 (X3): got real '2.' and X4 got real '1.'; expected X3 < X4 (the range of x)");
  EXPECT_TRUE(test::mentions(test::read_error("TABLEM1,42\n,0.,0.,5.,1.,2.,3.,ENDT\n"),
                             {"deck.bdf:1: TABLEM1 42", "change direction; expected x in ascending or descending order"}));
  EXPECT_TRUE(test::mentions(test::read_error("TABLEM1,42\n,0.,0.,ENDT\nTABLEM2,42,0.\n,0.,0.,ENDT\n"),
                             {"deck.bdf:3: TABLEM", "duplicate TABLEMi id, first defined at deck.bdf:1"}));
}

}  // namespace
}  // namespace seflex
