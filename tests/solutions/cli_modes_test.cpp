// seflex modes: the eigenvalue table, --csv, --vtk (read back with VTK), --eigensolver, --count.
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <gtest/gtest.h>

#include <sstream>

#include "laminate_reference.hpp"
#include "nastran_test_util.hpp"
#include "solution_decks.hpp"
#include "test_support.hpp"

namespace seflex {
namespace {

std::filesystem::path bar_cc() {
  return test::validation_dir() / "mystran_cbar_cantilever_and_freefree_modes" / "BAR-CC-GIV.DAT";
}

// The table reproduces MYSTRAN's REAL EIGENVALUES of BAR-CC-GIV (tests/data/validation), and the
// CSV holds mode, eigenvalue and frequency.
TEST(ModesCli, BarCantileverTableAndCsv) {
  test::TempDir dir;
  const auto r = test::run_seflex("modes '" + bar_cc().string() + "' --csv f.csv", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("R E A L   E I G E N V A L U E S"), std::string::npos);
  EXPECT_NE(r.out.find("      1         1    4.509067E+03  6.714959E+01  1.068719E+01   6.800571E-04   3.066423E+00"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("      4         4    3.318753E+06  1.821744E+03  2.899396E+02   1.590132E-03   5.277256E+03"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(test::read_file(dir / "f.csv").rfind("mode,eigenvalue,frequency_hz\n", 0), 0u);
  const auto rows = test::csv_rows(dir / "f.csv");
  ASSERT_EQ(rows.size(), 4u);
  const double cycles[4] = {10.68719, 62.81653, 166.3460, 289.9396};
  for (int j = 0; j < 4; ++j) {
    EXPECT_EQ(rows[j][0], j + 1);
    EXPECT_NEAR(rows[j][2] / cycles[j], 1.0, 1e-6);  // MYSTRAN's 7 digits: 4.7e-7; measured 2.9e-7
    EXPECT_NEAR(std::sqrt(rows[j][1]) / (2 * M_PI), rows[j][2], 1e-12 * rows[j][2]);
  }
}

// The .vtu reads back: 5 grids, 4 lines, per-mode displacement and rotation vectors in basic
// (NORM = MAX: the largest component of each mode is +1; in mode 1 it is the tip's T3), and the
// frequencies as field data.
TEST(ModesCli, VtkModeShapesReadBack) {
  test::TempDir dir;
  const auto r = test::run_seflex("modes '" + bar_cc().string() + "' --vtk bar.vtu", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((dir / "bar.vtu").string().c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  ASSERT_NE(grid, nullptr);
  EXPECT_EQ(grid->GetNumberOfPoints(), 5);
  EXPECT_EQ(grid->GetNumberOfCells(), 4);
  EXPECT_EQ(grid->GetCellType(0), 3);  // VTK_LINE
  vtkDataArray* ids = grid->GetPointData()->GetArray("grid_id");
  ASSERT_NE(ids, nullptr);
  EXPECT_EQ(ids->GetTuple1(4), 5);
  for (int k = 1; k <= 4; ++k) {
    const std::string name = "mode_0" + std::to_string(k);
    vtkDataArray* u = grid->GetPointData()->GetArray((name + "_displacement").c_str());
    vtkDataArray* rot = grid->GetPointData()->GetArray((name + "_rotation").c_str());
    ASSERT_NE(u, nullptr) << name;
    ASSERT_NE(rot, nullptr) << name;
    EXPECT_EQ(u->GetNumberOfComponents(), 3);
    double largest = 0;
    for (vtkIdType p = 0; p < 5; ++p)
      for (vtkDataArray* a : {u, rot})
        for (int c = 0; c < 3; ++c)
          if (std::abs(a->GetComponent(p, c)) > std::abs(largest)) largest = a->GetComponent(p, c);
    EXPECT_NEAR(largest, 1.0, 1e-12) << name;
    EXPECT_EQ(u->GetComponent(0, 2), 0.0) << name;           // grid 1 is clamped
    EXPECT_EQ(u->GetComponent(2, 0), 0.0) << name;           // GRDSET PS 1246
  }
  // mode 1 at grid 5: T3 = 1 and R2 as MYSTRAN prints it
  EXPECT_NEAR(grid->GetPointData()->GetArray("mode_01_displacement")->GetComponent(4, 2), 1.0, 1e-12);
  EXPECT_NEAR(grid->GetPointData()->GetArray("mode_01_rotation")->GetComponent(4, 1), -1.398892E-02, 1e-8);
  vtkDataArray* hz = grid->GetFieldData()->GetArray("frequency_hz");
  ASSERT_NE(hz, nullptr);
  ASSERT_EQ(hz->GetNumberOfTuples(), 4);
  EXPECT_NEAR(hz->GetTuple1(0) / 10.68719, 1.0, 1e-6);
}

// A free plate large enough for the Krylov backends: Spectra, ARPACK and block Lanczos print the
// same frequencies, six of them rigid-body modes below 1e-4 of the first elastic one; --count
// overrides ND.
TEST(ModesCli, KrylovBackendsAgreeOnAFreePlate) {
  test::TempDir dir;
  const auto deck = dir.write("plate.bdf", test::free_plate_deck(24, 16, 12));
  std::vector<std::vector<std::vector<double>>> results;
  for (const char* solver : {"spectra", "arpack", "block"}) {
    const std::string csv = std::string(solver) + ".csv";
    const auto r = test::run_seflex("modes plate.bdf --count 14 --eigensolver " + std::string(solver) + " --csv " + csv,
                                    dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("eigensolver " + std::string(solver)), std::string::npos) << r.out;
    results.push_back(test::csv_rows(dir / csv));
    ASSERT_EQ(results.back().size(), 14u);
    int rigid = 0;
    for (const auto& row : results.back()) rigid += row[2] < 1e-4 * results.back()[6][2];
    EXPECT_EQ(rigid, 6) << solver;
  }
  // a block of 3 holds only half of the six rigid-body modes: the completeness check brings the rest
  const auto small = test::run_seflex("modes plate.bdf --count 14 --block-size 3 --csv block3.csv", dir.path());
  ASSERT_EQ(small.exit_code, 0) << small.err;
  results.push_back(test::csv_rows(dir / "block3.csv"));
  ASSERT_EQ(results.back().size(), 14u);
  int rigid = 0;
  for (const auto& row : results.back()) rigid += row[2] < 1e-4 * results.back()[6][2];
  EXPECT_EQ(rigid, 6) << "block 3";
  for (std::size_t b = 1; b < results.size(); ++b)
    for (int j = 6; j < 14; ++j) EXPECT_NEAR(results[0][j][1] / results[b][j][1], 1.0, 1e-10) << b << " mode " << j + 1;
  const auto nd = test::run_seflex("modes plate.bdf", dir.path());
  ASSERT_EQ(nd.exit_code, 0) << nd.err;
  EXPECT_NE(nd.out.find(", 12 modes,"), std::string::npos) << nd.out;  // EIGRL ND = 12
}

// A laminated plate from the deck to the eigenvalue table: simply supported [0/90/90/0] T300/5208
// (PCOMP in large field, MAT8 with a continuation), 0.2 x 0.3 m, 20 x 20 CQUAD4; the four lowest
// frequencies against the Navier solution of lamination theory (Reddy, Mechanics of Laminated
// Composite Plates and Shells, 2nd ed., ch. 5; D from the textbook sums of
// tests/support/laminate_reference.hpp), within 1 % (tests/fem/composite_plate_test.cpp has the same
// plate through the library: -0.26, -0.52, -0.21, +0.48 %).
TEST(ModesCli, CrossPlyPcompPlateMatchesNavier) {
  using namespace fem::test::clt;
  const double a = 0.2, b = 0.3, h = 4 * kPly, rho = 1600.0;
  const int n = 20;
  std::string d = "SOL 103\nCEND\nMETHOD = 1\nSPC = 1\nBEGIN BULK\nEIGRL,1,,,4\n"
                  "MAT8,8,181.+9,10.3+9,.28,7.17+9,5.+9,4.+9,1600.,+M\n+M,,,,1.+9\n" +
                  test::fixed_line({"PCOMP*", "1", "", "", ""}, 16, "*P1") +
                  test::fixed_line({"*P1", "", "", "", "SYM"}, 16, "*P2") +
                  test::fixed_line({"*P2", "8", "1.25-4", "0.", "NO"}, 16, "*P3") +
                  test::fixed_line({"*P3", "8", "1.25-4", "90."}, 16);
  auto id = [&](int i, int j) { return 1 + i + (n + 1) * j; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      d += "GRID," + std::to_string(id(i, j)) + ",," + std::to_string(a * i / n) + "," + std::to_string(b * j / n) + ",0.\n";
      const bool xe = i == 0 || i == n, ye = j == 0 || j == n;  // hard simple support: w and the edge's tangent rotation
      const std::string c = std::string("12") + (xe || ye ? "3" : "") + (xe ? "4" : "") + (ye ? "5" : "") + "6";
      d += "SPC1,1," + c + "," + std::to_string(id(i, j)) + "\n";
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      d += "CQUAD4," + std::to_string(id(i, j)) + ",1," + std::to_string(id(i, j)) + "," + std::to_string(id(i + 1, j)) +
           "," + std::to_string(id(i + 1, j + 1)) + "," + std::to_string(id(i, j + 1)) + "\n";
  d += "ENDDATA\n";
  test::TempDir dir;
  dir.write("laminate.bdf", d);
  const auto r = test::run_seflex("modes laminate.bdf --csv f.csv", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("PCOMP"), std::string::npos) << r.err;  // used, not warned about
  const Eigen::Matrix3d D = hand_abd({0, 90, 90, 0}).D;
  std::vector<double> ref;
  for (int m = 1; m <= 4; ++m)
    for (int k = 1; k <= 4; ++k) {
      const double x = m / a, y = k / b;
      const double dmn = D(0, 0) * std::pow(x, 4) + 2 * (D(0, 1) + 2 * D(2, 2)) * x * x * y * y + D(1, 1) * std::pow(y, 4);
      ref.push_back(std::sqrt(std::pow(kPi, 4) * dmn / (rho * h)) / (2 * kPi));
    }
  std::sort(ref.begin(), ref.end());
  const auto rows = test::csv_rows(dir / "f.csv");
  ASSERT_EQ(rows.size(), 4u);
  for (int j = 0; j < 4; ++j) EXPECT_NEAR(rows[j][2] / ref[j], 1.0, 0.01) << "mode " << j + 1;
}

TEST(ModesCli, RefusesToOverwriteAndChecksOptions) {
  test::TempDir dir;
  dir.write("f.csv", "keep\n");
  const auto r = test::run_seflex("modes '" + bar_cc().string() + "' --csv f.csv", dir.path());
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("f.csv"), std::string::npos) << r.err;
  EXPECT_EQ(test::read_file(dir / "f.csv"), "keep\n");
  EXPECT_EQ(test::run_seflex("modes '" + bar_cc().string() + "' --csv f.csv --force", dir.path()).exit_code, 0);
  EXPECT_EQ(test::run_seflex("modes '" + bar_cc().string() + "' --eigensolver lobpcg", dir.path()).exit_code, 2);
  EXPECT_EQ(test::run_seflex("modes '" + bar_cc().string() + "' --count 0", dir.path()).exit_code, 2);
  EXPECT_EQ(test::run_seflex("modes '" + bar_cc().string() + "' --block-size 0", dir.path()).exit_code, 2);
  EXPECT_EQ(test::run_seflex("modes '" + bar_cc().string() + "' --vtk shapes.vtk", dir.path()).exit_code, 2);
}

}  // namespace
}  // namespace seflex
