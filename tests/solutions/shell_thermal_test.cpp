// Thermal loads of CQUAD4/CTRIA3 shells (TEMP/TEMPD, PSHELL with MAT1/MAT8 alphas, PCOMP with MAT8
// plies) in linear statics, against references computed here independently of seflex:
// - a free plate heated uniformly expands by alpha dT x with no stress (Timoshenko & Goodier,
//   Theory of Elasticity, 3rd ed., sec. 150: a linear temperature field in a free body is stress
//   free), also for a MAT8 (orthotropic) PSHELL turned by THETA;
// - a plate held at every grid carries N = -E alpha dT t / (1 - nu) (the same, sec. 151: plane
//   stress with eps = 0): the reactions of an edge sum to N times its length;
// - an unsymmetric [0/90] cross-ply PCOMP curls: its mid-plane strains and curvatures follow from
//   classical lamination theory, [A B; B D] [eps0; kappa] = dT [N_T; M_T] (Jones, Mechanics of
//   Composite Materials, 2nd ed., sec. 4.5; Hyer, Stress Analysis of Fiber-Reinforced Composite
//   Materials, ch. 11), written out here in closed form for a two-ply cross-ply;
// - Nastran's element temperature of a shell is the mean of its grids' temperatures (QRG TEMP,
//   without TEMPPi): one element with two hot and two cold grids expands by the mean;
// - `seflex static` on a heated quasi-isotropic [0/45/-45/90]s PCOMP (MYSTRAN's VD0114 laminate):
//   free expansion by alpha_eff dT with alpha_eff = [(Q11 + Q12) a1 + (Q12 + Q22) a2] / (Q11 + Q22 + 2 Q12)
//   (the isotropic part of N_T over the isotropic A11 + A12 = T (U1 + U4); Jones ch. 4).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "nastran_test_util.hpp"
#include "statics_test_util.hpp"
#include "seflex/fem/loads.hpp"
#include "seflex/solutions/statics.hpp"
#include "test_support.hpp"

namespace seflex {
namespace {

using test::num;

constexpr auto u = test::displacement;

/// A plate [0, a] x [0, b] in the x-y plane of n x n CQUAD4 (tria: 2 n^2 CTRIA3), property 1, grid
/// id 1 + i + (n + 1) j; the interior grids moved by `skew` (a fraction of the cell) to distort the
/// mesh. Temperatures and the rest of the bulk data in `more`.
std::string plate(int n, double a, double b, bool tria, double skew, const std::string& case_control,
                  const std::string& more) {
  std::string d = "SOL 101\nCEND\n" + case_control + "BEGIN BULK\n" + more;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = a * i / n, y = b * j / n;
      if (i > 0 && i < n && j > 0 && j < n) x += skew * a / n * ((i + j) % 2 ? 1 : -1), y += 0.5 * skew * b / n;
      d += "GRID," + std::to_string(1 + i + (n + 1) * j) + ",," + num(x) + "," + num(y) + ",0.\n";
    }
  int eid = 1;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int g1 = 1 + i + (n + 1) * j, g2 = g1 + 1, g3 = g2 + n + 1, g4 = g1 + n + 1;
      if (tria) {
        d += "CTRIA3," + std::to_string(eid++) + ",1," + std::to_string(g1) + "," + std::to_string(g2) + "," + std::to_string(g3) + "\n";
        d += "CTRIA3," + std::to_string(eid++) + ",1," + std::to_string(g1) + "," + std::to_string(g3) + "," + std::to_string(g4) + "\n";
      } else {
        d += "CQUAD4," + std::to_string(eid++) + ",1," + std::to_string(g1) + "," + std::to_string(g2) + "," +
             std::to_string(g3) + "," + std::to_string(g4) + "\n";
      }
    }
  return d + "ENDDATA\n";
}

/// `d` with `fields` appended to every CQUAD4 and CTRIA3 line (e.g. ",90." for THETA, ",0" for MCID 0:
/// the material x axis is the projected basic x axis, not each element's G1-G2 edge).
std::string with_element_fields(std::string d, const std::string& fields) {
  for (const char* card : {"CQUAD4", "CTRIA3"})
    for (std::size_t k = d.find(card); k != std::string::npos; k = d.find(card, k + 1)) d.insert(d.find('\n', k), fields);
  return d;
}

constexpr double E = 7.0e10, nu = 0.3, alpha = 2.3e-5, tref = 20.0, t = 2.0e-3;
const std::string kAluminium = "MAT1,1,7.e10,,0.3,2700.,2.3e-5,20.\nPSHELL,1,1,2.e-3,1,,1\n";

// Free plate (grid 1 at the origin held in all six components: it removes the rigid-body motion
// and nothing of the free expansion), TEMPD 120: u = alpha dT x, v = alpha dT y, w = 0 at every grid,
// no reaction, on a distorted mesh of quads and of triangles.
TEST(ShellThermalLoad, FreePlateExpandsWithoutStress) {
  const int n = 3;
  for (const bool tria : {false, true}) {
    const fem::Model m =
        test::read_deck(plate(n, 0.3, 0.2, tria, 0.2, "SPC = 1\nTEMPERATURE(LOAD) = 5\n", kAluminium + "SPC1,1,123456,1\nTEMPD,5,120.\n"));
    const auto s = solutions::solve_static(m);
    const double e = alpha * 100.0;
    for (const auto& g : m.grids) {
      EXPECT_NEAR(u(m, s, g.id, 1), e * g.x_basic.x(), 1e-12) << (tria ? "CTRIA3" : "CQUAD4") << " grid " << g.id;
      EXPECT_NEAR(u(m, s, g.id, 2), e * g.x_basic.y(), 1e-12) << (tria ? "CTRIA3" : "CQUAD4") << " grid " << g.id;
      EXPECT_NEAR(u(m, s, g.id, 3), 0.0, 1e-12);
      for (int c = 4; c <= 6; ++c) EXPECT_NEAR(u(m, s, g.id, c), 0.0, 1e-10);
    }
    EXPECT_LT(s.q_g.cwiseAbs().maxCoeff(), 1e-9 * E * t * e * 0.3);  // stress free: no reaction
  }
}

// Every grid held: the load is the plate's restrained thermal force, N = E alpha dT t / (1 - nu) per
// unit length of edge, outward; the interior grids of a regular mesh carry none.
TEST(ShellThermalLoad, ClampedPlateCarriesThePlaneStressThermalForce) {
  const int n = 4;
  const double a = 0.4, b = 0.2, dT = 80.0;
  std::string spc = "SPC1,1,123456,1,THRU," + std::to_string((n + 1) * (n + 1)) + "\n";
  for (const bool tria : {false, true}) {
    const fem::Model m = test::read_deck(
        plate(n, a, b, tria, 0.0, "SPC = 1\nTEMP(LOAD) = 5\n", kAluminium + spc + "TEMPD,5," + num(tref + dT) + "\n"));
    const auto s = solutions::solve_static(m);
    const double N = E * alpha * dT * t / (1.0 - nu);
    double right = 0, top = 0, interior = 0;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const int g = 1 + i + (n + 1) * j;
        const double px = s.p_g[*fem::find_dof(m, s.dofs, g, 1)], py = s.p_g[*fem::find_dof(m, s.dofs, g, 2)];
        if (i == n) right += px;
        if (j == n) top += py;
        if (i > 0 && i < n && j > 0 && j < n) interior = std::max({interior, std::abs(px), std::abs(py)});
      }
    EXPECT_NEAR(right / (N * b), 1.0, 1e-12) << (tria ? "CTRIA3" : "CQUAD4");
    EXPECT_NEAR(top / (N * a), 1.0, 1e-12) << (tria ? "CTRIA3" : "CQUAD4");
    EXPECT_LT(interior, 1e-9 * N * a);
    EXPECT_NEAR(s.q_g.sum() + s.p_g.sum(), 0.0, 1e-9 * N * a);  // the reactions hold it
  }
}

// A PSHELL of a MAT8 (A1 along the material 1 axis, A2 along 2) turned by THETA = 90 degrees: the
// plate expands by A2 dT along x and A1 dT along y. TREF is the material's.
TEST(ShellThermalLoad, OrthotropicPshellExpandsAlongItsMaterialAxes) {
  const double a1 = -0.5e-6, a2 = 30.0e-6, dT = 50.0;
  const fem::Model m = test::read_deck(with_element_fields(
      plate(2, 0.2, 0.2, false, 0.0, "SPC = 1\nTEMP = 5\n",
            "MAT8,8,140.e9,10.e9,.3,5.e9,,,1600.,+M\n+M,-0.5e-6,30.e-6,-10.\nPSHELL,1,8,1.e-3,8\n"
            "SPC1,1,123456,1\nTEMPD,5,40.\n"),
      ",90."));
  const auto s = solutions::solve_static(m);
  for (const auto& g : m.grids) {
    EXPECT_NEAR(u(m, s, g.id, 1), a2 * dT * g.x_basic.x(), 1e-13) << g.id;
    EXPECT_NEAR(u(m, s, g.id, 2), a1 * dT * g.x_basic.y(), 1e-13) << g.id;
  }
}

// [0/90] T300/5208 (Tsai & Hahn values as in Jones, table 2-3: E1 181 GPa, E2 10.3 GPa, nu12 0.28,
// G12 7.17 GPa; alpha1 0.02e-6, alpha2 22.5e-6), plies 0.125 mm, cooled by 150 K from TREF. With
// Q11, Q12, Q22 the ply's reduced stiffnesses and h the ply thickness (0 degree ply below the
// mid-plane), classical lamination theory gives
//   A11 = A22 = (Q11 + Q22) h, A12 = 2 Q12 h;  B11 = -B22 = (Q22 - Q11) h^2 / 2, B12 = 0;
//   D11 = D22 = (Q11 + Q22) h^3 / 3, D12 = 2 Q12 h^3 / 3;
//   N_T = h (Q11 a1 + Q12 a2 + Q22 a2 + Q12 a1) (1, 1);
//   M_T = h^2 / 2 (Q22 a2 + Q12 a1 - Q11 a1 - Q12 a2) (1, -1);
// and the free plate (held at the origin grid, which the free deformation leaves in place) takes
// u = eps_x x, v = eps_y y, w = -(k_x x^2 + k_y y^2) / 2 (a saddle: k_y = -k_x).
TEST(ShellThermalLoad, UnsymmetricCrossPlyCurlsAsLaminationTheory) {
  const double E1 = 181e9, E2 = 10.3e9, nu12 = 0.28, G12 = 7.17e9, a1 = 0.02e-6, a2 = 22.5e-6, h = 0.125e-3;
  const double dT = -150.0;
  for (const bool tria : {false, true}) {
    // MCID 0: every element's laminate x axis is the basic x axis (a distorted mesh or a triangle's
    // G1-G2 edge would turn it element by element)
    const fem::Model m = test::read_deck(with_element_fields(
        plate(4, 0.1, 0.1, tria, 0.15, "SPC = 1\nTEMP = 5\n",
              "MAT8,8,181.e9,10.3e9,.28,7.17e9,,,1600.,+M\n+M,0.02e-6,22.5e-6,999.\n"
              "PCOMP,1,,,,,170.,,,+P\n+P,8,0.125e-3,0.,,8,0.125e-3,90.\n"
              "SPC1,1,123456,1\nTEMPD,5,20.\n"),
        ",0"));
    const auto s = solutions::solve_static(m);
    const double den = 1.0 - nu12 * nu12 * E2 / E1;
    const double Q11 = E1 / den, Q22 = E2 / den, Q12 = nu12 * E2 / den;
    (void)G12;
    Eigen::Matrix4d ABD;  // rows: N_x, N_y, M_x, M_y; columns: eps_x, eps_y, k_x, k_y
    const double A11 = (Q11 + Q22) * h, A12 = 2 * Q12 * h, B11 = (Q22 - Q11) * h * h / 2;
    const double D11 = (Q11 + Q22) * h * h * h / 3, D12 = 2 * Q12 * h * h * h / 3;
    ABD << A11, A12, B11, 0, A12, A11, 0, -B11, B11, 0, D11, D12, 0, -B11, D12, D11;
    const double NT = h * (Q11 * a1 + Q12 * a2 + Q22 * a2 + Q12 * a1), MT = h * h / 2 * (Q22 * a2 + Q12 * a1 - Q11 * a1 - Q12 * a2);
    const Eigen::Vector4d ek = ABD.lu().solve(dT * Eigen::Vector4d(NT, NT, MT, -MT));
    double w_max = 0;
    for (const auto& g : m.grids) {
      const double x = g.x_basic.x(), y = g.x_basic.y();
      const double w = -(ek[2] * x * x + ek[3] * y * y) / 2;
      w_max = std::max(w_max, std::abs(w));
      EXPECT_NEAR(u(m, s, g.id, 1), ek[0] * x, 1e-7 * std::abs(ek[0]) * 0.1) << g.id;
      EXPECT_NEAR(u(m, s, g.id, 2), ek[1] * y, 1e-7 * std::abs(ek[1]) * 0.1) << g.id;
      EXPECT_NEAR(u(m, s, g.id, 3), w, 1e-7 * std::abs(ek[2]) * 0.01) << (tria ? "CTRIA3" : "CQUAD4") << " grid " << g.id;
      EXPECT_NEAR(u(m, s, g.id, 4), -ek[3] * y, 1e-7 * std::abs(ek[3]) * 0.1) << g.id;  // theta_x = w,y
      EXPECT_NEAR(u(m, s, g.id, 5), ek[2] * x, 1e-7 * std::abs(ek[2]) * 0.1) << g.id;   // theta_y = -w,x
    }
    EXPECT_GT(w_max, 1e-4);  // it does curl (0.1 m plate: about a millimetre)
    EXPECT_NEAR(ek[3], -ek[2], 1e-12 * std::abs(ek[2]));
  }
}

// The element temperature of a shell is the mean of its grids' (TEMP for two grids, TEMPD for the
// other two): one CQUAD4 expands by alpha (mean - TREF).
TEST(ShellThermalLoad, ElementTemperatureIsTheMeanOfItsGrids) {
  const fem::Model m = test::read_deck(plate(1, 0.1, 0.1, false, 0.0, "SPC = 1\nTEMP = 5\n",
                                             kAluminium + "SPC1,1,123456,1\nTEMP,5,2,120.,3,120.\nTEMPD,5,40.\n"));
  const auto s = solutions::solve_static(m);
  EXPECT_NEAR(u(m, s, 2, 1) / (alpha * (80.0 - tref) * 0.1), 1.0, 1e-9);
  EXPECT_NEAR(u(m, s, 4, 2) / (alpha * (80.0 - tref) * 0.1), 1.0, 1e-9);
}

// A heated PSHELL whose MID4 (membrane-bending coupling) expands is refused, naming the card.
TEST(ShellThermalLoad, Mid4WithThermalExpansionIsRefused) {
  const fem::Model m = test::read_deck(plate(1, 0.1, 0.1, false, 0.0, "SPC = 1\nTEMP = 5\n",
                                             "MAT1,1,7.e10,,0.3,2700.,2.3e-5,20.\nMAT1,4,7.e9,,0.3,0.,1.e-5,20.\n"
                                             "PSHELL,1,1,2.e-3,1,,1,,,+P\n+P,,,4\nSPC1,1,123456,1\nTEMPD,5,120.\n"));
  try {
    solutions::solve_static(m);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("deck.bdf:16: CQUAD4: thermal load set 5 gives a temperature to shells whose PSHELL MID4 "
                       "(membrane-bending coupling) has thermal expansion, and seflex does not compute the thermal "
                       "moment of MID4"),
              std::string::npos)
        << msg;
  }
  // the library's thermal load refuses it too (MID1 here has ALPHA as well; also without it)
  for (const char* mat1 : {"MAT1,1,7.e10,,0.3,2700.,2.3e-5,20.\n", "MAT1,1,7.e10,,0.3,2700.\n"}) {
    const fem::Model l = test::read_deck(plate(1, 0.1, 0.1, false, 0.0, "SPC = 1\nTEMP = 5\n",
                                               std::string(mat1) + "MAT1,4,7.e9,,0.3,0.,1.e-5,20.\n"
                                               "PSHELL,1,1,2.e-3,1,,1,,,+P\n+P,,,4\nSPC1,1,123456,1\nTEMPD,5,120.\n"));
    try {
      fem::thermal_load_vector(l, fem::make_dof_map(l), 5);
      ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find("deck.bdf:16: CQUAD4 1"), std::string::npos) << msg;
      EXPECT_NE(msg.find("thermal load set 5 heats it and its PSHELL 1 has a MID4 (membrane-bending coupling) material "
                         "with thermal expansion"),
                std::string::npos)
          << msg;
      EXPECT_NE(msg.find("expected ALPHA blank on MID4's material"), std::string::npos) << msg;
    }
  }
}

// A heated shell with a grid that the set gives no temperature (no TEMP for it, no TEMPD): refused,
// naming the element and the grid.
TEST(ShellThermalLoad, GridWithoutTemperatureIsRefused) {
  const fem::Model m = test::read_deck(
      plate(1, 0.1, 0.1, false, 0.0, "SPC = 1\nTEMP = 5\n", kAluminium + "SPC1,1,123456,1\nTEMP,5,1,50.,2,50.,3,50.\n"));
  try {
    solutions::solve_static(m);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("CQUAD4 1"), std::string::npos) << msg;
    EXPECT_NE(msg.find("GRID 4 has no temperature in thermal load set 5 (no TEMP card gives it and no TEMPD)"),
              std::string::npos)
        << msg;
  }
}

// The command line runs a heated laminate (before: refused): VD0114's [0/45/-45/90]s graphite/epoxy
// (MAT8 E1 2.03e7, E2 1.49e6, NU12 .29, A1 .7e-6, A2 31.2e-6; PCOMP TREF 30, SYM), a 100 x 100 plate of
// 3 x 3 CQUAD4 held at one corner in 1-2 and along the edge x = 0 in 1, TEMPD 100: the far corner
// moves by alpha_eff 70 x 100 in x and y.
TEST(ShellThermalLoad, CommandLineExpandsAQuasiIsotropicLaminate) {
  std::string d = "SOL 101\nCEND\nSPC = 200\nSUBCASE 2\n  TEMP(LOAD) = 200\nBEGIN BULK\n"
                  "MAT8,210,2.03+7,1.49+6,.29,74.7+4,1.E+15,1.E+15,0.1,+MA1\n+MA1,0.7E-6,31.2E-6,30.0\n"
                  "PCOMP,200,-0.5,,1.23+4,TSAI,30.,,SYM,+P1\n+P1,210,0.125,0.,,210,0.125,45.,,+P2\n"
                  "+P2,210,0.125,-45.,,210,0.125,90.\nTEMPD,200,100.\nSPC1,200,1345,5,9,13\nSPC1,200,12345,1\n";
  for (int j = 0; j <= 3; ++j)
    for (int i = 0; i <= 3; ++i)
      d += "GRID," + std::to_string(1 + i + 4 * j) + ",," + num(100.0 * i / 3) + "," + num(100.0 * j / 3) + ",0.,,6\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const int g = 1 + i + 4 * j;
      d += "CQUAD4," + std::to_string(1 + i + 3 * j) + ",200," + std::to_string(g) + "," + std::to_string(g + 1) + "," +
           std::to_string(g + 5) + "," + std::to_string(g + 4) + "\n";
    }
  d += "ENDDATA\n";
  test::TempDir dir;
  dir.write("qi.bdf", d);
  const auto r = test::run_seflex("static qi.bdf -o u.csv", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double E1 = 2.03e7, E2 = 1.49e6, nu12 = .29, a1 = .7e-6, a2 = 31.2e-6;
  const double den = 1 - nu12 * nu12 * E2 / E1, Q11 = E1 / den, Q22 = E2 / den, Q12 = nu12 * E2 / den;
  const double alpha_eff = ((Q11 + Q12) * a1 + (Q12 + Q22) * a2) / (Q11 + Q22 + 2 * Q12);
  bool found = false;
  for (const auto& row : test::csv_rows(dir / "u.csv"))  // grid, t1, t2, t3, r1, r2, r3
    if (row[0] == 16.0) {
      found = true;
      EXPECT_NEAR(row[1] / (alpha_eff * 70 * 100), 1.0, 1e-9);
      EXPECT_NEAR(row[2] / (alpha_eff * 70 * 100), 1.0, 1e-9);
      EXPECT_NEAR(row[3], 0.0, 1e-12);  // symmetric laminate: no curvature
    }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace seflex
