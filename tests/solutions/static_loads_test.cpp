// Pressure (PLOAD2), inertia (GRAV, RFORCE) and thermal (TEMP, TEMPD, TEMPRB) loads in linear
// statics, each against a reference computed here independently of seflex: beam and plate theory
// (closed forms and the Navier series), the exact nodal solution of the discretised problem (point
// loads on an Euler-Bernoulli cantilever, a rod's axial forces by equilibrium), and conservation
// (total gravity load = total mass x g).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "nastran_test_util.hpp"
#include "statics_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/loads.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

constexpr double kPi = 3.14159265358979323846;

using test::num;

constexpr auto u = test::displacement;
double p(const fem::Model& m, const solutions::StaticSolution& s, int g, int c) {
  return s.p_g[*fem::find_dof(m, s.dofs, g, c)];
}

// ---------------------------------------------------------------------------------------------
// GRAV on a cantilever of n CBARs along x (L = 2, E = 7e10, A = 1e-4, I2 = 3e-8, rho = 2700),
// clamped at grid 1, gravity g along -z.
std::string gravity_cantilever(int n, const std::string& case_control, const std::string& more) {
  std::string d = "SOL 101\nCEND\nSPC = 1\n" + case_control +
                  "BEGIN BULK\nMAT1,1,7.e10,,0.3,2700.\n"
                  "PBAR,1,1,1.e-4,2.e-8,3.e-8,4.e-8\nSPC1,1,123456,1\n" +
                  more;
  for (int i = 0; i <= n; ++i) d += "GRID," + std::to_string(i + 1) + ",," + num(2.0 * i / n) + ",0.,0.\n";
  for (int i = 1; i <= n; ++i)
    d += "CBAR," + std::to_string(i) + ",1," + std::to_string(i) + "," + std::to_string(i + 1) + ",0.,1.,0.\n";
  return d + "ENDDATA\n";
}

// The lumped mass puts m_e/2 of each element on its ends, so the load is P_i = m_e g at interior
// grids and m_e g / 2 at the tip; an exact (Euler-Bernoulli) element gives the beam-theory tip
// deflection of point loads, w(L) = sum P_i x_i^2 (3L - x_i) / (6 EI) (Timoshenko & Gere, table
// G-1), computed here. It converges to q L^4 / (8 EI) with q = rho A g; the total load is the mass
// times g, and the SPC forces balance it.
TEST(GravityLoad, CantileverUnderOwnWeight) {
  const int n = 20;
  const double L = 2.0, E = 7e10, A = 1e-4, I = 3e-8, rho = 2700, g = 9.81;
  const fem::Model m = test::read_deck(gravity_cantilever(n, "LOAD = 3\n", "GRAV,3,,9.81,0.,0.,-1.\n"));
  const auto s = solutions::solve_static(m);
  const double me = rho * A * L / n;
  double w_lumped = 0;
  for (int i = 1; i <= n; ++i) {
    const double x = L * i / n, P = (i == n ? 0.5 : 1.0) * me * g;
    w_lumped += P * x * x * (3 * L - x) / (6 * E * I);
  }
  EXPECT_NEAR(u(m, s, n + 1, 3) / -w_lumped, 1.0, 1e-9);
  const double q = rho * A * g;
  EXPECT_NEAR(u(m, s, n + 1, 3) / -(q * L * L * L * L / (8 * E * I)), 1.0, 2e-3);
  double fz = 0, qz = 0;
  for (int i = 1; i <= n + 1; ++i) fz += p(m, s, i, 3), qz += s.q_g[*fem::find_dof(m, s.dofs, i, 3)];
  EXPECT_NEAR(fz / -(rho * A * L * g), 1.0, 1e-12);
  EXPECT_NEAR(qz / (rho * A * L * g), 1.0, 1e-9);
  EXPECT_EQ(p(m, s, 5, 1), 0.0);
  EXPECT_EQ(p(m, s, 5, 4), 0.0);
}

// The acceleration is A (N1, N2, N3), in a rotated rectangular CID; LOAD combinations scale it,
// and PARAM WTMASS scales the mass it acts on (the load is M a with M = WTMASS x the input mass).
TEST(GravityLoad, SystemsCombinationsAndWtmass) {
  const std::string base = "GRAV,3,,9.81,0.,0.,-1.\n";
  const fem::Model ref = test::read_deck(gravity_cantilever(4, "LOAD = 3\n", base));
  const auto r = solutions::solve_static(ref);
  // CORD2R 9: e3 = basic x, e1 = basic z; N = (-0.5, 0, 0) * A = 19.62 -> 9.81 along -z basic
  const std::string cord = "CORD2R,9,,0.,0.,0.,1.,0.,0.,+C\n+C,0.,0.,1.\n";
  const fem::Model rot = test::read_deck(gravity_cantilever(4, "LOAD = 4\n", cord + "GRAV,4,9,19.62,-0.5,0.,0.\n"));
  EXPECT_LE((solutions::solve_static(rot).u_g - r.u_g).norm(), 1e-12 * r.u_g.norm());
  // LOAD 10 = 2 * (1.5 GRAV 3 - 1 FORCE 8): superposition
  const std::string combo = base + "FORCE,8,5,,100.,0.,1.,0.\nLOAD,10,2.,1.5,3,-1.,8\n";
  const fem::Model c = test::read_deck(gravity_cantilever(4, "SUBCASE 1\nLOAD = 10\nSUBCASE 2\nLOAD = 8\n", combo));
  const auto cs = solutions::solve_statics(c);
  ASSERT_EQ(cs.size(), 2u);
  EXPECT_LE((cs[0].u_g - (3.0 * r.u_g - 2.0 * cs[1].u_g)).norm(), 1e-12 * cs[0].u_g.norm());
  // WTMASS halves the load
  const fem::Model w = test::read_deck(gravity_cantilever(4, "LOAD = 3\n", base + "PARAM,WTMASS,0.5\n"));
  EXPECT_LE((solutions::solve_static(w).u_g - 0.5 * r.u_g).norm(), 1e-12 * r.u_g.norm());
}

// A CONM2 with an offset: the gravity load at its grid is m g and the moment of m g about the grid
// (M times the rigid-body acceleration: the offset couples translation and rotation).
TEST(GravityLoad, OffsetMassGivesItsMoment) {
  const fem::Model m =
      test::read_deck(gravity_cantilever(2, "LOAD = 3\n", "GRAV,3,,2.,0.,0.,-1.\nCONM2,50,3,,4.,0.,0.3,0.\n"));
  const auto s = solutions::solve_static(m);
  const double me = 2700 * 1e-4 * 1.0;  // element mass, half of it at the tip
  EXPECT_NEAR(p(m, s, 3, 3), -(4.0 + 0.5 * me) * 2.0, 1e-12);
  // moment of the force (0, 0, -8) at (0, 0.3, 0) from the grid: (0.3 * -8, 0, 0)
  EXPECT_NEAR(p(m, s, 3, 4), -2.4, 1e-12);
  EXPECT_NEAR(p(m, s, 3, 5), 0.0, 1e-15);
}

// ---------------------------------------------------------------------------------------------
// RFORCE: a rod of n CONRODs along x from the rotation axis (basic z through grid 1), spinning at
// A = 10 rev/s (omega = 20 pi rad/s). Each grid carries its lumped mass m_i, loaded outward with
// m_i omega^2 x_i; by equilibrium the axial force of element j is the sum over the grids outboard
// of it (computed here), and the continuous rod's is rho A omega^2 (L^2 - x^2) / 2.
TEST(RotationalLoad, SpinningRodAxialForce) {
  const int n = 40;
  const double L = 1.0, E = 2e11, A = 1e-4, rho = 7800, omega = 2 * kPi * 10.0;
  std::string d =
      "SOL 101\nCEND\nSPC = 1\nLOAD = 5\nBEGIN BULK\nMAT1,1,2.e11,,0.3,7800.\n"
      "SPC1,1,123456,1\nSPC1,1,23456,2,THRU," +
      std::to_string(n + 1) + "\nRFORCE,5,1,,10.,0.,0.,1.\n";
  for (int i = 0; i <= n; ++i) d += "GRID," + std::to_string(i + 1) + ",," + num(L * i / n) + ",0.,0.\n";
  for (int i = 1; i <= n; ++i)
    d += "CONROD," + std::to_string(i) + "," + std::to_string(i) + "," + std::to_string(i + 1) + ",1,1.e-4\n";
  const fem::Model m = test::read_deck(d + "ENDDATA\n");
  const auto s = solutions::solve_static(m);
  const double h = L / n, mi = rho * A * h;
  double worst_discrete = 0, worst_continuous = 0;
  for (int j = 1; j <= n; ++j) {  // element j between grids j and j + 1
    const double N = E * A * (u(m, s, j + 1, 1) - u(m, s, j, 1)) / h;
    double outboard = 0;
    for (int i = j; i <= n; ++i) outboard += (i == n ? 0.5 : 1.0) * mi * omega * omega * (L * i / n);
    const double xm = (j - 0.5) * h;
    const double continuous = rho * A * omega * omega * (L * L - xm * xm) / 2;
    worst_discrete = std::max(worst_discrete, std::abs(N / outboard - 1.0));
    if (j <= n / 2) worst_continuous = std::max(worst_continuous, std::abs(N / continuous - 1.0));
  }
  EXPECT_LT(worst_discrete, 1e-9);
  EXPECT_LT(worst_continuous, 1e-3);  // lumped discretisation error, O(h^2)
  // tip: u(L) = rho omega^2 L^3 / (3 E) for the continuous rod
  EXPECT_NEAR(u(m, s, n + 1, 1) / (rho * omega * omega * L * L * L / (3 * E)), 1.0, 1e-3);
}

// The load of one mass m at r from the axis: centrifugal m omega^2 r outward (omega = 2 pi A |R|
// with R as given), tangential -m alpha x r (alpha = 2 pi RACC R, the d'Alembert force of the
// angular acceleration, as MYSTRAN's RFORCE_PROC), the offset's moment, and the grid's CD system.
TEST(RotationalLoad, PointMassLoadsAndSigns) {
  const std::string bulk =
      "MAT1,1,7.e10,,0.3,2700.\nGRID,1,,0.,0.,0.\nGRID,2,,2.,0.,0.,7\n"
      "CORD2R,7,,0.,0.,0.,0.,0.,1.,+C\n+C,0.,1.,0.\n"  // e1 = basic y, e2 = -basic x
      "CONROD,1,1,2,1,1.e-4\nCONM2,9,2,,3.,0.,0.,0.5\nSPC1,1,123456,1\n";
  const fem::Model m = test::read_deck("SOL 101\nCEND\nSPC = 1\nLOAD = 5\nBEGIN BULK\n" + bulk +
                                       "RFORCE,5,1,,0.5,0.,0.,2.,,+R\n+R,0.25\nENDDATA\n");
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  const Eigen::VectorXd pv = fem::load_vector(m, g.dofs, 5, &g.load_mass());
  const double w = 2 * kPi * 0.5 * 2.0, alpha = 2 * kPi * 0.25 * 2.0;
  const double mt = 3.0 + 0.5 * 2700 * 1e-4 * 2.0;  // CONM2 + half the rod
  // basic force: (mt w^2 2, -mt alpha 2, 0); moment of the CONM2's force about the grid: offset
  // (0, 0, 0.5) x (3 w^2 2, -3 alpha 2, 0) = (0.5 * 3 alpha 2, 0.5 * 3 w^2 2, 0)
  const Eigen::Vector3d F(mt * w * w * 2, -mt * alpha * 2, 0), Mo(0.5 * 3 * alpha * 2, 0.5 * 3 * w * w * 2, 0);
  const Eigen::Index d0 = *fem::find_dof(m, g.dofs, 2, 1);
  // CD 7: components along (basic y, -basic x, basic z)
  EXPECT_NEAR(pv[d0 + 0], F.y(), 1e-9 * F.norm());
  EXPECT_NEAR(pv[d0 + 1], -F.x(), 1e-9 * F.norm());
  EXPECT_NEAR(pv[d0 + 2], 0.0, 1e-12 * F.norm());
  EXPECT_NEAR(pv[d0 + 3], Mo.y(), 1e-9 * Mo.norm());
  EXPECT_NEAR(pv[d0 + 4], -Mo.x(), 1e-9 * Mo.norm());
  // no mass at the axis grid's distance: no load
  EXPECT_LT(pv.segment<3>(*fem::find_dof(m, g.dofs, 1, 1)).norm(), 1e-12);
}

// ---------------------------------------------------------------------------------------------
// PLOAD2 on a simply supported square plate (a = 1, t = 10 mm, steel), 16 x 16 CQUAD4: the Navier
// series w(a/2, a/2) = 16 q / (pi^6 D) sum_{m,n odd} (-1)^((m+n)/2 - 1) / (m n (m^2 + n^2)^2) a^4
// (Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, sec. 30), summed here, plus the
// transverse shear deflection of Mindlin's plate, 16 q / pi^2 sum (-1)^(...) / (m n kappa G t k^2)
// with k^2 = pi^2 (m^2 + n^2) / a^2 (0.05 % here). The edges are the "hard" simple support Navier
// assumes (w = 0 and no twist of the edge, so the rotation about the edge's normal is held too;
// leaving it free, the soft support, gives 0.8 % more deflection at this thickness).
TEST(PressureLoad, SimplySupportedPlateMatchesNavier) {
  const int n = 16;
  const double a = 1.0, t = 0.01, E = 2.1e11, nu = 0.3, q = 1000.0;
  std::string d =
      "SOL 101\nCEND\nSPC = 1\nLOAD = 2\nBEGIN BULK\nMAT1,1,2.1e11,,0.3,7800.\nPSHELL,1,1,0.01,1,,1\n"
      "PLOAD2,2,1000.,1,THRU," +
      std::to_string(n * n) + "\n";
  auto id = [&](int i, int j) { return 1 + i + (n + 1) * j; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      d += "GRID," + std::to_string(id(i, j)) + ",," + num(a * i / n) + "," + num(a * j / n) + ",0.\n";
      std::string c = "3";
      if (i == 0 || i == n) c += "4";  // edges along y: no twist about x
      if (j == 0 || j == n) c += "5";
      if (c.size() > 1) d += "SPC1,1," + c + "," + std::to_string(id(i, j)) + "\n";
    }
  d += "SPC1,1,12," + std::to_string(id(0, 0)) + "\nSPC1,1,2," + std::to_string(id(n, 0)) + "\n";
  int e = 1;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      d += "CQUAD4," + std::to_string(e++) + ",1," + std::to_string(id(i, j)) + "," + std::to_string(id(i + 1, j)) +
           "," + std::to_string(id(i + 1, j + 1)) + "," + std::to_string(id(i, j + 1)) + "\n";
  const fem::Model m = test::read_deck(d + "ENDDATA\n");
  const auto s = solutions::solve_static(m);
  const double D = E * t * t * t / (12 * (1 - nu * nu));
  const double kGt = 5.0 / 6.0 * E / (2 * (1 + nu)) * t;
  double sum = 0, shear = 0;
  for (int mm = 1; mm < 400; mm += 2)
    for (int nn = 1; nn < 400; nn += 2) {
      const double sign = (((mm + nn) / 2 - 1) % 2) ? -1.0 : 1.0;
      sum += sign / (mm * nn * std::pow(mm * mm + nn * nn, 2.0));
      shear += sign * 16 * q / (kPi * kPi * mm * nn) / (kGt * kPi * kPi * (mm * mm + nn * nn) / (a * a));
    }
  const double w_navier = 16 * q * a * a * a * a / (std::pow(kPi, 6) * D) * sum;
  EXPECT_NEAR(w_navier * D / (q * a * a * a * a), 0.00406, 1e-5);  // the tabulated coefficient
  EXPECT_NEAR(shear / w_navier, 5.2e-4, 1e-5);
  EXPECT_NEAR(u(m, s, id(n / 2, n / 2), 3) / (w_navier + shear), 1.0, 0.003);
  // total load q a^2 along +z (the normal of the counter-clockwise grid order); no moments
  double fz = 0, other = 0;
  for (int g = 1; g <= (n + 1) * (n + 1); ++g) {
    fz += p(m, s, g, 3);
    for (int c : {1, 2, 4, 5, 6}) other += std::abs(p(m, s, g, c));
  }
  EXPECT_NEAR(fz / (q * a * a), 1.0, 1e-12);
  EXPECT_EQ(other, 0.0);
  EXPECT_NEAR(p(m, s, id(3, 3), 3), q * a * a / (n * n), 1e-12);  // a rectangle: A/4 per corner, 4 elements
}

// The work-equivalent corner forces of one element: a triangle P A n / 3 per corner, a quad
// P int N_i n dA (summing to P times its vector area, also warped), along the normal of the grid
// order, reversed by a negative P; the THRU form skips ids that are not shells.
TEST(PressureLoad, CornerForcesOfOneElement) {
  const std::string bulk =
      "MAT1,1,2.1e11,,0.3,7800.\nPSHELL,1,1,0.01,1\n"
      "GRID,1,,0.,0.,0.\nGRID,2,,2.,0.,0.\nGRID,3,,1.5,1.,0.2\nGRID,4,,0.5,1.,0.\nGRID,5,,3.,0.,0.\n"
      "CQUAD4,10,1,1,2,3,4\nCTRIA3,11,1,2,5,3\nCBAR,12,7,1,5,0.,1.,0.\nPBAR,7,1,1.e-4,1.e-8,1.e-8\n";
  const fem::Model m =
      test::read_deck("BEGIN BULK\n" + bulk + "PLOAD2,1,-3.,10\nPLOAD2,2,5.,11\nPLOAD2,3,2.,9,THRU,13\nENDDATA\n");
  const fem::DofMap dofs = fem::make_dof_map(m);
  const Eigen::Vector3d x1(0, 0, 0), x2(2, 0, 0), x3(1.5, 1, 0.2), x4(0.5, 1, 0), x5(3, 0, 0);
  auto force = [&](const Eigen::VectorXd& v, int g) {
    return Eigen::Vector3d(v.segment<3>(*fem::find_dof(m, dofs, g, 1)));
  };
  // quad: sum of the corner forces = -3 * vector area = -3 * (diag1 x diag2) / 2
  const Eigen::VectorXd p1 = fem::load_vector(m, dofs, 1);
  const Eigen::Vector3d area = 0.5 * (x3 - x1).cross(x4 - x2);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int g = 1; g <= 5; ++g) sum += force(p1, g);
  EXPECT_LE((sum - (-3.0) * area).norm(), 1e-12);
  EXPECT_GT(area.z(), 0.0);
  // triangle: equal thirds of P A n
  const Eigen::VectorXd p2 = fem::load_vector(m, dofs, 2);
  const Eigen::Vector3d nA = 0.5 * (x5 - x2).cross(x3 - x2);
  for (int g : {2, 5, 3}) EXPECT_LE((force(p2, g) - 5.0 * nA / 3.0).norm(), 1e-12);
  // THRU 9..13: the quad and the triangle; the bar (12) and the missing 9, 13 are skipped
  const Eigen::VectorXd p3 = fem::load_vector(m, dofs, 3);
  EXPECT_LE((p3 - (-2.0 / 3.0) * p1 - 0.4 * p2).norm(), 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Thermal loads. A bar (L = 2 in two CBARs, E = 2e11, A = 1e-3, I1 = 2e-6, I2 = 3e-6, alpha =
// 1.2e-5, TREF = 20) clamped at grid 1: its free thermal deformation is exact at the tip,
//   u = alpha int (T - TREF) dx,  v = -alpha TP1 L^2 / 2,  w = -alpha TP2 L^2 / 2,
//   theta_z = -alpha TP1 L,  theta_y = +alpha TP2 L   (v'' = -alpha TP1: the hotter +y fibres lengthen).
std::string thermal_bar(const std::string& spc, const std::string& temps) {
  return "SOL 101\nCEND\nSPC = 1\nTEMPERATURE(LOAD) = 7\nBEGIN BULK\nMAT1,1,2.e11,,0.3,7800.,1.2e-5,20.\n"
         "PBAR,1,1,1.e-3,2.e-6,3.e-6,4.e-6\nGRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,2.,0.,0.\n"
         "CBAR,1,1,1,2,0.,1.,0.\nCBAR,2,1,2,3,0.,1.,0.\n" +
         spc + temps + "ENDDATA\n";
}

TEST(ThermalLoad, FreeBarExpandsAndBendsAsTheory) {
  // TA/TB linear along the bar (20 -> 120), gradients TP1 = 30, TP2 = -10 per unit length
  const fem::Model m = test::read_deck(thermal_bar("SPC1,1,123456,1\n",
                                                   "TEMPRB,7,1,20.,70.,30.,30.,-10.,-10.\n"
                                                   "TEMPRB,7,2,70.,120.,30.,30.,-10.,-10.\n"));
  const auto s = solutions::solve_static(m);
  const double al = 1.2e-5, L = 2.0;
  EXPECT_NEAR(u(m, s, 3, 1) / (al * 50.0 * L), 1.0, 1e-9);  // mean T - TREF = 50
  EXPECT_NEAR(u(m, s, 3, 2) / (-al * 30 * L * L / 2), 1.0, 1e-9);
  EXPECT_NEAR(u(m, s, 3, 3) / (-al * -10 * L * L / 2), 1.0, 1e-9);
  EXPECT_NEAR(u(m, s, 3, 6) / (-al * 30 * L), 1.0, 1e-9);
  EXPECT_NEAR(u(m, s, 3, 5) / (al * -10 * L), 1.0, 1e-9);
  EXPECT_NEAR(u(m, s, 2, 1) / (al * 25.0 * 1.0), 1.0, 1e-9);  // first element: mean 45 - 20
  // free expansion: no reaction
  EXPECT_LT(s.q_g.norm(), 1e-6 * 2e11 * 1e-3 * al * 50);
}

// Clamped at both ends, a uniform temperature rise dT is held by the axial force E A alpha dT; grid
// temperatures (TEMP, the rest from TEMPD) give the same as TEMPRB of the same mean.
TEST(ThermalLoad, ClampedBarReactionAndGridTemperatures) {
  const std::string spc = "SPC1,1,123456,1,3\n";
  const fem::Model m = test::read_deck(thermal_bar(spc, "TEMP,7,2,80.\nTEMPD,7,80.\n"));
  const auto s = solutions::solve_static(m);
  const double N = 2e11 * 1e-3 * 1.2e-5 * 60.0;
  EXPECT_NEAR(s.q_g[*fem::find_dof(m, s.dofs, 1, 1)] / N, 1.0, 1e-9);
  EXPECT_NEAR(s.q_g[*fem::find_dof(m, s.dofs, 3, 1)] / -N, 1.0, 1e-9);
  EXPECT_LT(s.u_g.norm(), 1e-15);
  // a CROD/CONROD: TEMP at both grids, free end
  const fem::Model r = test::read_deck(
      "SOL 101\nCEND\nSPC = 1\nTEMP = 4\nBEGIN BULK\nMAT1,1,2.e11,,0.3,7800.,1.2e-5,20.\nGRID,1,,0.,0.,0.\n"
      "GRID,2,,0.,3.,0.,,13456\nCONROD,1,1,2,1,1.e-3\nSPC1,1,123456,1\nTEMP,4,1,10.,2,50.\nENDDATA\n");
  EXPECT_NEAR(u(r, solutions::solve_static(r), 2, 2) / (1.2e-5 * 10.0 * 3.0), 1.0, 1e-9);  // mean 30 - 20
}

}  // namespace
}  // namespace seflex
