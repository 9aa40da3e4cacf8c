// Simply supported square plates: natural frequencies of CQUAD4 (and CTRIA3) meshes against plate
// theory, thin (Kirchhoff) and thick (Mindlin), with Nastran's default lumped mass.
#include <gtest/gtest.h>

#include <cmath>

#include "shell_mesh.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"

namespace seflex::fem {
namespace {

const double kPi = 3.14159265358979323846;
const double kA = 10.0, kE = 200e9, kNu = 0.3, kRho = 8000.0, kTsT = 0.833333;

// Lowest `count` frequencies (Hz) of the hard simply supported plate a x a, thickness t, n x n mesh:
// w = 0 on the edges, theta_x = 0 on x = 0, a and theta_y = 0 on y = 0, a (the rotation along the
// edge), in-plane dofs held (they decouple from bending in a flat plate).
std::vector<double> plate_frequencies(int n, double t, bool triangles, int count) {
  Model m;
  test::add_mat1(m, 1, kE, kNu, kRho);
  test::add_pshell(m, 1, 1, t).ts_t = kTsT;
  const auto mesh =
      test::add_shell_mesh(m, n, n, [](double s, double r) { return Eigen::Vector3d(kA * s, kA * r, 0.0); }, triangles);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      std::string c = "126";
      if (i == 0 || i == n) c += "34";
      if (j == 0 || j == n) c += "35";
      test::add_spc(m, 1, mesh.id(i, j), c);
    }
  test::finalize_for_test(m);
  const GlobalMatrices g = assemble(m, assembly_options(m));
  const ConstrainedSystem c = apply_constraints(m, g, 1);
  std::vector<double> f;
  for (double lam : test::lowest_eigenvalues(c.K_ff, c.M_ff, count)) f.push_back(std::sqrt(lam) / (2 * kPi));
  return f;
}

// Plate theory for mode (p, q): k^2 = (p^2 + q^2) (pi / a)^2, D = E t^3 / (12 (1 - nu^2)).
// Kirchhoff (Leissa, Vibration of Plates, NASA SP-160, 1969, eq. 4.20): omega^2 = D k^4 / (rho t).
// Mindlin without rotary inertia (the lumped and coupled shell masses have none; Mindlin, J. Appl.
// Mech. 18 (1951) 31-38, with the rotary-inertia term dropped):
//   omega^2 = D k^4 / (rho t (1 + D k^2 / (kappa G t))),  kappa = TS/T.
double theory_hz(int p, int q, double t, bool shear) {
  const double k2 = (p * p + q * q) * std::pow(kPi / kA, 2);
  const double D = kE * t * t * t / (12 * (1 - kNu * kNu)), G = kE / (2 * (1 + kNu));
  double w2 = D * k2 * k2 / (kRho * t);
  if (shear) w2 /= 1 + D * k2 / (kTsT * G * t);
  return std::sqrt(w2) / (2 * kPi);
}

void check_plate(double t, bool shear_theory, bool triangles, double tol_moderate) {
  const double ref[4] = {theory_hz(1, 1, t, shear_theory), theory_hz(1, 2, t, shear_theory),
                         theory_hz(2, 1, t, shear_theory), theory_hz(2, 2, t, shear_theory)};
  double prev = 1.0;
  for (int n : {8, 16, 32}) {
    const auto f = plate_frequencies(n, t, triangles, 4);
    double err = 0.0;
    for (int i = 0; i < 4; ++i) err = std::max(err, std::abs(f[i] / ref[i] - 1.0));
    std::printf("t = %.2f %s n = %d: f1 = %.4f Hz (theory %.4f), max error of 4 modes %.2e\n", t,
                triangles ? "CTRIA3" : "CQUAD4", n, f[0], ref[0], err);
    if (n == 16) {
      EXPECT_LT(err, tol_moderate) << "n = 16";
    }
    EXPECT_LT(err, prev) << "n = " << n;
    prev = err;
  }
}

// Thin plate a/t = 200: f11 = 2.377 Hz (NAFEMS FV16 lists the same Kirchhoff values).
TEST(PlateFrequencies, ThinSimplySupportedQuads) { check_plate(0.05, false, false, 0.02); }
// Thick plate a/t = 10: shear lowers f11 by 2.7 % against Kirchhoff.
TEST(PlateFrequencies, ThickSimplySupportedQuads) {
  EXPECT_GT(theory_hz(1, 1, 1.0, false) / theory_hz(1, 1, 1.0, true), 1.02);
  check_plate(1.0, true, false, 0.02);
}
TEST(PlateFrequencies, ThinSimplySupportedTriangles) { check_plate(0.05, false, true, 0.02); }

}  // namespace
}  // namespace seflex::fem
