// A solid bracket deck (CHEXA, PSOLID, MAT1, RBE2 attachments, PLOAD4 on solid faces, a LOAD
// combination, two subcases) through seflex info, static, convert and reduce.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>

#include "test_support.hpp"

namespace seflex {
namespace {

/// A 0.2 x 0.02 x 0.02 m aluminium bar (nu = 0) of 10 x 2 x 2 CHEXA (grids i + 11 j + 33 k + 1), an RBE2
/// from grid 1000 to the end x = 0 and from grid 2000 to the end x = 0.2; PLOAD4 set 10: 1 MPa on
/// the end faces x = 0.2 pushing along -x (a compressive end load of 400 N); LOAD 20 = 2 x set 10.
/// Grid 3000, tied by an RBE2 to the mid cross-section, is a grid with six dofs for the floating
/// frame of the reduction (solid grids have translations only, and the frame node must have six).
std::string bracket_deck(const std::string& case_control) {
  std::ostringstream d;
  d << "SOL 101\nCEND\n" << case_control << "BEGIN BULK\nMAT1,1,7.e10,,0.,2700.\nPSOLID,1,1\n";
  auto id = [](int i, int j, int k) { return 1 + i + 11 * j + 33 * k; };
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 10; ++i)  // std::to_string: always a decimal point, as a real field needs
        d << "GRID," << id(i, j, k) << ",," << std::to_string(0.02 * i) << "," << std::to_string(0.01 * j) << ","
          << std::to_string(0.01 * k) << "\n";
  int eid = 1;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 10; ++i) {
        d << "CHEXA," << eid << ",1," << id(i, j, k) << "," << id(i + 1, j, k) << "," << id(i + 1, j + 1, k) << ","
          << id(i, j + 1, k) << "," << id(i, j, k + 1) << "," << id(i + 1, j, k + 1) << "\n," << id(i + 1, j + 1, k + 1)
          << "," << id(i, j + 1, k + 1) << "\n";
        if (i == 9) d << "PLOAD4,10," << eid << ",1.e6,,,," << id(10, j, k) << "," << id(10, j + 1, k + 1) << "\n";
        ++eid;
      }
  d << "GRID,1000,,-0.01,0.01,0.01\nGRID,2000,,0.21,0.01,0.01\nGRID,3000,,0.1,0.01,0.01\n";
  for (const int i : {0, 10, 5}) {  // RBE2 EID GN CM G1-G5 / G6-G9 on a continuation line
    d << "RBE2," << (i == 0 ? "500,1000" : i == 10 ? "501,2000" : "502,3000") << ",123456";
    int n = 0;
    for (int k = 0; k <= 2; ++k)
      for (int j = 0; j <= 2; ++j) d << (n++ == 5 ? "\n," : ",") << id(i, j, k);
    d << "\n";
  }
  d << "SPC1,1,123456,1000\nLOAD,20,1.,2.,10\nENDDATA\n";
  return d.str();
}

std::map<std::pair<int, int>, std::vector<double>> read_rows(const std::filesystem::path& file) {
  std::istringstream csv(test::read_file(file));
  std::string line;
  std::getline(csv, line);
  std::map<std::pair<int, int>, std::vector<double>> rows;
  while (std::getline(csv, line)) {
    std::vector<double> v;
    std::istringstream f(line);
    for (std::string x; std::getline(f, x, ',');) v.push_back(std::stod(x));
    rows[{static_cast<int>(v[0]), static_cast<int>(v[1])}] = v;
  }
  return rows;
}

TEST(SolidCli, InfoStaticConvertAndReduceAcceptAChexaBracket) {
  test::TempDir dir;
  dir.write("bracket.bdf", bracket_deck("SPC = 1\nSUBCASE 1\nLOAD = 10\nSUBCASE 2\nLOAD = 20\n"));
  const auto info = test::run_seflex("info bracket.bdf", dir.path());
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("    CHEXA" + std::string(18, ' ') + std::string(8, ' ') + "40\n"), std::string::npos) << info.out;
  EXPECT_EQ(info.out.find("refused"), std::string::npos) << info.out;

  // Static: the end load 400 N compresses the bar (nu = 0: uniaxial stress, which the CHEXA represents
  // exactly, so the RBE2 ends restrain nothing): end shortening F L / (E A) = 400 * 0.2 / (7e10 * 4e-4).
  const auto st = test::run_seflex("static bracket.bdf -o u.csv", dir.path());
  ASSERT_EQ(st.exit_code, 0) << st.err;
  const auto rows = read_rows(dir / "u.csv");
  std::string line;
  const double shortening = 400 * 0.2 / (7e10 * 4e-4);
  EXPECT_NEAR(-rows.at({1, 2000})[2] / shortening, 1.0, 1e-9);
  EXPECT_NEAR(rows.at({2, 2000})[2], 2 * rows.at({1, 2000})[2], 1e-12 * shortening);  // LOAD 20 = 2 x set 10

  // Convert writes the solids, PSOLID and PLOAD4 back; the written deck gives the same displacements.
  const auto conv = test::run_seflex("convert bracket.bdf -o out.bdf", dir.path());
  ASSERT_EQ(conv.exit_code, 0) << conv.err;
  const std::string written = test::read_file(dir / "out.bdf");
  for (const char* card : {"CHEXA,1,1,1,2,13,12,34,35\n,46,45", "PSOLID,1,1", "PLOAD4,10,10,"})
    EXPECT_NE(written.find(card), std::string::npos) << card << "\n" << written.substr(0, 3000);
  const auto st2 = test::run_seflex("static out.bdf -o u2.csv", dir.path());
  ASSERT_EQ(st2.exit_code, 0) << st2.err;
  const auto rows2 = read_rows(dir / "u2.csv");
  ASSERT_EQ(rows2.size(), rows.size());
  for (const auto& [key, v] : rows)
    for (std::size_t c = 2; c < v.size(); ++c) EXPECT_NEAR(rows2.at(key)[c], v[c], 1e-9 * shortening);

  // Craig-Bampton with every fixed-interface mode kept reproduces the free-free frequencies.
  dir.write("free.bdf", bracket_deck(""));
  const auto r = test::run_seflex("reduce free.bdf --interface 1000,2000 --modes 1000 --compare 6 -o b.se", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream out(r.out.substr(r.out.find("full FE (Hz)")));
  std::getline(out, line);
  int rows_seen = 0;
  while (std::getline(out, line) && !line.empty()) {
    std::istringstream f(line);
    int mode;
    double red, full;
    std::string rel;
    f >> mode >> red >> full >> rel;
    if (rel == "(rigid)") continue;
    ++rows_seen;
    EXPECT_LT(std::abs(std::stod(rel)), 1e-6) << line;
  }
  EXPECT_EQ(rows_seen, 6);
}

}  // namespace
}  // namespace seflex
