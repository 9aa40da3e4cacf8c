// CBUSH/PBUSH, CELAS3/CELAS4, CMASS1-4/PMASS and CONM1 read from decks, each against an independent
// reference: an equivalent CELAS2 model (CBUSH without offset), hand-derived statics (CBUSH with
// orientation vector and offset: the energy of the spring at P, minimised by hand below), closed-form
// eigenvalues of a two-dof spring-mass chain, and the rotation of a 6 x 6 mass matrix. Each also goes
// through `seflex convert`'s writer and back.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <sstream>
#include <string>

#include "nastran_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/io/nastran_writer.hpp"
#include "seflex/solutions/normal_modes.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

Eigen::MatrixXd dense_K(const fem::Model& m) { return Eigen::MatrixXd(fem::assemble(m, fem::assembly_options(m)).K); }
Eigen::MatrixXd dense_M(const fem::Model& m) { return Eigen::MatrixXd(fem::assemble(m, fem::assembly_options(m)).M); }

double u(const fem::Model& m, const solutions::StaticSolution& s, int g, int c) {
  return s.u_g[*fem::find_dof(m, s.dofs, g, c)];
}

/// Write the model with `seflex convert`'s writer and read it back.
fem::Model round_trip(const fem::Model& m) {
  std::ostringstream out;
  io::write_nastran(m, out);
  return test::read_deck(out.str(), "converted.bdf");
}

// ---------------------------------------------------------------------------------------------
// CBUSH between coincident grids, element axes = basic (CID 0): six uncoupled springs, the same K
// as six CELAS2 between the same components.
TEST(Cbush, CoincidentGridsEqualSixCelas2) {
  const std::string grids = "GRID,1,,1.,2.,3.\nGRID,2,,1.,2.,3.\n";
  const fem::Model bush = test::read_deck(grids + "CBUSH,7,70,1,2,,,,0\nPBUSH,70,K,1.e3,2.e3,3.e3,4.e3,5.e3,6.e3\n");
  std::string celas = grids;
  for (int c = 1; c <= 6; ++c) celas += "CELAS2," + std::to_string(10 + c) + "," + std::to_string(c) + ".e3,1," + std::to_string(c) + ",2," + std::to_string(c) + "\n";
  const fem::Model springs = test::read_deck(celas);
  const Eigen::MatrixXd Kb = dense_K(bush), Ks = dense_K(springs);
  EXPECT_LT((Kb - Ks).norm(), 1e-12 * Ks.norm()) << Kb;
  EXPECT_LT((dense_K(round_trip(bush)) - Ks).norm(), 1e-12 * Ks.norm());
}

// CBUSH GA = (0,0,0), GB = (L,0,0), X = (0,0,1): element x = basic x, z = x cross v = -y, y = z cross
// x = +z. GA clamped, force F along basic z at GB. The spring sits at P = GA + S (GB - GA); GB's
// motion at P: w_P = w_B + theta_yB (1 - S) L (theta x (P - B), P - B = (-(1 - S) L, 0, 0)); element
// rotation about its z (= -y): -theta_yB. Energy U = K2 w_P^2 / 2 + K6 theta_yB^2 / 2 - F w_B;
// dU/dw_B = 0: K2 w_P = F; dU/dtheta_yB = 0: K2 w_P (1 - S) L + K6 theta_yB = 0, so
//   theta_yB = -F (1 - S) L / K6,  w_B = F / K2 + F (1 - S)^2 L^2 / K6.
std::string bush_cantilever(const std::string& cbush) {
  return "SOL 101\nCEND\nSPC = 1\nLOAD = 2\nBEGIN BULK\n"
         "GRID,1,,0.,0.,0.\nGRID,2,,2.,0.,0.\nSPC1,1,123456,1\nFORCE,2,2,,100.,0.,0.,1.\n"
         "PBUSH,70,K,1.e5,2.e4,3.e5,4.e5,5.e5,6.e3\n" + cbush + "ENDDATA\n";
}

TEST(Cbush, OrientationAndOffsetAgainstHandCalculation) {
  const double L = 2.0, F = 100.0, K2 = 2e4, K6 = 6e3;
  for (const double S : {0.5, 0.25, 0.0}) {
    const std::string card = "CBUSH,7,70,1,2,0.,0.,1.,\n,";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4f", S);
    const fem::Model m = test::read_deck(bush_cantilever(card + buf + "\n"));
    const auto s = solutions::solve_static(m);
    const double w = F / K2 + F * (1 - S) * (1 - S) * L * L / K6;
    const double ty = -F * (1 - S) * L / K6;
    EXPECT_NEAR(u(m, s, 2, 3), w, 1e-12 * w) << "S = " << S;
    EXPECT_NEAR(u(m, s, 2, 5), ty, 1e-12 * std::abs(ty)) << "S = " << S;
    EXPECT_NEAR(u(m, s, 2, 1), 0.0, 1e-15);
    EXPECT_NEAR(u(m, s, 2, 2), 0.0, 1e-15);
    const fem::Model back = round_trip(m);
    EXPECT_NEAR(u(back, solutions::solve_static(back), 2, 3), w, 1e-12 * w);
  }
}

// The same spring point given as an offset: OCID = 0 (basic), S1-S3 = (0.5 L, 0, 0) from GA; and the
// orientation from a grid GO instead of the vector; and the element axes from a CID equal to the
// vector's axes (CORD2R with x = basic x, y = basic z).
TEST(Cbush, OffsetSystemGoAndCidGiveTheSameStiffness) {
  const double L = 2.0, F = 100.0, K2 = 2e4, K6 = 6e3;
  const double w = F / K2 + F * 0.25 * L * L / K6;
  for (const std::string& card : {std::string("CBUSH,7,70,1,2,0.,0.,1.,\n,,0,1.,0.,0.\n"),
                                 std::string("CBUSH,7,70,1,2,3\nGRID,3,,0.,0.,5.\n"),
                                 std::string("CBUSH,7,70,1,2,,,,9\nCORD2R,9,,0.,0.,0.,0.,-1.,0.,\n,1.,0.,0.\n")}) {
    const fem::Model m = test::read_deck(bush_cantilever(card));
    EXPECT_NEAR(u(m, solutions::solve_static(m), 2, 3), w, 1e-12 * w) << card;
    const fem::Model back = round_trip(m);
    EXPECT_NEAR(u(back, solutions::solve_static(back), 2, 3), w, 1e-12 * w) << card;
  }
}

// Grounded CBUSH (GB blank) with CID: K of the grid = R diag(K) R^T; a CID rotated 90 degrees about
// z swaps K1 and K2 (and K4, K5) in basic.
TEST(Cbush, GroundedWithRotatedCid) {
  const fem::Model m = test::read_deck(
      "GRID,1,,0.,0.,0.\nCBUSH,7,70,1,,,,,9\nPBUSH,70,K,1.,2.,3.,4.,5.,6.\n"
      "CORD2R,9,,0.,0.,0.,0.,0.,1.,\n,0.,1.,0.\n");
  const Eigen::MatrixXd K = dense_K(m);
  Eigen::VectorXd expected(6);
  expected << 2, 1, 3, 5, 4, 6;
  EXPECT_LT((K - Eigen::MatrixXd(expected.asDiagonal())).norm(), 1e-14) << K;
}

TEST(Cbush, MissingOrientationIsAnError) {
  std::string msg;
  try {
    const fem::Model m = test::read_deck("GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nCBUSH,7,70,1,2\nPBUSH,70,K,1.,2.,3.,4.,5.,6.\n");
    dense_K(m);
  } catch (const InputError& e) {
    msg = e.what();
  }
  EXPECT_TRUE(test::mentions(msg, {"deck.bdf:3", "CBUSH 7", "GO/X1-X3", "expected an orientation vector"}));
  EXPECT_TRUE(test::mentions(test::read_error("PBUSH,70,Q,1.\n"), {"deck.bdf:1: PBUSH 70, field 3 (keyword): got text 'Q'; expected K, B, GE, RCV or M"}));
  EXPECT_TRUE(test::mentions(test::read_error("GRID,1,,0.,0.,0.\nCBUSH,7,70,1,2\nPBUSH,70,K,1.\n"),
                             {"CBUSH 7", "GB", "grid 2", "not defined"}));
}

// PBUSH B and GE are read (written back) and listed as approximated: statics and real modes ignore them.
TEST(Cbush, DampingIsNoted) {
  const fem::Model m = test::read_deck("PBUSH,70,K,1.,2.,3.,4.,5.,6.\n,,B,0.1\n,,GE,0.02\n");
  ASSERT_EQ(m.bush_props.size(), 1u);
  EXPECT_EQ(m.bush_props[0].b[0], 0.1);
  EXPECT_EQ(m.bush_props[0].ge[0], 0.02);
  EXPECT_EQ(m.bush_props[0].k[5], 6.0);
  bool noted = false;
  for (const auto& u : m.unsupported) noted = noted || u.name.rfind("PBUSH B", 0) == 0;
  EXPECT_TRUE(noted);
  const fem::Model back = round_trip(m);
  EXPECT_EQ(back.bush_props[0].b[0], 0.1);
  // the keyword of a continuation line is in field 3 (field 2 blank), as in the QRG
  EXPECT_TRUE(test::mentions(test::read_error("PBUSH,70,K,1.\n,B,0.1\n"), {"deck.bdf:2", "PBUSH 70", "expected a blank field 2 on a continuation line"}));
  EXPECT_EQ(back.bush_props[0].ge[0], 0.02);
}

// ---------------------------------------------------------------------------------------------
// Two-dof chain on scalar points: ground -k1- S10 -k2- S11, masses m1 at S10, m2 at S11 (CELAS4,
// CELAS3 + PELAS, CMASS4, CMASS3 + PMASS). omega^2 are the roots of
//   m1 m2 w^4 - (m1 k2 + m2 (k1 + k2)) w^2 + k1 k2 = 0.
TEST(ScalarElements, TwoDofChainOnScalarPointsMatchesClosedForm) {
  const double k1 = 1000, k2 = 400, m1 = 2, m2 = 0.5;
  const std::string deck =
      "SOL 103\nCEND\nMETHOD = 1\nBEGIN BULK\nEIGRL,1,,,2\nSPOINT,10,11\n"
      "CELAS4,1,1000.,10\nCELAS3,2,20,10,11\nPELAS,20,400.\nCMASS4,3,2.,10\nCMASS3,4,40,11\nPMASS,40,0.5\nENDDATA\n";
  const fem::Model m = test::read_deck(deck);
  const double a = m1 * m2, b = -(m1 * k2 + m2 * (k1 + k2)), c = k1 * k2;
  const double r1 = (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a), r2 = (-b + std::sqrt(b * b - 4 * a * c)) / (2 * a);
  for (const fem::Model* model : {&m}) {
    const auto modes = solutions::solve_normal_modes(*model);
    ASSERT_EQ(modes.eigenvalues.size(), 2);
    EXPECT_NEAR(modes.eigenvalues[0], r1, 1e-9 * r1);
    EXPECT_NEAR(modes.eigenvalues[1], r2, 1e-9 * r2);
  }
  const fem::Model back = round_trip(m);
  const auto modes = solutions::solve_normal_modes(back);
  ASSERT_EQ(modes.eigenvalues.size(), 2);
  EXPECT_NEAR(modes.eigenvalues[1], r2, 1e-9 * r2);
  EXPECT_TRUE(test::mentions(test::read_error("GRID,5,,0.,0.,0.\nCELAS4,1,1000.,5\nCMASS2,2,1.,5,1\n"), {"deck.bdf:2: CELAS4 1, field 4 (S1): references point 5, which is not an SPOINT; expected a scalar point (it is a GRID: use CELAS1 or CELAS2)"}));
}

// CMASS2 between two grid components couples them: M = m [1 -1; -1 1]; CMASS1 through PMASS, grounded.
TEST(ScalarElements, CmassOnGridComponents) {
  const fem::Model m = test::read_deck(
      "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nCMASS2,5,3.,1,2,2,2\nCMASS1,6,60,2,6\nPMASS,60,0.25\n");
  const Eigen::MatrixXd M = dense_M(m);
  EXPECT_EQ(M(1, 1), 3.0);
  EXPECT_EQ(M(7, 7), 3.0);
  EXPECT_EQ(M(1, 7), -3.0);
  EXPECT_EQ(M(7, 1), -3.0);
  EXPECT_EQ(M(11, 11), 0.25);
  EXPECT_NEAR(M.sum(), 0.25, 1e-15);  // the coupled pair sums to zero
  EXPECT_LT((dense_M(round_trip(m)) - M).norm(), 1e-15);
}

// ---------------------------------------------------------------------------------------------
// CONM1 in a system rotated 90 degrees about z (x' = basic y, y' = -basic x): the diagonal
// (m1, m2, m3, J1, J2, J3) in CID becomes (m2, m1, m3, J2, J1, J3) in basic, and M21 = c couples
// x', y' -> basic -c between y and x... computed here as R M R^T with R = [0 -1 0; 1 0 0; 0 0 1].
TEST(Conm1, RotatedMatrixAndFrequency) {
  const fem::Model m = test::read_deck(
      "GRID,1,,0.,0.,0.\nCORD2R,9,,0.,0.,0.,0.,0.,1.,\n,0.,1.,0.\n"
      "CONM1,5,1,9,2.,0.5,3.,,,\n,4.,,,,5.,,,\n,,6.,,,,,,7.\n");
  Eigen::Matrix<double, 6, 6> Mc = Eigen::Matrix<double, 6, 6>::Zero();
  Mc.diagonal() << 2, 3, 4, 5, 6, 7;
  Mc(0, 1) = Mc(1, 0) = 0.5;
  Eigen::Matrix3d R;
  R << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  Eigen::Matrix<double, 6, 6> T = Eigen::Matrix<double, 6, 6>::Zero();
  T.topLeftCorner<3, 3>() = R;
  T.bottomRightCorner<3, 3>() = R;
  const Eigen::MatrixXd expected = T * Mc * T.transpose();
  const Eigen::MatrixXd M = dense_M(m);
  EXPECT_LT((M - expected).norm(), 1e-14) << M;
  EXPECT_LT((dense_M(round_trip(m)) - expected).norm(), 1e-14);
  // on a grounded spring k along basic z: omega^2 = k / m3
  const fem::Model f = test::read_deck(
      "SOL 103\nCEND\nMETHOD = 1\nSPC = 1\nBEGIN BULK\nEIGRL,1,,,1\nGRID,1,,0.,0.,0.\nSPC1,1,12456,1\n"
      "CONM1,5,1,,2.,,3.,,,\n,4.\nCELAS2,6,100.,1,3\nENDDATA\n");
  const auto modes = solutions::solve_normal_modes(f);
  ASSERT_GE(modes.eigenvalues.size(), 1);
  EXPECT_NEAR(modes.eigenvalues[0], 100.0 / 4.0, 1e-12 * 25.0);
  EXPECT_TRUE(test::mentions(test::read_error("CONM1,5,1,,-2.\n"), {"deck.bdf:1: CONM1 5, field 5 (M11): got real '-2.'; expected a diagonal term >= 0"}));
}

}  // namespace
}  // namespace seflex
