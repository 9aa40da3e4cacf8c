// seflex static: exit status, summary, and the CSV against beam theory (basic system).
#include <gtest/gtest.h>

#include <sstream>

#include "solution_decks.hpp"
#include "test_support.hpp"

namespace seflex {
namespace {

/// CSV rows keyed by the first column.
std::map<int, std::vector<double>> read_csv(const std::filesystem::path& p, std::string& header) {
  std::istringstream in(test::read_file(p));
  std::getline(in, header);
  std::map<int, std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> v;
    std::istringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');) v.push_back(std::stod(f));
    rows[static_cast<int>(v.at(0))] = v;
  }
  return rows;
}

// Tip load P on an Euler-Bernoulli cantilever: w(L) = P L^3 / (3 E I), R2 = -dw/dx = -P L^2 / (2 E I)
// (Timoshenko & Gere, table G-1), exact at the nodes of cubic beam elements. The tip's CD system
// is rotated; the CSV is in basic regardless.
TEST(StaticCli, CantileverCsvInBasicMatchesBeamTheory) {
  test::TempDir dir;
  const auto deck = dir.write("cantilever.bdf", test::cantilever_deck());
  const auto r = test::run_seflex("static '" + deck.string() + "' -o out.csv", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string header;
  const auto rows = read_csv(dir / "out.csv", header);
  EXPECT_EQ(header, "grid,t1,t2,t3,r1,r2,r3");
  ASSERT_EQ(rows.size(), 11u);
  const double P = 120, L = 1.5, EI = 7e10 * 2e-8;
  const auto& tip = rows.at(11);
  EXPECT_NEAR(tip[3] / (P * L * L * L / (3 * EI)), 1.0, 1e-9);
  EXPECT_NEAR(tip[5] / (-P * L * L / (2 * EI)), 1.0, 1e-9);
  EXPECT_LT(std::abs(tip[1]) + std::abs(tip[2]) + std::abs(tip[4]) + std::abs(tip[6]), 1e-12);
  for (double v : rows.at(1)) EXPECT_EQ(v, v == 1.0 ? 1.0 : 0.0);  // grid 1 clamped
  // summary: the SPC forces balance the load, FZ = -120 and MY = +180 about the origin
  EXPECT_NE(r.out.find("LOAD 7, SPC 1"), std::string::npos) << r.out;
  const auto line = r.out.substr(r.out.find("SPC forces"));
  std::istringstream words(line.substr(std::string("SPC forces").size()));
  double f[6];
  for (double& x : f) words >> x;
  EXPECT_NEAR(f[2], -120.0, 1e-6);
  EXPECT_NEAR(f[4], 180.0, 1e-6);
  EXPECT_NE(r.out.find("at grid 11"), std::string::npos) << r.out;
}

// A 10-ply PCOMPG of a MAT8 fabric, 2 x 2 CQUAD4 in the x-z plane pulled in its plane (fixed-format
// cards as Simcenter Nastran's preprocessor writes them: PCOMPG with Z0 blank, TSAI, the allowables
// line of MAT8). The model is pyNastran's models/nx/laminate/laminate_elstrn_fiber_center.bdf (its
// grids, cards and loads); the reference is its F06, Simcenter Nastran 2306 (8/25/23) SOL 101,
// DISPLACEMENT VECTOR: translations within 1e-6 of the largest (the drilling rotations R2 are the
// elements' own and are not compared).
TEST(StaticCli, PcompgMembraneMatchesSimcenterNastran) {
  const std::string deck =
      "SOL 101\nCEND\nSUBCASE 1\n  LOAD = 17\n  SPC = 18\nBEGIN BULK\nPARAM,K6ROT,100.\n"
      "GRID,1,,10.,0.,12.5\nGRID,2,,0.,0.,12.5\nGRID,3,,10.,0.,0.\nGRID,4,,10.,0.,25.\nGRID,5,,20.,0.,12.5\n"
      "GRID,6,,0.,0.,25.\nGRID,7,,0.,0.,0.\nGRID,8,,20.,0.,0.\nGRID,9,,20.,0.,25.\n"
      "CQUAD4         3       2       1       2       7       3\n"
      "CQUAD4         4       2       5       1       3       8\n"
      "CQUAD4         1       2       9       4       1       5\n"
      "CQUAD4         2       2       4       6       2       1\n"
      "PCOMPG         2          0.000015000.00    TSAI 20.0000  0.0000        +\n"
      "+              1       60.195580  0.0000     YES                        +\n"
      "+              2       60.195580 90.0000     YES                        +\n"
      "+              3       60.195580  0.0000     YES                        +\n"
      "+              4       60.195580 90.0000     YES                        +\n"
      "+              5       60.195580  0.0000     YES                        +\n"
      "+              6       60.195580  0.0000     YES                        +\n"
      "+              7       60.195580 90.0000     YES                        +\n"
      "+              8       60.195580  0.0000     YES                        +\n"
      "+              9       60.195580 90.0000     YES                        +\n"
      "+             10       60.195580  0.0000     YES\n"
      "MAT8           66.7141+76.6727+70.0530005.0676+65.0676+65.0676+61.5440-6+\n"
      "+         0.0000  0.0000        7.5017+56.2781+57.2943+55.8428+588680.21\n"
      "FORCE         17       4       050000.00  0.0000  0.00001.000000\n"
      "FORCE         17       6       025000.00  0.0000  0.00001.000000\n"
      "FORCE         17       9       025000.00  0.0000  0.00001.000000\n"
      "SPC           18       3  123456  0.0000\nSPC           18       7  123456  0.0000\n"
      "SPC           18       8  123456  0.0000\nENDDATA\n";
  test::TempDir dir;
  dir.write("laminate.bdf", deck);
  const auto r = test::run_seflex("static laminate.bdf -o out.csv", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string header;
  const auto rows = read_csv(dir / "out.csv", header);
  // Simcenter Nastran: T1, T3 of grids 1, 2, 4, 5, 6, 9 (T2 = 0)
  const std::map<int, std::pair<double, double>> ref = {
      {1, {-6.194415e-16, 4.763643e-04}}, {2, {2.520294e-05, 4.780829e-04}},  {4, {-1.255585e-15, 9.553896e-04}},
      {5, {-2.520294e-05, 4.780829e-04}}, {6, {1.797797e-05, 9.546929e-04}}, {9, {-1.797797e-05, 9.546929e-04}}};
  const double scale = 9.553896e-04;
  for (const auto& [g, t] : ref) {
    EXPECT_NEAR(rows.at(g)[1], t.first, 1e-6 * scale) << "grid " << g;
    EXPECT_NEAR(rows.at(g)[2], 0.0, 1e-6 * scale) << "grid " << g;
    EXPECT_NEAR(rows.at(g)[3], t.second, 1e-6 * scale) << "grid " << g;
  }
}

TEST(StaticCli, RefusesToOverwriteWithoutForce) {
  test::TempDir dir;
  const auto deck = dir.write("cantilever.bdf", test::cantilever_deck());
  dir.write("out.csv", "precious\n");
  const auto r = test::run_seflex("static '" + deck.string() + "' -o out.csv", dir.path());
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("out.csv"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  EXPECT_EQ(test::read_file(dir / "out.csv"), "precious\n");
  const auto forced = test::run_seflex("static '" + deck.string() + "' -o out.csv --force", dir.path());
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_EQ(test::read_file(dir / "out.csv").rfind("grid,t1", 0), 0u);
}

TEST(StaticCli, DefaultOutputIsNamedAfterTheDeck) {
  test::TempDir dir;
  const auto deck = dir.write("cantilever.bdf", test::cantilever_deck());
  const auto r = test::run_seflex("static cantilever.bdf", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "cantilever_displacements.csv"));
}

}  // namespace
}  // namespace seflex
