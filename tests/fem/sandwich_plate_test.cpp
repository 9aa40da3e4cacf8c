// Sandwich and shear-flexible PSHELL sections (12I/T^3 != 1, TS/T, MID3 blank): simply supported
// 1 m x 1 m plates of CQUAD4 and CTRIA3, statics and modes, against plate theory.
//
// The seed's honeycomb panel is a PSHELL with T = 3.6e-4 m (the face sheets), 12I/T^3 = 11200 and
// TS/T = 19.13: its bending thickness (12 I)^(1/3) = 22.4 T. Until 2026-11 the MITC shear
// stabilisation was written in T, which removed almost all of the sandwich's transverse shear
// stiffness (20 x 20 quads gave 50.8 Hz for the 70.6 Hz of plate theory, 17.0 Hz with TS/T = 0.833).
//
// References (independent of seflex):
//  - Navier solution of the simply supported plate for the load and mode (p, q), k^2 = (p^2 + q^2)
//    (pi/a)^2, D = E (12I/T^3) T^3 / (12 (1 - nu^2)) (Nastran's PSHELL bending stiffness, MSC Nastran
//    QRG, PSHELL remark on 12I/T^3), S = G3 TS (transverse shear stiffness per length):
//      Kirchhoff: omega^2 = D k^4 / m          (Leissa, Vibration of Plates, NASA SP-160, eq. 4.20)
//      Mindlin without rotary inertia (the shell mass matrices carry none):
//                 omega^2 = D k^4 / (m (1 + D k^2 / S))   (Mindlin, J. Appl. Mech. 18 (1951) 31-38)
//      sinusoidal load q0 sin(pi x/a) sin(pi y/a): w_max = q0 / (D k^4) (1 + D k^2 / S)
//                 (Reddy, Theory and Analysis of Elastic Plates and Shells, 2nd ed., sec. 10.2.2:
//                  the shear term of first-order shear deformation theory for one Navier term)
//    with m = rho T + NSM the mass per area.
//  - The lumped nodal forces of the sinusoidal load sampled at the grids have exactly the (1,1)
//    Fourier coefficient of the continuous load (discrete orthogonality of the sine on the grid), so
//    the only error is the element's.
#include <gtest/gtest.h>

#include <cmath>

#include "shell_mesh.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/dof_map.hpp"

#include <Eigen/SparseCholesky>

namespace seflex::fem {
namespace {

const double kPi = 3.14159265358979323846;
const double kA = 1.0, kE = 1.21e11, kNu = 0.3, kG = kE / (2 * (1 + kNu));
const double kT = 3.6e-4, kNsm = 11.46;

struct Section {
  double bend_ratio = 1.0;
  bool mid3 = true;
  double ts_t = 0.833333;
};

double bending_D(const Section& s) { return kE * s.bend_ratio * kT * kT * kT / (12 * (1 - kNu * kNu)); }
// Transverse shear stiffness per length; MID3 blank: rigid in shear (Kirchhoff), as Nastran.
double shear_S(const Section& s) { return s.mid3 ? kG * s.ts_t * kT : INFINITY; }

double theory_hz(const Section& s, int p, int q) {
  const double k2 = (p * p + q * q) * std::pow(kPi / kA, 2), D = bending_D(s);
  const double w2 = D * k2 * k2 / (kNsm * (1 + D * k2 / shear_S(s)));  // rho = 0: NSM is all the mass
  return std::sqrt(w2) / (2 * kPi);
}

struct Plate {
  Model model;
  test::ShellMesh mesh;
  int n = 0;
};

// Hard simply supported plate, n x n, in-plane dofs held (they decouple in a flat plate).
Plate make_plate(const Section& s, int n, bool triangles) {
  Plate p;
  p.n = n;
  test::add_mat1(p.model, 1, kE, kNu, 0.0);
  ShellProperty& ps = test::add_pshell(p.model, 1, 1, kT, s.mid3, kNsm);
  ps.bend_ratio = s.bend_ratio;
  ps.ts_t = s.ts_t;
  p.mesh = test::add_shell_mesh(
      p.model, n, n, [](double u, double v) { return Eigen::Vector3d(kA * u, kA * v, 0.0); }, triangles);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      std::string c = "126";
      if (i == 0 || i == n) c += "34";
      if (j == 0 || j == n) c += "35";
      test::add_spc(p.model, 1, p.mesh.id(i, j), c);
    }
  test::finalize_for_test(p.model);
  return p;
}

std::vector<double> frequencies(Plate& p, int count) {
  const GlobalMatrices g = assemble(p.model, assembly_options(p.model));
  const ConstrainedSystem c = apply_constraints(p.model, g, 1);
  std::vector<double> f;
  for (double lam : test::lowest_eigenvalues(c.K_ff, c.M_ff, count)) f.push_back(std::sqrt(lam) / (2 * kPi));
  return f;
}

// Centre deflection under q0 sin(pi x/a) sin(pi y/a), lumped to the grids.
double centre_deflection(Plate& p, double q0) {
  const GlobalMatrices g = assemble(p.model, assembly_options(p.model));
  const ConstrainedSystem c = apply_constraints(p.model, g, 1);
  Eigen::VectorXd p_g = Eigen::VectorXd::Zero(g.K.rows());
  const double h = kA / p.n;
  for (int j = 1; j < p.n; ++j)
    for (int i = 1; i < p.n; ++i) {
      const auto d = find_dof(p.model, g.dofs, p.mesh.id(i, j), 3);
      p_g[*d] = q0 * std::sin(kPi * i * h / kA) * std::sin(kPi * j * h / kA) * h * h;
    }
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(c.K_ff);
  const Eigen::VectorXd u_g = expand(c, ldlt.solve(reduce_load(c, g, p_g)));
  return u_g[*find_dof(p.model, g.dofs, p.mesh.id(p.n / 2, p.n / 2), 3)];
}

// The four lowest modes (1,1), (1,2), (2,1), (2,2) within `tol` of plate theory.
void expect_modes(const Section& s, bool triangles, double tol) {
  Plate p = make_plate(s, 20, triangles);
  const auto f = frequencies(p, 4);
  const double ref[4] = {theory_hz(s, 1, 1), theory_hz(s, 1, 2), theory_hz(s, 2, 1), theory_hz(s, 2, 2)};
  for (int i = 0; i < 4; ++i) {
    std::printf("12I/T^3 = %g, TS/T = %g%s, %s: mode %d %.4f Hz, theory %.4f Hz (%+.3f %%)\n", s.bend_ratio, s.ts_t,
                s.mid3 ? "" : " (MID3 blank)", triangles ? "CTRIA3" : "CQUAD4", i + 1, f[i], ref[i],
                100 * (f[i] / ref[i] - 1));
    EXPECT_NEAR(f[i] / ref[i], 1.0, tol) << "mode " << i + 1;
  }
}

void expect_static(const Section& s, bool triangles, double tol) {
  Plate p = make_plate(s, 20, triangles);
  const double q0 = 1000.0, k2 = 2 * std::pow(kPi / kA, 2), D = bending_D(s);
  const double ref = q0 / (D * k2 * k2) * (1 + D * k2 / shear_S(s));
  const double w = centre_deflection(p, q0);
  std::printf("12I/T^3 = %g, TS/T = %g%s, %s: centre deflection %.6e m, theory %.6e m (%+.3f %%)\n", s.bend_ratio,
              s.ts_t, s.mid3 ? "" : " (MID3 blank)", triangles ? "CTRIA3" : "CQUAD4", w, ref, 100 * (w / ref - 1));
  EXPECT_NEAR(w / ref, 1.0, tol);
}

// The seed's panel section: shear is stiff (D k^2 / S = 3.6e-4), so the plate is a Kirchhoff plate;
// f11 = 70.6 Hz.
const Section kSeed{11200.0, true, 19.13};
// The same with the default TS/T: shear lowers f11 by 0.4 %.
const Section kSeedDefaultTs{11200.0, true, 0.833333};
// MID3 blank: no transverse shear flexibility.
const Section kSeedNoMid3{11200.0, false, 0.833333};
// A soft core (TS/T = 0.05): D k^2 / S = 0.13 for mode (1,1), 0.53 for (2,2); shear governs.
const Section kSoftCore{11200.0, true, 0.05};
// Homogeneous plate of the same thickness (12I/T^3 = 1): thin, a/T = 2800.
const Section kSolid{1.0, true, 0.833333};

TEST(SandwichPlate, ReferencesSpanKirchhoffToShearDominated) {
  // the cases test what they claim: shear negligible, small, dominant
  EXPECT_NEAR(theory_hz(kSeed, 1, 1), 70.6, 0.05);
  EXPECT_LT(theory_hz(kSeedNoMid3, 1, 1) / theory_hz(kSeed, 1, 1) - 1, 2e-4);
  EXPECT_GT(theory_hz(kSeedNoMid3, 1, 1) / theory_hz(kSeedDefaultTs, 1, 1) - 1, 3e-3);
  EXPECT_GT(theory_hz(kSeedNoMid3, 2, 2) / theory_hz(kSoftCore, 2, 2), 1.2);
}

TEST(SandwichPlate, ModesQuadsWithinOnePercentOfPlateTheory) {
  expect_modes(kSeed, false, 0.01);
  expect_modes(kSeedDefaultTs, false, 0.01);
  expect_modes(kSeedNoMid3, false, 0.01);
  expect_modes(kSoftCore, false, 0.01);
  expect_modes(kSolid, false, 0.01);
}

TEST(SandwichPlate, ModesTrianglesWithinOnePercentOfPlateTheory) {
  expect_modes(kSeed, true, 0.01);
  expect_modes(kSeedNoMid3, true, 0.01);  // the DKT (MITC3 with the Kirchhoff penalty locked here)
  expect_modes(kSoftCore, true, 0.01);
}

TEST(SandwichPlate, StaticsQuadsWithinOnePercentOfPlateTheory) {
  expect_static(kSeed, false, 0.01);
  expect_static(kSeedDefaultTs, false, 0.01);
  expect_static(kSeedNoMid3, false, 0.01);
  expect_static(kSoftCore, false, 0.01);
  expect_static(kSolid, false, 0.01);
}

TEST(SandwichPlate, StaticsTrianglesWithinOnePercentOfPlateTheory) {
  expect_static(kSeed, true, 0.01);
  expect_static(kSeedNoMid3, true, 0.01);
  expect_static(kSoftCore, true, 0.01);
}

}  // namespace
}  // namespace seflex::fem
