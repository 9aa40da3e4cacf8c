// Thick simply supported plates (a/t = 10): CQUAD4 and CTRIA3 meshes against Mindlin plate theory,
// statics and modes, on the plate of MYSTRAN's AQ3U2S004 decks (a quarter of a 2 x 2 plate, t = 0.2,
// 4 x 4 elements: t/h = 0.8), refined.
//
// Both elements scale the transverse shear stiffness by t^2 / (t^2 + 0.1 h^2) (Lyly, Stenberg &
// Vihinen), which at t/h = 0.8 removes 13.5 % of it. For the quad that softening is not the error of
// the thick plate: without it (tried on the `thick` branch, commit a5172b3) the 4 x 4 quad is too
// stiff (compliance -3.6 % instead of -2.8 %, centre deflection -0.43 % instead of +0.35 %) and only
// the lumped-mass frequencies move closer (f11 -0.91 % instead of -1.33 %): an exchange of errors of
// the same order, both falling as h^2. These tests hold the accuracy of the elements as they are.
//
// References (independent of seflex), for mode or load term (m, n), m and n odd (the quarter keeps
// the modes symmetric about both centre lines), k^2 = (m^2 + n^2) (pi/a)^2, D = E t^3/(12 (1 - nu^2)),
// S = (5/6) G t (PSHELL TS/T default):
//  - Mindlin's plate without rotary inertia (the shell mass matrices carry none; Mindlin, J. Appl.
//    Mech. 18 (1951) 31-38, with the rotary-inertia term dropped):
//      omega^2 = D k^4 / (rho t (1 + D k^2 / S)).
//  - Uniform pressure q, Navier's series of first-order shear deformation theory (Reddy, Theory and
//    Analysis of Elastic Plates and Shells, 2nd ed., 2007, sec. 10.2; equivalently Wang, Reddy & Lee,
//    Shear Deformable Beams and Plates, 2000, ch. 5: w_Mindlin = w_Kirchhoff + M/S):
//      w(a/2, a/2) = sum 16 q / (pi^2 m n) (1 / (D k^4) + 1 / (S k^2)) sin(m pi/2) sin(n pi/2),
//    summed to m, n < 400 (converged to 1e-8).
// The corner forces of the pressure are the elements' work-equivalent loads (q A / 4 per corner of a
// rectangle, q A / 3 per corner of a triangle), as PLOAD2 gives them.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "shell_mesh.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/dof_map.hpp"

namespace seflex::fem {
namespace {

const double kPi = 3.14159265358979323846;
const double kA = 2.0, kT = 0.2, kE = 200e9, kNu = 0.3, kRho = 8000.0;
const double kG = kE / (2 * (1 + kNu)), kD = kE * kT * kT * kT / (12 * (1 - kNu * kNu)), kS = 5.0 / 6.0 * kG * kT;

double mindlin_hz(int m, int n) {
  const double k2 = (m * m + n * n) * std::pow(kPi / kA, 2);
  return std::sqrt(kD * k2 * k2 / (kRho * kT * (1 + kD * k2 / kS))) / (2 * kPi);
}

double mindlin_centre_deflection(double q) {
  double w = 0;
  for (int m = 1; m < 400; m += 2)
    for (int n = 1; n < 400; n += 2) {
      const double k2 = (m * m + n * n) * std::pow(kPi / kA, 2);
      const double sign = ((m + n) / 2) % 2 == 1 ? 1.0 : -1.0;  // sin(m pi/2) sin(n pi/2)
      w += sign * 16 * q / (kPi * kPi * m * n) * (1 / (kD * k2 * k2) + 1 / (kS * k2));
    }
  return w;
}

// Work of the pressure on the quarter, q int w dA = (1/4) sum q_mn q (2a/(m pi)) (2a/(n pi)) (1/(D k^4) + 1/(S k^2)),
// q_mn = 16 q / (pi^2 m n): the compliance, which the work-equivalent corner forces F give as F . u.
double mindlin_quarter_compliance(double q) {
  double c = 0;
  for (int m = 1; m < 400; m += 2)
    for (int n = 1; n < 400; n += 2) {
      const double k2 = (m * m + n * n) * std::pow(kPi / kA, 2);
      c += 16 * q * q / (kPi * kPi * m * n) * (2 * kA / (m * kPi)) * (2 * kA / (n * kPi)) * (1 / (kD * k2 * k2) + 1 / (kS * k2));
    }
  return 0.25 * c;
}

struct Quarter {
  Model model;
  test::ShellMesh mesh;
  int n = 0;
};

// The quarter 0 <= x, y <= a/2 of the plate, n x n: symmetry on x = 0 (theta_y = 0) and y = 0
// (theta_x = 0), hard simple support on x = a/2 (w, theta_x) and y = a/2 (w, theta_y); in-plane dofs
// and the drilling rotation held (they decouple in a flat plate). As AQ3U2S004's SPC1 cards.
Quarter make_quarter(int n, bool triangles) {
  Quarter p;
  p.n = n;
  test::add_mat1(p.model, 1, kE, kNu, kRho);
  test::add_pshell(p.model, 1, 1, kT);
  p.mesh = test::add_shell_mesh(
      p.model, n, n, [](double u, double v) { return Eigen::Vector3d(0.5 * kA * u, 0.5 * kA * v, 0.0); }, triangles);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      std::string c = "126";
      if (i == 0) c += "5";
      if (j == 0) c += "4";
      if (i == n) c += "34";
      if (j == n) c += "35";
      test::add_spc(p.model, 1, p.mesh.id(i, j), c);
    }
  test::finalize_for_test(p.model);
  return p;
}

// The four lowest frequencies (Hz) of the quarter: modes (1,1), (1,3), (3,1), (3,3).
std::vector<double> frequencies(const Quarter& p) {
  const GlobalMatrices g = assemble(p.model, assembly_options(p.model));
  const ConstrainedSystem c = apply_constraints(p.model, g, 1);
  std::vector<double> f;
  for (double lam : test::lowest_eigenvalues(c.K_ff, c.M_ff, 4)) f.push_back(std::sqrt(lam) / (2 * kPi));
  return f;
}

struct StaticResult {
  double w_centre = 0, compliance = 0;
};

// Centre deflection and compliance F . u under a uniform pressure q (work-equivalent corner forces).
StaticResult pressure_response(const Quarter& p, double q, bool triangles) {
  const GlobalMatrices g = assemble(p.model, assembly_options(p.model));
  const ConstrainedSystem c = apply_constraints(p.model, g, 1);
  Eigen::VectorXd p_g = Eigen::VectorXd::Zero(g.K.rows());
  const double h = 0.5 * kA / p.n;
  auto add = [&](int i, int j, double f) { p_g[*find_dof(p.model, g.dofs, p.mesh.id(i, j), 3)] += f; };
  for (int j = 0; j < p.n; ++j)
    for (int i = 0; i < p.n; ++i) {
      if (triangles) {  // (a, b, c) and (a, c, d), as add_shell_mesh splits the cell
        const double f = q * 0.5 * h * h / 3;
        add(i, j, 2 * f);
        add(i + 1, j, f);
        add(i + 1, j + 1, 2 * f);
        add(i, j + 1, f);
      } else {
        add(i, j, q * h * h / 4);
        add(i + 1, j, q * h * h / 4);
        add(i + 1, j + 1, q * h * h / 4);
        add(i, j + 1, q * h * h / 4);
      }
    }
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(c.K_ff);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  const Eigen::VectorXd u_g = expand(c, ldlt.solve(reduce_load(c, g, p_g)));
  return {u_g[*find_dof(p.model, g.dofs, p.mesh.id(0, 0), 3)], p_g.dot(u_g)};
}

TEST(ThickPlate, ReferencesShowShear) {
  // Shear lowers f11 by 2.7 % and adds 5.2 % to the centre deflection at a/t = 10.
  const double k2 = 2 * std::pow(kPi / kA, 2);
  const double f11_kirchhoff = std::sqrt(kD * k2 * k2 / (kRho * kT)) / (2 * kPi);
  EXPECT_NEAR(mindlin_hz(1, 1) / f11_kirchhoff, 0.9729, 1e-4);
  // Kirchhoff centre deflection 0.00406235 q a^4 / D (Timoshenko & Woinowsky-Krieger, table 8).
  EXPECT_NEAR(mindlin_centre_deflection(1.0) / (0.00406235 * std::pow(kA, 4) / kD), 1.0518, 1e-4);
}

TEST(ThickPlate, QuadStaticsConvergeToMindlin) {
  const double q = 1e5, ref = mindlin_centre_deflection(q), cref = mindlin_quarter_compliance(q);
  // t/h = 0.8, 1.6, 3.2: centre deflection +0.35 %, +0.088 %, +0.022 %; compliance -2.8 %, -0.70 %,
  // -0.18 % (without the stabilisation -0.43 / -0.105 / -0.026 % and -3.6 / -0.92 / -0.23 %).
  const double tol[3] = {0.005, 0.0012, 0.0003}, ctol[3] = {0.03, 0.0075, 0.0019};
  double prev = 1.0, cprev = 1.0;
  for (int k = 0; k < 3; ++k) {
    const int n = 4 << k;
    const StaticResult r = pressure_response(make_quarter(n, false), q, false);
    std::printf("thick plate CQUAD4 %2d x %2d (t/h = %.1f): centre deflection %+.3f %%, compliance %+.3f %%\n", n, n,
                kT * 2 * n / kA, 100 * (r.w_centre / ref - 1), 100 * (r.compliance / cref - 1));
    EXPECT_NEAR(r.w_centre / ref, 1.0, tol[k]) << n;
    EXPECT_NEAR(r.compliance / cref, 1.0, ctol[k]) << n;
    EXPECT_LT(std::abs(r.w_centre / ref - 1), prev) << n;
    EXPECT_LT(std::abs(r.compliance / cref - 1), cprev) << n;
    prev = std::abs(r.w_centre / ref - 1);
    cprev = std::abs(r.compliance / cref - 1);
  }
}

TEST(ThickPlate, QuadModesConvergeToMindlin) {
  const double ref[4] = {mindlin_hz(1, 1), mindlin_hz(1, 3), mindlin_hz(3, 1), mindlin_hz(3, 3)};
  // Largest error of the four (mode (3,3), 1.5 half-waves on the quarter), falling as h^2:
  // -12.7 %, -3.3 %, -0.85 % (the lumped mass lowers it; the coupled mass gives +21 % at 4 x 4).
  // f11 at the 4 x 4 mesh of AQ3U2S004: -1.33 % (MYSTRAN's MIN4T -0.0 %, mystran_plate_test.cpp).
  const double tol[3] = {0.135, 0.036, 0.0095};
  double prev = 1.0;
  for (int k = 0; k < 3; ++k) {
    const int n = 4 << k;
    const auto f = frequencies(make_quarter(n, false));
    double err = 0;
    for (int i = 0; i < 4; ++i) err = std::max(err, std::abs(f[i] / ref[i] - 1));
    std::printf("thick plate CQUAD4 %2d x %2d: f = %.1f %.1f %.1f %.1f Hz, Mindlin %.1f %.1f %.1f %.1f Hz\n", n, n, f[0],
                f[1], f[2], f[3], ref[0], ref[1], ref[2], ref[3]);
    EXPECT_LT(err, tol[k]) << n;
    EXPECT_LT(err, prev) << n;
    prev = err;
    if (n == 4) {
      EXPECT_NEAR(f[0] / ref[0], 1.0, 0.015);
    }
  }
}

TEST(ThickPlate, TrianglesConvergeToMindlin) {
  // The stabilisation helps the thick triangle: without it the 4 x 4 x 2 mesh is up to 6 % too stiff.
  const double q = 1e5, wref = mindlin_centre_deflection(q);
  const double ref[4] = {mindlin_hz(1, 1), mindlin_hz(1, 3), mindlin_hz(3, 1), mindlin_hz(3, 3)};
  // Frequencies within 0.93 %, 0.24 %, 0.06 %; centre deflection -2.4 %, -0.52 %, -0.12 %.
  const double tol_f[3] = {0.012, 0.004, 0.001}, tol_w[3] = {0.025, 0.006, 0.0015};
  double prev = 1.0;
  for (int k = 0; k < 3; ++k) {
    const int n = 4 << k;
    const Quarter p = make_quarter(n, true);
    const auto f = frequencies(p);
    double err = 0;
    for (int i = 0; i < 4; ++i) err = std::max(err, std::abs(f[i] / ref[i] - 1));
    const double w = pressure_response(p, q, true).w_centre;
    std::printf("thick plate CTRIA3 %2d x %2d x 2: frequencies within %.3f %%, centre deflection %+.3f %%\n", n, n,
                100 * err, 100 * (w / wref - 1));
    EXPECT_LT(err, tol_f[k]) << n;
    EXPECT_NEAR(w / wref, 1.0, tol_w[k]) << n;
    EXPECT_LT(err, prev) << n;
    prev = err;
  }
}

}  // namespace
}  // namespace seflex::fem
