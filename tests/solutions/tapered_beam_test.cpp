// Tapered CBEAM (PBEAM and PBEAML stations): a cantilever whose A, I1, J vary linearly from end A to
// end B against the closed forms of the flexibility integrals (Castigliano, Roark's Formulas for
// Stress and Strain, ch. 8, beams of variable section):
//   axial  u = F int ds / (E A) = F L ln(A_B / A_A) / (E (A_B - A_A)),
//   twist  phi = T L ln(J_B / J_A) / (G (J_B - J_A)),
//   tip deflection under F_y  v = F int (L - s)^2 / (E I1(s)) ds
//     = F / (E b^3) [c^2 ln(c / a) - 2 c (c - a) + (c^2 - a^2) / 2],  a = I1_A, c = I1_B, b = (c - a) / L;
// a station in the middle (two linear pieces); the lumped mass and its centre; a PBEAML tube whose
// radius tapers (dimensions linear, properties not: against Simpson's rule on the exact section);
// the writer and back.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <sstream>
#include <string>

#include "nastran_test_util.hpp"
#include "statics_test_util.hpp"
#include "seflex/fem/mass_properties.hpp"
#include "seflex/io/nastran_writer.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

using test::num;
constexpr double kPi = 3.14159265358979323846;
constexpr double E = 7.0e10, nu = 0.3, G = E / (2 * (1 + nu)), rho = 2700.0, L = 2.0;
constexpr double F = 1000.0, T = 50.0;

std::string cantilever(const std::string& pbeam) {
  return "SOL 101\nCEND\nSPC = 1\nLOAD = 2\nBEGIN BULK\nMAT1,3," + num(E) + ",," + num(nu) + "," + num(rho) + "\n" + pbeam +
         "CBEAM,5,7,1,2,0.,1.,0.\nGRID,1,,0.,0.,0.\nGRID,2,," + num(L) + ",0.,0.\nSPC1,1,123456,1\n"
         "FORCE,2,2,," + num(F) + ",1.,1.,0.\nMOMENT,2,2,," + num(T) + ",1.,0.,0.\nENDDATA\n";
}

fem::Model round_trip(const fem::Model& m) {
  std::ostringstream out;
  io::write_nastran(m, out);
  return test::read_deck(out.str(), "converted.bdf");
}

/// int_0^L (L - s)^2 / I(s) ds for I linear from a to c.
double bending_integral(double a, double c) {
  const double b = (c - a) / L;
  return (c * c * std::log(c / a) - 2 * c * (c - a) + 0.5 * (c * c - a * a)) / (b * b * b);
}

TEST(TaperedBeam, LinearPbeamAgainstTheFlexibilityIntegrals) {
  const double AA = 4e-4, AB = 1e-4, IA = 8e-8, IB = 2e-8, JA = 1e-7, JB = 3e-8;
  // end A; end B as a station (NO, X/XB = 1); K1 = K2 = 0: no shear flexibility
  const std::string pbeam = "PBEAM,7,3," + num(AA) + "," + num(IA) + "," + num(IA) + ",0.," + num(JA) + "\n,NO,1.," + num(AB) + "," +
                            num(IB) + "," + num(IB) + ",0.," + num(JB) + "\n,0.,0.\n";
  const fem::Model m = test::read_deck(cantilever(pbeam));
  EXPECT_TRUE(m.unsupported.empty()) << m.unsupported.front().name;
  const double u = F * L * std::log(AB / AA) / (E * (AB - AA));
  const double phi = T * L * std::log(JB / JA) / (G * (JB - JA));
  const double v = F * bending_integral(IA, IB) / E;
  for (const fem::Model& model : {m, round_trip(m)}) {
    const auto s = solutions::solve_static(model);
    // measured: 1e-14, 1e-15 and 6e-15 of u, phi and v (4 x 8 Gauss points per interval)
    EXPECT_NEAR(test::displacement(model, s, 2, 1), u, 1e-13 * u);
    EXPECT_NEAR(test::displacement(model, s, 2, 4), phi, 1e-13 * phi);
    EXPECT_NEAR(test::displacement(model, s, 2, 2), v, 1e-13 * v);
  }
  // lumped mass rho L (A_A + A_B)/2, centre at L (A_A + 2 A_B) / (3 (A_A + A_B))
  const fem::MassProperties mp = fem::mass_properties(m);
  EXPECT_NEAR(mp.mass, rho * L * (AA + AB) / 2, 1e-12 * rho * L * AA);
  EXPECT_NEAR(mp.cg.x(), L * (AA + 2 * AB) / (3 * (AA + AB)), 1e-12);
}

TEST(TaperedBeam, MidStationMakesTwoLinearPieces) {
  const double IA = 8e-8, IM = 2e-8, A = 4e-4, J = 1e-7;
  // I1 = IA at end A, IM at the station X/XB = 0.5 and at end B: linear, then constant
  const std::string pbeam = "PBEAM,7,3," + num(A) + "," + num(IA) + "," + num(IA) + ",0.," + num(J) + "\n,NO,0.5," + num(A) + "," +
                            num(IM) + "," + num(IM) + ",0.," + num(J) + "\n,NO,1.," + num(A) + "," + num(IM) + "," + num(IM) + ",0.," +
                            num(J) + "\n,0.,0.\n";
  const fem::Model m = test::read_deck(cantilever(pbeam));
  // first half: I linear from IA to IM over [0, L/2], (L - s)^2 weighting; second half constant IM
  const double h = L / 2, b = (IM - IA) / h;
  double first = 0;  // int_0^h (L - s)^2 / (IA + b s) ds by the substitution w = IA + b s
  {
    const double c = IA + b * L;  // (L - s) = (c - w) / b
    auto prim = [&](double w) { return (c * c * std::log(w) - 2 * c * w + 0.5 * w * w) / (b * b * b); };
    first = prim(IM) - prim(IA);
  }
  const double second = h * h * h / 3 / IM;  // int_h^L (L - s)^2 ds / IM
  const double v = F * (first + second) / E;
  const auto s = solutions::solve_static(m);
  EXPECT_NEAR(test::displacement(m, s, 2, 2), v, 1e-13 * v);  // measured 4e-15
}

// PBEAML TUBE with the outer radius tapering from 0.03 to 0.02 (inner 0.01): the dimensions are
// linear, the section not; the reference integrates the exact I(s) by Simpson's rule (2000 panels).
TEST(TaperedBeam, PbeamlTubeWithTaperedRadius) {
  const double ro_a = 0.03, ro_b = 0.02, ri = 0.01;
  const fem::Model m = test::read_deck(cantilever("PBEAML,7,3,,TUBE\n," + num(ro_a) + "," + num(ri) + ",0.,NO,1.," + num(ro_b) + "," +
                                                  num(ri) + ",0.\n"));
  EXPECT_TRUE(m.unsupported.empty());
  auto I = [&](double s) {
    const double ro = ro_a + (ro_b - ro_a) * s / L;
    return kPi * (std::pow(ro, 4) - std::pow(ri, 4)) / 4;
  };
  const int n = 2000;
  double integral = 0;
  for (int k = 0; k <= n; ++k) {
    const double s = L * k / n, w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    integral += w * (L - s) * (L - s) / I(s);
  }
  integral *= L / n / 3;
  const double v = F * integral / E;
  const auto s = solutions::solve_static(m);
  const double v_seflex = test::displacement(m, s, 2, 2);
  // the tube's shear flexibility F int ds / (K G A) with K = 0.5 (fem/beam_section.hpp), A = pi (ro^2 - ri^2)
  double shear = 0;
  for (int k = 0; k <= n; ++k) {
    const double sx = L * k / n, w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    const double ro = ro_a + (ro_b - ro_a) * sx / L;
    shear += w / (0.5 * G * kPi * (ro * ro - ri * ri));
  }
  shear *= F * L / n / 3;
  // measured -1.42e-4: the section properties are linear between 32 sections per station interval
  EXPECT_NEAR(v_seflex, v + shear, 2.1e-4 * (v + shear)) << (v_seflex / (v + shear) - 1);
  const fem::Model back = round_trip(m);
  EXPECT_NEAR(test::displacement(back, solutions::solve_static(back), 2, 2), v_seflex, 1e-12 * v_seflex);
}

}  // namespace
}  // namespace seflex
