// CQUAD8 (MITC9 plate) and CTRIA6 (MITC7 plate), quadratic membranes: the simply supported square
// plate under uniform pressure against Navier's series (Timoshenko & Woinowsky-Krieger, Theory of
// Plates and Shells, 2nd ed., sec. 30; the Mindlin series adds the shear term 1 / (k G t lambda^2)
// per harmonic), thin (MID3 blank: the Kirchhoff penalty must not lock) and thick (t/a = 0.1), at
// three mesh sizes with the measured convergence rate asserted; membrane and bending patch tests
// on distorted meshes with blank mid-side grids; rigid-body modes of warped, curved elements; the
// mass; the reader's field layout through the writer and back; refusals by their whole message.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include "assembly_test_util.hpp"
#include "nastran_test_util.hpp"
#include "statics_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_common.hpp"
#include "seflex/fem/element_shell_quadratic.hpp"
#include "seflex/fem/mass_properties.hpp"
#include "seflex/io/nastran_writer.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

using test::num;
constexpr double kPi = 3.14159265358979323846;
constexpr double E = 2.1e11, nu = 0.3, a = 1.0, q = 1.0e3;

/// Centre deflection of the simply supported square plate (side a) under pressure q: Navier's double
/// series, with the transverse shear term of the Mindlin plate when shear_Gt > 0 (k G t, k = 5/6).
double navier_centre(double t, double shear_kGt) {
  const double D = E * t * t * t / (12 * (1 - nu * nu));
  double w = 0;
  for (int m = 1; m < 400; m += 2)
    for (int n = 1; n < 400; n += 2) {
      const double lam2 = kPi * kPi * (m * m + n * n) / (a * a);
      const double sign = ((m + n) / 2 - 1) % 2 == 0 ? 1.0 : -1.0;  // sin(m pi/2) sin(n pi/2), m and n odd
      double c = 1.0 / (D * lam2 * lam2);
      if (shear_kGt > 0) c += 1.0 / (shear_kGt * lam2);
      w += sign * 16 * q / (kPi * kPi * m * n) * c;
    }
  return w;
}

/// An N x N mesh of the plate: CQUAD8 (tri = false) or two CTRIA6 per square; grid (i, j) of the
/// (2N+1)^2 lattice has id 1000 i + j + 1; edges simply supported (w = 0; the tangential rotation
/// held: theta_x on x = 0, a; theta_y on y = 0, a), the membrane held at one corner; PLOAD2 q.
std::string plate_deck(int N, bool tri, double t, bool mid3) {
  std::ostringstream d;
  d << "SOL 101\nCEND\nSPC = 1\nLOAD = 2\nBEGIN BULK\nMAT1,3," << num(E) << ",," << num(nu) << ",7800.\n";
  d << "PSHELL,7,3," << num(t) << ",3,," << (mid3 ? "3" : "") << "\n";
  const int L = 2 * N;
  auto id = [](int i, int j) { return 1000 * i + j + 1; };
  for (int i = 0; i <= L; ++i)
    for (int j = 0; j <= L; ++j) {
      d << "GRID," << id(i, j) << ",," << num(a * i / L) << "," << num(a * j / L) << ",0.\n";
      std::string c;
      if (i == 0 || i == L) c += "34";
      if (j == 0 || j == L) c += (c.empty() ? "35" : "5");
      if (!c.empty()) d << "SPC1,1," << c << "," << id(i, j) << "\n";
    }
  d << "SPC1,1,126," << id(0, 0) << "\nSPC1,1,2," << id(L, 0) << "\n";
  int eid = 1;
  for (int i = 0; i < L; i += 2)
    for (int j = 0; j < L; j += 2) {
      const int c1 = id(i, j), c2 = id(i + 2, j), c3 = id(i + 2, j + 2), c4 = id(i, j + 2);
      const int m12 = id(i + 1, j), m23 = id(i + 2, j + 1), m34 = id(i + 1, j + 2), m41 = id(i, j + 1), mc = id(i + 1, j + 1);
      if (!tri) {
        d << "CQUAD8," << eid << ",7," << c1 << "," << c2 << "," << c3 << "," << c4 << "," << m12 << "," << m23 << "\n," << m34
          << "," << m41 << "\n";
        d << "PLOAD2,2," << num(q) << "," << eid++ << "\n";
      } else {
        d << "CTRIA6," << eid << ",7," << c1 << "," << c2 << "," << c3 << "," << m12 << "," << m23 << "," << mc << "\n";
        d << "PLOAD2,2," << num(q) << "," << eid++ << "\n";
        d << "CTRIA6," << eid << ",7," << c1 << "," << c3 << "," << c4 << "," << mc << "," << m34 << "," << m41 << "\n";
        d << "PLOAD2,2," << num(q) << "," << eid++ << "\n";
      }
    }
  d << "ENDDATA\n";
  return d.str();
}

double centre_deflection(int N, bool tri, double t, bool mid3) {
  const fem::Model m = test::read_deck(plate_deck(N, tri, t, mid3));
  const auto s = solutions::solve_static(m);
  return test::displacement(m, s, 1000 * N + N + 1, 3);
}

// Errors of the centre deflection at N = 2, 4, 8 and the observed rates log2(e(N) / e(2N)), measured
// (this build, relative errors at N = 2, 4, 8):
//   CQUAD8 thin (t/a = 1e-3, MID3 blank)  3.24e-2 1.65e-3 9.72e-5: rates 4.29, 4.09
//   CTRIA6 thin                            5.76e-2 5.60e-3 5.43e-4: rates 3.36, 3.37
//   CQUAD8 thick (t/a = 0.1, Mindlin)      3.06e-2 1.55e-3 9.12e-5: rates 4.31, 4.08
//   CTRIA6 thick                           3.62e-2 1.88e-3 8.73e-5: rates 4.27, 4.43
// The centre deflection of these quadratic elements converges at O(h^4) (CTRIA6's crossed mesh of
// a thin plate at O(h^3.4)), no slower in the thin plate than in the thick one: no shear locking.
// Asserted: the smaller measured rate less 0.3; the finest error below 1.5 times the measured one.
TEST(QuadraticShell, SimplySupportedPlateConvergesAtItsOrder) {
  struct Case {
    bool tri;
    double t;
    bool mid3;
    double min_rate, max_error;
  };
  const Case cases[] = {{false, 0.001, false, 3.79, 1.5e-4}, {true, 0.001, false, 3.06, 8.2e-4},
                        {false, 0.1, true, 3.78, 1.4e-4},   {true, 0.1, true, 3.97, 1.3e-4}};
  for (const Case& c : cases) {
    const double w_ref = c.mid3 ? navier_centre(c.t, 5.0 / 6.0 * E / (2 * (1 + nu)) * c.t) : navier_centre(c.t, 0.0);
    double e[3];
    for (int k = 0; k < 3; ++k) e[k] = std::abs(centre_deflection(2 << k, c.tri, c.t, c.mid3) / w_ref - 1);
    const double r1 = std::log2(e[0] / e[1]), r2 = std::log2(e[1] / e[2]);
    EXPECT_GT(r1, c.min_rate) << (c.tri ? "CTRIA6" : "CQUAD8") << " t = " << c.t << " errors " << e[0] << " " << e[1] << " " << e[2];
    EXPECT_GT(r2, c.min_rate) << (c.tri ? "CTRIA6" : "CQUAD8") << " t = " << c.t << " errors " << e[0] << " " << e[1] << " " << e[2];
    EXPECT_LT(e[2], c.max_error) << (c.tri ? "CTRIA6" : "CQUAD8") << " t = " << c.t;
  }
}


// A distorted patch of four CQUAD8 (the inner grid moved, one mid-side grid blank) or eight CTRIA6:
// the boundary grids given the displacements of a constant membrane strain and of a constant
// curvature (w quadratic, the Kirchhoff rotations theta_x = w,y, theta_y = -w,x), the inner ones
// free: they must follow the same fields exactly (patch test).
std::string patch_deck(bool tri, bool bending) {
  // lattice 5 x 5 of grids (0..4)^2 on [0, 2]^2, the centre corner grid moved to (1.1, 0.9)
  std::ostringstream d;
  d << "SOL 101\nCEND\nSPC = 1\nBEGIN BULK\nMAT1,3," << num(E) << ",," << num(nu) << "\nPSHELL,7,3,0.01,3,,3\n";
  auto id = [](int i, int j) { return 100 * i + j + 1; };
  std::map<int, Eigen::Vector2d> x;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) x[id(i, j)] = Eigen::Vector2d(0.5 * i, 0.5 * j);
  x[id(2, 2)] = {1.1, 0.9};                                   // corner grid of all four quadrilaterals
  for (const auto& [m, c] : std::map<int, std::pair<int, int>>{{id(1, 2), {id(0, 2), id(2, 2)}}, {id(3, 2), {id(2, 2), id(4, 2)}},
                                                              {id(2, 1), {id(2, 0), id(2, 2)}}, {id(2, 3), {id(2, 2), id(2, 4)}}})
    x[m] = 0.5 * (x[c.first] + x[c.second]);                  // mid-side grids on the straight edges
  for (int i = 1; i <= 3; i += 2)  // the triangles' diagonals (corner i-1, j-1 to i+1, j+1): straight
    for (int j = 1; j <= 3; j += 2) {
      if (tri) x[id(i, j)] = 0.5 * (x[id(i - 1, j - 1)] + x[id(i + 1, j + 1)]);
      else x.erase(id(i, j));  // no element holds the centre of a quadrilateral
    }
  // the exact fields: membrane u = 1e-3 (x + 0.5 y), v = 1e-3 (-0.3 x + 2 y), drilling theta_z = the
  // membrane rotation (v,x - u,y)/2 = -0.4e-3; plate w = 1e-3 (x^2 + x y + 2 y^2) with the Kirchhoff
  // rotations theta_x = w,y, theta_y = -w,x
  for (const auto& [g, p] : x) {
    d << "GRID," << g << ",," << num(p.x()) << "," << num(p.y()) << ",0.\n";
    const bool boundary = std::abs(p.x()) < 1e-12 || std::abs(p.y()) < 1e-12 || std::abs(p.x() - 2) < 1e-12 || std::abs(p.y() - 2) < 1e-12;
    const double X = p.x(), Y = p.y();
    if (boundary) {
      if (bending) {
        const double val[3] = {1e-3 * (X * X + X * Y + 2 * Y * Y), 1e-3 * (X + 4 * Y), -1e-3 * (2 * X + Y)};
        for (int c = 0; c < 3; ++c) d << "SPC,1," << g << "," << c + 3 << "," << num(val[c]) << "\n";
      } else {
        const double val[3] = {1e-3 * (X + 0.5 * Y), 1e-3 * (-0.3 * X + 2 * Y), -0.4e-3};
        const int comp[3] = {1, 2, 6};
        for (int c = 0; c < 3; ++c) d << "SPC,1," << g << "," << comp[c] << "," << num(val[c]) << "\n";
      }
    }
    d << "SPC1,1," << (bending ? "126" : "345") << "," << g << "\n";  // the other part held
  }
  int eid = 1;
  for (int i = 0; i < 4; i += 2)
    for (int j = 0; j < 4; j += 2) {
      const int c1 = id(i, j), c2 = id(i + 2, j), c3 = id(i + 2, j + 2), c4 = id(i, j + 2);
      const int m12 = id(i + 1, j), m23 = id(i + 2, j + 1), m34 = id(i + 1, j + 2), m41 = id(i, j + 1), mc = id(i + 1, j + 1);
      if (!tri) {  // membrane: the first element leaves the mid-side grid of its edge 4-1 on the patch's boundary
        // blank (a linear field is still exact; on an inner edge the neighbour would be incompatible)
        const std::string g8 = eid == 1 && !bending ? std::string("") : std::to_string(m41);
        d << "CQUAD8," << eid << ",7," << c1 << "," << c2 << "," << c3 << "," << c4 << "," << m12 << "," << m23 << "\n," << m34
          << "," << g8 << "\n";
        ++eid;
      } else {
        d << "CTRIA6," << eid++ << ",7," << c1 << "," << c2 << "," << c3 << "," << m12 << "," << m23 << "," << mc << "\n";
        d << "CTRIA6," << eid++ << ",7," << c1 << "," << c3 << "," << c4 << "," << mc << "," << m34 << "," << m41 << "\n";
      }
    }
  d << "ENDDATA\n";
  return d.str();
}

TEST(QuadraticShell, MembraneAndBendingPatchTests) {
  for (const bool tri : {false, true})
    for (const bool bending : {false, true}) {
      const fem::Model m = test::read_deck(patch_deck(tri, bending));
      const auto s = solutions::solve_static(m);
      double worst = 0;
      for (const fem::Grid& g : m.grids) {
        const double X = g.x_basic.x(), Y = g.x_basic.y();
        const double u[6] = {bending ? 0.0 : 1e-3 * (X + 0.5 * Y), bending ? 0.0 : 1e-3 * (-0.3 * X + 2 * Y),
                             bending ? 1e-3 * (X * X + X * Y + 2 * Y * Y) : 0.0, bending ? 1e-3 * (X + 4 * Y) : 0.0,
                             bending ? -1e-3 * (2 * X + Y) : 0.0, bending ? 0.0 : -0.4e-3};
        for (int c = 0; c < 6; ++c) worst = std::max(worst, std::abs(test::displacement(m, s, g.id, c + 1) - u[c]));
      }
      EXPECT_LT(worst, 1e-13) << (tri ? "CTRIA6" : "CQUAD8") << (bending ? " bending" : " membrane");
    }
}

// Warped, curved elements (mid-side grids off the chords and out of the plane), some mid-side grids
// blank: the six rigid-body motions are force-free; one element alone has exactly six.
TEST(QuadraticShell, RigidBodyModesOfWarpedCurvedElements) {
  fem::QuadraticShellElement e;
  e.corners = 4;
  e.x = {Eigen::Vector3d(0, 0, 0.02), Eigen::Vector3d(1.1, 0.1, -0.02), Eigen::Vector3d(1.0, 0.9, 0.02), Eigen::Vector3d(-0.1, 1.0, -0.02),
         Eigen::Vector3d(0.55, 0.0, 0.01), Eigen::Vector3d(1.1, 0.5, 0.0), Eigen::Vector3d(0.45, 0.97, 0.0), Eigen::Vector3d(0, 0, 0)};
  e.has_mid = {true, true, true, false};
  e.x[7] = 0.5 * (e.x[3] + e.x[0]);
  const fem::Model m = test::read_deck("MAT1,3," + num(E) + ",," + num(nu) + ",7800.\nPSHELL,7,3,0.01,3,,3\n");
  fem::Shell sh;
  sh.pid = 7;
  sh.nnode = 4;
  e.section = fem::make_shell_section(m, sh);
  for (const int corners : {4, 3}) {
    fem::QuadraticShellElement el = e;
    el.corners = corners;
    if (corners == 3) {
      el.x = {Eigen::Vector3d(0, 0, 0.02), Eigen::Vector3d(1.1, 0.1, -0.02), Eigen::Vector3d(0.2, 0.9, 0.0),
              Eigen::Vector3d(0.55, 0.02, 0.0), Eigen::Vector3d(0.65, 0.5, 0.01), Eigen::Vector3d(0.1, 0.45, 0.01),
              Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
      el.has_mid = {true, false, true, false};
      el.x[4] = 0.5 * (el.x[1] + el.x[2]);
    }
    const fem::NodeMatrix<8> K = fem::quadratic_shell_stiffness(el, 100.0);
    std::array<Eigen::Vector3d, 8> x = el.x;
    const Eigen::Matrix<double, 48, 6> R = fem::rigid_body_modes<8>(x, Eigen::Vector3d(0.3, 0.4, 0.1));
    EXPECT_LT((K * R).norm(), 1e-10 * K.norm()) << corners;
    // zero eigenvalues of the grids present: exactly the six rigid-body motions
    std::vector<int> rows;
    for (int k = 0; k < 2 * corners; ++k)
      if (k < corners || el.has_mid[static_cast<std::size_t>(k - corners)])
        for (int c = 0; c < 6; ++c) rows.push_back(6 * k + c);
    Eigen::MatrixXd Kp(rows.size(), rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (std::size_t j = 0; j < rows.size(); ++j) Kp(i, j) = K(rows[i], rows[j]);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Kp);
    int zero = 0;
    for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) zero += es.eigenvalues()[i] < 1e-9 * es.eigenvalues().maxCoeff();
    EXPECT_EQ(zero, 6) << corners << " corners: " << es.eigenvalues().head(8).transpose();
  }
}

// Mass (rho t + NSM) A lumped (HRZ: all diagonal entries positive) and coupled; CG at the centre.
TEST(QuadraticShell, Mass) {
  for (const bool tri : {false, true}) {
    fem::Model m = test::read_deck(plate_deck(2, tri, 0.01, true));
    const double mass = 7800.0 * 0.01 * a * a;
    EXPECT_NEAR(fem::mass_properties(m).mass, mass, 1e-12 * mass);
    EXPECT_LT((fem::mass_properties(m).cg - Eigen::Vector3d(a / 2, a / 2, 0)).norm(), 1e-14);
    const Eigen::MatrixXd M(fem::assemble(m, fem::assembly_options(m)).M);
    EXPECT_GT(M.diagonal().minCoeff(), -1e-30);
    m.params.push_back({"COUPMASS", {"1"}, {}});
    EXPECT_NEAR(fem::mass_properties(m).mass, mass, 1e-12 * mass);
  }
}

// The fields of CQUAD8 (T1-T4 line 2, THETA/MCID, ZOFFS, TFLAG line 3) and CTRIA6, through the
// writer and back.
TEST(QuadraticShell, FieldsThroughTheWriter) {
  const std::string base = "MAT1,3,2.1+11,,0.3\nPSHELL,7,3,0.01,3\nGRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,1.,1.,0.\n"
                           "GRID,4,,0.,1.,0.\nGRID,5,,0.5,0.,0.\nGRID,6,,1.,0.5,0.\nGRID,8,,0.,0.5,0.\n";
  const fem::Model m = test::read_deck(base + "CQUAD8,9,7,1,2,3,4,5,6\n,,8,0.01,0.02,0.03,0.04,30.,0.001\n,1\n"
                                              "CTRIA6,10,7,1,2,3,5,,\n,11.,0.002,0.01,0.02,0.03,1\n");
  ASSERT_EQ(m.shells8.size(), 2u);
  const fem::QuadraticShell& quad = m.shells8[0];
  EXPECT_EQ(quad.mid, (std::array<int, 4>{5, 6, 0, 8}));
  EXPECT_EQ(quad.shell.t, (std::array<double, 4>{0.01, 0.02, 0.03, 0.04}));
  EXPECT_EQ(quad.shell.theta_deg, 30.0);
  EXPECT_EQ(quad.shell.zoffs, 0.001);
  EXPECT_EQ(quad.shell.tflag, 1);
  const fem::QuadraticShell& t = m.shells8[1];
  EXPECT_EQ(t.mid, (std::array<int, 4>{5, 0, 0, 0}));
  EXPECT_EQ(t.shell.theta_deg, 11.0);
  EXPECT_EQ(t.shell.zoffs, 0.002);
  EXPECT_EQ(t.shell.tflag, 1);
  std::ostringstream out;
  io::write_nastran(m, out);
  const fem::Model back = test::read_deck(out.str(), "converted.bdf");
  ASSERT_EQ(back.shells8.size(), 2u);
  EXPECT_EQ(back.shells8[0].mid, quad.mid);
  EXPECT_EQ(back.shells8[0].shell.t, quad.shell.t);
  EXPECT_EQ(back.shells8[1].shell.theta_deg, 11.0);
  const Eigen::MatrixXd K(fem::assemble(m, fem::assembly_options(m)).K), Kb(fem::assemble(back, fem::assembly_options(back)).K);
  EXPECT_EQ((K - Kb).norm(), 0.0);
}

TEST(QuadraticShell, RefusalsNameCardFieldAndWhatWasExpected) {
  EXPECT_EQ(test::read_error("CQUAD8,9,7,1,2,3,4,5,2\n"), "deck.bdf:1: CQUAD8 9, field 9 (G6): grid 2 repeats G2; expected distinct grids");
  EXPECT_EQ(test::read_error("CTRIA6,9,7,1,2,3\n,,,,,,2\n"), "deck.bdf:2: CTRIA6 9, field 7 (TFLAG): got integer '2'; expected 0, 1 or blank");
  // a mid-side grid beyond the far corner folds the map
  EXPECT_EQ(test::assembly_error("MAT1,3,2.1+11,,0.3\nPSHELL,7,3,0.01,3\nGRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,0.,1.,0.\n"
                                 "GRID,4,,1.5,0.,0.\nCTRIA6,9,7,1,2,3,4\n"),
            "deck.bdf:7: CTRIA6 9: its mid-side grids distort it so much that its map folds over (Jacobian <= 0); expected "
            "each mid-side grid near the middle of its edge");
}

}  // namespace
}  // namespace seflex
