// External superelements (SEBULK EXTOP4: a part given by its KAA and MAA in an OP4 file, ASSIGN
// INPUTT4 in the executive control, EXTRN and SPOINTs for its modal coordinates):
// - round trip: a cantilevered strip of three plates solved whole, and with plates 1-2 reduced by
//   seflex to a Craig-Bampton superelement (every fixed-interface mode of its two interior grids),
//   written to OP4 and attached to plate 3 as EXTOP4: the same static displacements (the static
//   condensation of a part loaded at its boundary only is exact) and the same frequencies (all
//   interior modes kept: the Craig-Bampton basis spans the part's dofs), to round-off;
// - MSC Nastran 2017.1's se_test_n11 (tests/data/pynastran/se_test_n11, README there): the CBUSH
//   forces of its three load cases against the deck's OP2, and its GRAV cases, which load no mass
//   in Nastran (the residual has none; the external part has no load set), zero;
// - the OP4 reader on the layouts Nastran writes (dense, sparse, bigmat; single and double precision)
//   against the same matrix, and its errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "nastran_test_util.hpp"
#include "test_support.hpp"
#include "seflex/fem/element_results.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/io/nastran.hpp"
#include "seflex/io/op4.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"
#include "seflex/solutions/normal_modes.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

using test::num;

const char* kMaterials[3] = {"7.0e10,,0.3,2700.", "2.0e11,,0.29,7800.", "1.1e11,,0.34,4400."};
const double kThickness[3] = {0.02, 0.015, 0.01};

std::string grid(int id, double x, double y) { return "GRID," + std::to_string(id) + ",," + num(x) + "," + num(y) + ",0.\n"; }
std::string plate(int k) {  // MAT1, PSHELL and CQUAD4 k + 1 (grids 2k+1 .. 2k+4)
  const std::string id = std::to_string(k + 1);
  return "MAT1," + id + "," + kMaterials[k] + "\nPSHELL," + id + "," + id + "," + num(kThickness[k]) + "," + id + ",," + id + "\n" +
         "CQUAD4," + id + "," + id + "," + std::to_string(2 * k + 1) + "," + std::to_string(2 * k + 3) + "," + std::to_string(2 * k + 4) +
         "," + std::to_string(2 * k + 2) + "\n";
}
const char* kLoads = "FORCE,2,7,,1.,300.,-200.,50.\nFORCE,2,8,,1.,300.,-200.,50.\nMOMENT,2,8,,1.,0.,40.,0.\n";

// The whole strip: plates 1-3 from x = 0 to 3, clamped at x = 0, loaded at x = 3.
std::string whole_strip() {
  std::string d = "SOL 101\nCEND\nSPC = 1\nLOAD = 2\nMETHOD = 3\nBEGIN BULK\nEIGRL,3,,,6\n";
  for (int i = 0; i < 4; ++i) d += grid(2 * i + 1, i, 0) + grid(2 * i + 2, i, 1);
  for (int k = 0; k < 3; ++k) d += plate(k);
  return d + "SPC1,1,123456,1,2\n" + kLoads + "ENDDATA\n";
}

// Plates 1-2 alone, clamped: the part to reduce (interface grids 5 and 6).
std::string part_deck() {
  std::string d = "SOL 103\nCEND\nSPC = 1\nBEGIN BULK\n";
  for (int i = 0; i < 3; ++i) d += grid(2 * i + 1, i, 0) + grid(2 * i + 2, i, 1);
  return d + plate(0) + plate(1) + "SPC1,1,123456,1,2\nENDDATA\n";
}

// Plate 3 with the part attached as EXTOP4 11 (modal coordinates on SPOINTs 101-112).
std::string external_deck(const std::string& assign, int modes = 12) {
  const std::string last = std::to_string(100 + modes);
  std::string d = assign + "SOL 101\nCEND\nLOAD = 2\nMETHOD = 3\nBEGIN BULK\nEIGRL,3,,,6\n";
  for (int i = 2; i < 4; ++i) d += grid(2 * i + 1, i, 0) + grid(2 * i + 2, i, 1);
  d += plate(2) + kLoads;
  d += "SEBULK,11,EXTOP4,,MANUAL,,,31\nSECONCT,11,0,,,,,,,\n,5,5,6,6,101,THRU," + last + ",101,\n,THRU," + last + "\nSPOINT,101,THRU," + last + "\n";
  d += "BEGIN SUPER = 11\n" + grid(5, 2, 0) + grid(6, 2, 1) + "EXTRN,5,123456,6,123456\n";
  for (int s = 101; s <= 100 + modes; ++s) d += "EXTRN," + std::to_string(s) + ",0\n";
  return d + "SPOINT,101,THRU," + last + "\nENDDATA\n";
}

// The reduction of the part: interface grids 5 and 6, `modes` fixed-interface modes, dynamics only.
reduction::SuperelementOptions part_options(int modes) {
  reduction::SuperelementOptions o;
  o.interface_ids = {5, 6};
  o.modes.modes = modes;
  o.modes.extra_modes = 0;
  o.modes.backend = linalg::EigenBackend::Dense;
  o.full_mesh = false;
  o.stiffening = false;
  return o;
}

Eigen::Matrix<double, 6, 1> motion(const fem::Model& m, const solutions::StaticSolution& s, int id) {
  Eigen::Matrix<double, 6, 1> u;
  for (int c = 0; c < 6; ++c) u[c] = s.u_g[*fem::find_dof(m, s.dofs, id, c + 1)];
  return u;
}

TEST(ExternalSuperelement, RoundTripThroughOp4EqualsTheWholeModel) {
  const test::TempDir dir;
  const fem::Model part = test::read_deck(part_deck(), "part.bdf");
  reduction::SuperelementOptions o = part_options(0);
  reduction::SuperelementInfo info;
  reduction::reduce_to_superelement(part, o, &info);
  const auto n_interior = static_cast<int>(info.stats.n_interior);
  EXPECT_EQ(info.stats.n_interior, 12) << info.autospc_dofs << " by AUTOSPC";  // grids 3 and 4
  // every mode of the interior: with the lumped mass its translations carry, 6 are finite, and the
  // massless rotations follow them statically in the modes and the constraint modes alike, so the
  // basis holds every motion of the part's dynamics
  o.modes.modes = n_interior;
  const se::Superelement body = reduction::reduce_to_superelement(part, o);
  ASSERT_EQ(body.num_modes, 6);
  const int modes = body.num_modes;
  io::write_op4(body, dir / "part.op4", {false, true});
  dir.write("strip.bdf", external_deck("ASSIGN INPUTT4='part.op4',UNIT=31\n", modes));
  const fem::Model whole = test::read_deck(whole_strip(), "whole.bdf");
  const fem::Model ext = io::read_nastran(dir / "strip.bdf");
  ASSERT_EQ(ext.external_parts.size(), 1u);
  EXPECT_EQ(ext.external_parts[0].dofs.size(), static_cast<std::size_t>(12 + modes));
  const auto sw = solutions::solve_static(whole);
  const auto se = solutions::solve_static(ext);
  double scale = 0, worst = 0;
  for (const int g : {5, 6, 7, 8}) {
    const auto a = motion(whole, sw, g), b = motion(ext, se, g);
    scale = std::max(scale, a.cwiseAbs().maxCoeff());
    worst = std::max(worst, (a - b).cwiseAbs().maxCoeff());
  }
  EXPECT_GT(scale, 1e-6);
  EXPECT_LE(worst, 1e-12 * scale) << worst / scale;  // measured 7.5e-15 (text OP4 with 17 digits)
  const auto mw = solutions::solve_normal_modes(whole);
  const auto me = solutions::solve_normal_modes(ext);
  ASSERT_EQ(mw.eigenvalues.size(), 6);
  ASSERT_EQ(me.eigenvalues.size(), 6);
  for (int k = 0; k < 6; ++k)
    EXPECT_NEAR(me.eigenvalues[k], mw.eigenvalues[k], 1e-12 * mw.eigenvalues[k]) << "mode " << k + 1;  // measured <= 5.4e-15
}

TEST(ExternalSuperelement, SeTestN11AgainstMscNastran) {
  const std::filesystem::path dir = test::data_dir() / "pynastran/se_test_n11";
  const fem::Model m = io::read_nastran(dir / "se_test_n11_static_10_cases.bdf");
  ASSERT_EQ(m.external_parts.size(), 1u);
  EXPECT_EQ(m.external_parts[0].dofs.size(), 105u);  // 11 grids x 6 + 39 modal coordinates
  bool case_warning = false;  // the ASSIGN's incl/SE/SE_TEST_N11.op4 is incl/se/se_test_n11.op4
  for (const auto& w : m.read_warnings) case_warning = case_warning || w.find("differs only in the case") != std::string::npos;
  EXPECT_TRUE(case_warning);
  solutions::StaticOptions so;
  so.ignore_unknown_cards = false;
  const auto sols = solutions::solve_statics(m, so);
  ASSERT_EQ(sols.size(), 10u);
  const fem::ElementResultMap map = fem::make_element_result_map(m, {20110001, 20110002, 20110003});
  ASSERT_EQ(map.entries.size(), 3u);
  std::ifstream in(dir / "se_test_n11_msc_cbush_forces.csv");
  std::string line;
  std::getline(in, line);
  double worst = 0, scale = 0;
  int rows = 0;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string f;
    std::getline(row, f, ',');
    const int subcase = std::stoi(f);
    std::getline(row, f, ',');
    const int eid = std::stoi(f);
    Eigen::Matrix<double, 6, 1> ref;
    for (int c = 0; c < 6; ++c) std::getline(row, f, ','), ref[c] = std::stod(f);
    const auto& s = sols[static_cast<std::size_t>(subcase - 101)];
    ASSERT_EQ(s.selection.subcase_id, subcase);
    const Eigen::VectorXd r = map.apply(s.u_g);
    for (const auto& e : map.entries)
      if (e.id == eid) {
        const Eigen::Matrix<double, 6, 1> got = r.segment<6>(e.row);
        scale = std::max(scale, ref.head<3>().cwiseAbs().maxCoeff());
        worst = std::max(worst, (got - ref).cwiseAbs().maxCoeff());
      }
    ++rows;
  }
  EXPECT_EQ(rows, 9);
  EXPECT_NEAR(scale, 66.409485, 1e-5);
  // measured 3.9e-8 of the largest force: the OP2's single precision (6e-8) and its OP4's 15 digits
  EXPECT_LE(worst, 1e-6 * scale) << worst / scale;
  // the GRAV subcases load nothing, as in MSC's run (OLOAD resultants and CBUSH forces all zero)
  for (const int k : {0, 1, 2, 3, 7, 8, 9}) EXPECT_LE(map.apply(sols[static_cast<std::size_t>(k)].u_g).cwiseAbs().maxCoeff(), 1e-9 * scale);
  // MSC's SSG3 "EXTERNAL WORK" of subcases 105-107 (the f06): u^T p / 2
  const double work[3] = {2.6414675E-04, 2.2541014E-04, 2.3329299E-04};
  for (int k = 0; k < 3; ++k) {
    const auto& s = sols[static_cast<std::size_t>(4 + k)];
    EXPECT_NEAR(0.5 * s.u_g.dot(s.p_g), work[k], 1e-7 * work[k]) << "subcase " << 105 + k;  // measured <= 1.5e-8 (8 digits printed)
  }
}

// GRAV of the bulk data loads the residual's mass only, not the external part's MAA (in Nastran a
// part's loads are its own; se_test_n11 above shows MSC's): on the strip, plate 3 alone. Its total
// mass rho t A = 4400 * 0.01 * 1 = 44 kg (the rigid-body acceleration's resultant is the total mass
// whatever the mass matrix), against 44 + 171 kg if the part's plates 1-2 were loaded too.
TEST(ExternalSuperelement, GravLoadsTheResidualsMassOnly) {
  const test::TempDir dir;
  const fem::Model part = test::read_deck(part_deck(), "part.bdf");
  const se::Superelement body = reduction::reduce_to_superelement(part, part_options(4));
  io::write_op4(body, dir / "part.op4", {false, true});
  std::string deck = external_deck("ASSIGN INPUTT4='part.op4',UNIT=31\n", body.num_modes);
  deck.replace(deck.find("LOAD = 2"), 8, "LOAD = 4");
  deck.insert(deck.find("BEGIN BULK\n") + 11, "GRAV,4,,9.81,0.,0.,-1.\n");
  dir.write("strip.bdf", deck);
  const fem::Model ext = io::read_nastran(dir / "strip.bdf");
  ASSERT_EQ(ext.external_parts.size(), 1u);
  const auto s = solutions::solve_static(ext);
  double fz = 0, other = 0;
  for (const int g : {5, 6, 7, 8})
    for (int c = 1; c <= 6; ++c) {
      const double f = s.p_g[*fem::find_dof(ext, s.dofs, g, c)];
      if (c == 3) fz += f;
      else other = std::max(other, std::abs(f));
    }
  const double weight = 4400. * 0.01 * 1.0 * 9.81;
  EXPECT_NEAR(fz, -weight, 1e-12 * weight);
  EXPECT_LE(other, 1e-12 * weight);  // the plate's lumped mass: no moments, no in-plane force
  for (int q = 101; q <= 100 + body.num_modes; ++q) EXPECT_EQ(s.p_g[*fem::find_dof(ext, s.dofs, q, 0)], 0.0) << "SPOINT " << q;
}

// One 5 x 4 matrix in the OP4 layouts Nastran writes: dense double (seflex's own), sparse single
// (se_test_n11's), sparse double bigmat; the same values back.
TEST(ExternalSuperelement, Op4LayoutsReadBack) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(5, 4);
  A(0, 0) = 1.5, A(1, 0) = -2.25e-3, A(4, 0) = 7e120, A(2, 2) = -3.0, A(3, 2) = 4.0, A(4, 3) = 1e-200;
  const auto dense = io::parse_op4(io::op4_text({{"A", 2, A}}), "dense.op4");
  ASSERT_EQ(dense.size(), 1u);
  EXPECT_EQ(dense[0].name, "A");
  EXPECT_EQ((dense[0].values - A).cwiseAbs().maxCoeff(), 0.0);
  // sparse, single precision: strings headed by IS = (L + 1) * 65536 + IROW, L words
  const std::string sparse =
      "       4       5       2       1A       1P,3E22.15\n"
      "       1       0       5\n"
      "      196609\n"  // L = 2 from row 1
      " 1.500000000000000E+00-2.250000000000000E-03\n"
      "      131077\n"  // L = 1 from row 5
      " 7.000000000000000+120\n"
      "       3       0       3\n"
      "      196611\n"
      "-3.000000000000000E+00 4.000000000000000E+00\n"
      "       4       0       2\n"
      "      131077\n"
      " 1.000000000000000-200\n"
      "       5       1       1\n"
      " 0.000000000000000E+00\n";
  EXPECT_EQ((io::parse_op4(sparse, "sparse.op4")[0].values - A).cwiseAbs().maxCoeff(), 0.0);
  // bigmat (NROW < 0), double precision: "L+1 IROW" with L in words (2 a value)
  const std::string bigmat =
      "       4      -5       2       2A       1P,3D23.16\n"
      "       1       0      10\n"
      "       5       1\n"
      " 1.5000000000000000D+00-2.2500000000000000D-03\n"
      "       3       5\n"
      " 7.0000000000000000+120\n"
      "       3       0       6\n"
      "       5       3\n"
      "-3.0000000000000000D+00 4.0000000000000000D+00\n"
      "       4       0       4\n"
      "       3       5\n"
      " 1.0000000000000000-200\n"
      "       5       1       1\n"
      " 0.0000000000000000D+00\n";
  EXPECT_EQ((io::parse_op4(bigmat, "bigmat.op4")[0].values - A).cwiseAbs().maxCoeff(), 0.0);
  // errors name the file, line and matrix
  EXPECT_TRUE(test::mentions(test::input_error([&] { io::parse_op4(sparse.substr(0, sparse.find("       3       0")), "cut.op4"); }),
                             {"cut.op4:", "OP4 matrix A", "the file ends; expected a column record"}));
  std::string bad = sparse;
  bad.replace(bad.find("-3.000000000000000E+00"), 22, "-3.0000000000000x0E+00");
  EXPECT_TRUE(test::mentions(test::input_error([&] { io::parse_op4(bad, "bad.op4"); }),
                             {"bad.op4:9: OP4 matrix A: column 3, row 3", "expected a real number"}));
  std::string complex = sparse;
  complex.replace(complex.find("       1A"), 9, "       3A");
  EXPECT_TRUE(test::mentions(test::input_error([&] { io::parse_op4(complex, "c.op4"); }), {"c.op4:1: OP4 matrix A: NTYPE 3", "no complex"}));
}

TEST(ExternalSuperelement, Errors) {
  const test::TempDir dir;
  const auto error_of = [&](const std::string& deck) {
    const auto path = dir.write("d.bdf", deck);
    return test::input_error([&] { io::read_nastran(path); });
  };
  // no ASSIGN for the unit
  EXPECT_TRUE(test::mentions(error_of(external_deck("")), {"d.bdf:", "SEBULK 11, field 8 (UNITNO): unit 31 has no ASSIGN INPUTT4"}));
  // the file is missing
  EXPECT_TRUE(test::mentions(error_of(external_deck("ASSIGN INPUTT4='none.op4',UNIT=31\n")),
                             {"d.bdf:1: ASSIGN INPUTT4: the file 'none.op4' does not exist"}));
  // a KAA of another size than the EXTRN points give
  dir.write("small.op4", io::op4_text({{"KAA", 6, Eigen::MatrixXd::Identity(6, 6)}, {"MAA", 6, Eigen::MatrixXd::Identity(6, 6)}}));
  EXPECT_TRUE(test::mentions(error_of(external_deck("ASSIGN INPUTT4='small.op4',UNIT=31\n")),
                             {"small.op4: OP4 matrix KAA is 6 x 6; expected 24 x 24, the a-set of part 11"}));
}

}  // namespace
}  // namespace seflex
