// Beam natural frequencies against theory and against the MYSTRAN validation decks BAR-CC/BAR-FF
// (transcribed here card by card; the reader-based test of the same decks lives with the reader).
#include <gtest/gtest.h>

#include <cmath>

#include "fem_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"

namespace seflex::fem {
namespace {

const double kPi = 3.14159265358979323846;

struct BeamSpec {
  int n = 4;
  double L = 100, E = 1e7, nu = 0.3, rho = 0.1, A = 0.1, I = 0.1, J = 0.1, K = 0.0, wtmass = 1.0;
  MassKind mass = MassKind::Lumped;
};

// Beam along basic x in n CBARs, bending in the x-z plane only (GRDSET PS 1246, as the BAR decks).
Model beam_model(const BeamSpec& s) {
  Model m;
  m.grdset.present = true;
  m.grdset.ps = test::mask("1246");
  for (int i = 0; i <= s.n; ++i) test::add_grid(m, i + 1, s.L * i / s.n, 0, 0);
  test::add_mat1(m, 20, s.E, s.nu, s.rho);
  BarProperty& p = test::add_pbar(m, 25, 20, s.A, s.I, s.I, s.J);
  p.K1 = p.K2 = s.K;
  for (int i = 0; i < s.n; ++i) test::add_cbar(m, 100 + i, 25, i + 1, i + 2, {0, 0, 1});
  test::finalize_for_test(m);
  return m;
}

// Frequencies (Hz) of the beam with `spc` fixed; shift > 0 for free-free.
std::vector<double> frequencies(const Model& m, const BeamSpec& s, std::optional<int> spc, double shift = 0.0) {
  AssemblyOptions o;
  o.mass = s.mass;
  o.wtmass = s.wtmass;
  const GlobalMatrices g = assemble(m, o);
  const ConstrainedSystem c = apply_constraints(m, g, spc);
  std::vector<double> f;
  for (double lam : test::dense_eigenvalues(test::dense(c.K_ff), test::dense(c.M_ff), shift))
    f.push_back(std::sqrt(std::max(lam, 0.0)) / (2 * kPi));
  return f;
}

// BAR-CC-GIV.DAT: 4 CBAR, PBAR A = I1 = I2 = J = .1, MAT1 E = 1e7, nu = .3, rho = .1, GRDSET PS
// 1246, SPC1 35 at grid 1, PARAM WTMASS .002591, default lumped mass. Reference: MYSTRAN 12.0
// (tests/data/validation/mystran_cbar_cantilever_and_freefree_modes/BAR-CC-GIV.reference.txt).
// MYSTRAN prints 7 significant digits: the reference itself is only good to half a unit in the last
// digit, at most 4.7e-7 relative (10.68719). Measured (2026-11-28): largest difference 2.9e-7
// (cantilever), 1.8e-7 (free-free), i.e. within that rounding; tolerance 1e-6, twice the rounding.
TEST(BeamFrequencies, BarCcMatchesMystranToItsPrintedDigits) {
  BeamSpec s;
  s.wtmass = 0.002591;
  Model m = beam_model(s);
  test::add_spc1(m, 1, test::mask("35"), 1);
  const auto f = frequencies(m, s, 1);
  const double ref[4] = {10.68719, 62.81653, 166.3460, 289.9396};
  ASSERT_GE(f.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(f[i] / ref[i], 1.0, 1e-6) << "mode " << i + 1 << " f = " << f[i];
}

// BAR-FF-GIV.DAT: the same bar free-free; two rigid modes, then 59.11978 / 150.0817 / 271.5359 Hz
// (tolerance: see above).
TEST(BeamFrequencies, BarFfMatchesMystranToItsPrintedDigits) {
  BeamSpec s;
  s.wtmass = 0.002591;
  const Model m = beam_model(s);
  const auto f = frequencies(m, s, std::nullopt, 100.0);
  ASSERT_EQ(f.size(), 5u);
  EXPECT_LT(f[1], 1e-4 * f[2]);
  const double ref[3] = {59.11978, 150.0817, 271.5359};
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[i + 2] / ref[i], 1.0, 1e-6) << "mode " << i + 3 << " f = " << f[i + 2];
}

// Euler-Bernoulli cantilever: omega_n = (beta_n L)^2 sqrt(EI / (rho A L^4)), beta_1 L = 1.8751041,
// beta_2 L = 4.6940911 (Blevins, Formulas for Natural Frequency and Mode Shape, table 8-1).
// Free-free: beta L = 4.7300408, 7.8532046. Both mass matrices converge at their theoretical rates.
TEST(BeamFrequencies, ConvergeToEulerBernoulli) {
  const double bl_cc[2] = {1.8751040687, 4.6940911330}, bl_ff[2] = {4.7300407449, 7.8532046241};
  for (MassKind kind : {MassKind::Lumped, MassKind::Coupled}) {
    double prev_cc = 1.0, prev_ff = 1.0;
    for (int n : {4, 8, 16, 32}) {
      BeamSpec s;
      s.n = n;
      s.L = 2.0;
      s.E = 7e10;
      s.rho = 2700;
      s.A = 1e-4;
      s.I = 1e-9;
      s.J = 2e-9;
      s.mass = kind;
      const double scale = std::sqrt(s.E * s.I / (s.rho * s.A * std::pow(s.L, 4))) / (2 * kPi);
      Model m = beam_model(s);
      test::add_spc1(m, 1, test::mask("35"), 1);
      const auto fcc = frequencies(m, s, 1);
      const auto fff = frequencies(beam_model(s), s, std::nullopt, 10.0);
      double err_cc = 0, err_ff = 0;
      for (int i = 0; i < 2; ++i) {
        err_cc = std::max(err_cc, std::abs(fcc[i] / (bl_cc[i] * bl_cc[i] * scale) - 1));
        err_ff = std::max(err_ff, std::abs(fff[i + 2] / (bl_ff[i] * bl_ff[i] * scale) - 1));
      }
      // lumped mass converges as h^2 (error / 4 per halving), the coupled (Hermite) mass as h^4
      const double rate = kind == MassKind::Lumped ? 3.5 : 12.0;
      if (n >= 16) {  // asymptotic range
        EXPECT_GT(prev_cc / err_cc, rate) << "n = " << n;
        EXPECT_GT(prev_ff / err_ff, rate) << "n = " << n;
      }
      prev_cc = err_cc;
      prev_ff = err_ff;
    }
    EXPECT_LT(prev_cc, kind == MassKind::Lumped ? 2e-3 : 1e-6);
    EXPECT_LT(prev_ff, kind == MassKind::Lumped ? 6e-3 : 1e-5);
  }
}

// Simply supported Timoshenko beam (shear flexible, no rotary inertia, as neither mass matrix has
// bending rotary inertia): omega_n^2 = EI k^4 / (rho A (1 + EI k^2 / (kappa G A))), k = n pi / L
// (Timoshenko, Vibration Problems in Engineering, 1955, sec. 61, rotary-inertia term dropped).
// L/h = 10: shear lowers f1 by 1.3 %, far more than the discretisation error at n = 32.
TEST(BeamFrequencies, ConvergeToTimoshenkoShearBeam) {
  const double L = 1.0, h = 0.1, E = 2e11, nu = 0.3, rho = 7800, kappa = 5.0 / 6.0;
  const double A = h * h, I = h * h * h * h / 12, G = E / (2 * (1 + nu));
  double prev = 1.0;
  for (int n : {8, 16, 32}) {
    BeamSpec s;
    s.n = n;
    s.L = L;
    s.E = E;
    s.nu = nu;
    s.rho = rho;
    s.A = A;
    s.I = I;
    s.J = 2 * I;
    s.K = kappa;
    Model m = beam_model(s);
    test::add_spc1(m, 1, test::mask("3"), 1);
    test::add_spc1(m, 1, test::mask("3"), n + 1);
    const auto f = frequencies(m, s, 1);
    double err = 0;
    for (int mode = 1; mode <= 2; ++mode) {
      const double k = mode * kPi / L;
      const double w2 = E * I * std::pow(k, 4) / (rho * A * (1 + E * I * k * k / (kappa * G * A)));
      const double fref = std::sqrt(w2) / (2 * kPi);
      err = std::max(err, std::abs(f[mode - 1] / fref - 1));
      if (n == 32 && mode == 1) {
        const double f_eb = std::sqrt(E * I / (rho * A)) * k * k / (2 * kPi);
        EXPECT_GT(std::abs(f[0] / f_eb - 1), 0.01);  // shear flexibility really matters here
      }
    }
    EXPECT_LT(err, prev) << "n = " << n;
    prev = err;
  }
  EXPECT_LT(prev, 2e-3);
}

}  // namespace
}  // namespace seflex::fem
