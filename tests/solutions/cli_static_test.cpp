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
