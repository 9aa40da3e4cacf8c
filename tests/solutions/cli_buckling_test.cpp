// seflex buckling (SOL 105): Euler column deck (tests/data/buckling/euler_column_cbar.bdf) against
// Euler's load, the CSV, the VTK; a plate deck against Timoshenko & Gere with every Lanczos backend;
// `seflex info` classifying SOL 105, and the errors of decks without METHOD, without a preload
// subcase, or with an EIGR method.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "test_support.hpp"

namespace seflex {
namespace {

std::filesystem::path deck(const std::string& name) { return test::data_dir() / "buckling" / name; }

// Euler's load of the deck's column: pi^2 E I / l^2 with the PBAR's I = 7853.98 mm^4 (pi d^4 / 64,
// d = 20 mm), E = 207000 MPa, l = 420 mm: 90962 N, the value of Mitrotta's SOL 105 notebook
// (github.com/fmamitrotta/nonlinear-structural-stability-notebooks, 01_Buckling_Analysis_of_Euler_Column).
// 10 cubic-Hermite CBARs: the first pair (one mode per bending plane, I1 = I2) within 1e-4, the
// second pair (P = 4 x Euler, 5 elements per half-wave) within 1e-3, both from above.
TEST(BucklingCli, EulerColumnTableCsvAndVtk) {
  const double pi = std::acos(-1.0);
  const double P_euler = pi * pi * 207000.0 * 7853.98 / (420.0 * 420.0);
  EXPECT_NEAR(P_euler, 90962.0, 0.5);
  test::TempDir dir;
  const auto r =
      test::run_seflex("buckling '" + deck("euler_column_cbar.bdf").string() + "' --csv f.csv --vtk m.vtu", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("R E A L   E I G E N V A L U E S"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("preload SUBCASE 1 (LOAD 2), load factors of SUBCASE 2 (METHOD 10, SPC 1)"), std::string::npos)
      << r.out;
  EXPECT_EQ(test::read_file(dir / "f.csv").rfind("mode,load_factor\n", 0), 0u);
  const auto rows = test::csv_rows(dir / "f.csv");
  ASSERT_EQ(rows.size(), 4u);
  for (int j = 0; j < 4; ++j) {
    EXPECT_EQ(rows[j][0], j + 1);
    const double expected = (j < 2 ? 1.0 : 4.0) * P_euler;
    EXPECT_GT(rows[j][1], expected) << "mode " << j + 1;  // the consistent K_sigma gives upper bounds
    EXPECT_LT(rows[j][1] / expected - 1.0, j < 2 ? 1e-4 : 1e-3) << "mode " << j + 1;
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "m.vtu"));
}

// STATSUB names the preload subcase (QRG case control): the same load factors, and the command is
// not reported as unused.
TEST(BucklingCli, StatsubNamesThePreload) {
  test::TempDir dir;
  std::string text = test::read_file(deck("euler_column_cbar.bdf"));
  const auto at = text.find("  METHOD = 10");
  ASSERT_NE(at, std::string::npos);
  text.insert(at, "  STATSUB = 1\n");
  dir.write("statsub.bdf", text);
  const auto plain = test::run_seflex("buckling '" + deck("euler_column_cbar.bdf").string() + "' --csv a.csv", dir.path());
  const auto r = test::run_seflex("buckling statsub.bdf --csv b.csv", dir.path());
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("STATSUB"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("STATSUB"), std::string::npos) << r.out;
  const auto a = test::csv_rows(dir / "a.csv"), b = test::csv_rows(dir / "b.csv");
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t j = 0; j < a.size(); ++j) EXPECT_EQ(a[j][1], b[j][1]);
}

// The plate deck (tests/data/buckling/plate_ss_cquad4_10x10.bdf, 630 free dofs: above the dense
// solver's threshold, so the Lanczos backends really run): the three backends agree, and the first
// load factor is the plate's N_cr = 4 pi^2 D / b^2 (Timoshenko & Gere 1961, sec. 9.2) within 1 %, from
// above (MITC4 with the hard simple support converges from above: 8 x 8 +1.2 %, 16 x 16 +0.26 %).
TEST(BucklingCli, PlateWithEveryLanczosBackend) {
  const double pi = std::acos(-1.0);
  const double D = 7e10 * 1e-6 / (12 * (1 - 0.09));
  const double Ncr = 4 * pi * pi * D;
  test::TempDir dir;
  std::vector<std::vector<double>> first;
  for (const char* solver : {"block", "spectra", "arpack"}) {
    const std::string csv = std::string(solver) + ".csv";
    const auto r = test::run_seflex("buckling '" + deck("plate_ss_cquad4_10x10.bdf").string() +
                                        "' --count 2 --eigensolver " + solver + " --csv " + csv,
                                    dir.path());
    ASSERT_EQ(r.exit_code, 0) << solver << ": " << r.err;
    EXPECT_NE(r.out.find("eigensolver " + std::string(solver)), std::string::npos) << r.out;
    const auto rows = test::csv_rows(dir / csv);
    ASSERT_EQ(rows.size(), 2u) << solver;
    if (first.empty()) first = rows;
    for (int j = 0; j < 2; ++j) EXPECT_NEAR(rows[j][1] / first[j][1], 1.0, 1e-8) << solver << " mode " << j + 1;
    EXPECT_GT(rows[0][1] / Ncr - 1.0, 0.0) << solver;
    EXPECT_LT(rows[0][1] / Ncr - 1.0, 0.01) << solver;
  }
}

// The column located and displaced in a rotated rectangular system (CP = CD = 1, FORCE in CID 1):
// K_sigma's element displacements and blocks pass through the grids' CD axes; same load factors.
TEST(BucklingCli, ColumnInARotatedDisplacementSystem) {
  test::TempDir dir;
  for (const char* name : {"euler_column_cbar.bdf", "euler_column_cbar_rotated_cd.bdf"}) {
    const auto r = test::run_seflex("buckling '" + deck(name).string() + "' --csv " + name + ".csv", dir.path());
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
  }
  const auto a = test::csv_rows(dir / "euler_column_cbar.bdf.csv"),
             b = test::csv_rows(dir / "euler_column_cbar_rotated_cd.bdf.csv");
  ASSERT_EQ(a.size(), 4u);
  ASSERT_EQ(b.size(), 4u);
  for (int j = 0; j < 4; ++j) EXPECT_NEAR(b[j][1] / a[j][1], 1.0, 1e-9) << "mode " << j + 1;
}

TEST(BucklingCli, InfoClassifiesSol105) {
  const auto r = test::run_seflex("info '" + deck("euler_column_cbar.bdf").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("card use by buckling (SOL 105), the deck's SOL (run it with: seflex buckling DECK)"),
            std::string::npos)
      << r.out;
}

TEST(BucklingCli, ErrorsNameTheMissingSubcaseOrCard) {
  {
    const auto r = test::run_seflex("buckling '" + deck("euler_column_no_method.bdf").string() + "'");
    EXPECT_EQ(r.exit_code, 3) << r.out;
    EXPECT_NE(r.err.find("no subcase selects METHOD"), std::string::npos) << r.err;
  }
  {
    const auto r = test::run_seflex("buckling '" + deck("euler_column_no_preload.bdf").string() + "'");
    EXPECT_EQ(r.exit_code, 3) << r.out;
    EXPECT_NE(r.err.find("SUBCASE 2 selects METHOD = 10 but no subcase before it selects a LOAD"), std::string::npos)
        << r.err;
  }
  {
    const auto r = test::run_seflex("buckling '" + deck("euler_column_eigr.bdf").string() + "'");
    EXPECT_EQ(r.exit_code, 3) << r.out;
    EXPECT_NE(r.err.find("EIGR 11 is selected by METHOD of the buckling subcase"), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace seflex
