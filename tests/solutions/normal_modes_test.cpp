// Normal-modes solution: MYSTRAN's bar decks (frequencies, normalisation, generalised mass and
// stiffness), free-free plates (rigid-body mode count, Spectra vs ARPACK vs dense), EIGRL ranges.
#include "seflex/solutions/normal_modes.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "fem_models.hpp"

namespace seflex::solutions {
namespace {

// BAR-CC-GIV (MYSTRAN 12.0, tests/data/validation/mystran_cbar_cantilever_and_freefree_modes/
// BAR-CC-GIV.reference.txt): REAL EIGENVALUES with NORM = MAX, and eigenvector 1.
TEST(NormalModes, MystranBarCcFrequenciesAndMaxNormalisation) {
  const fem::Model m = test::mystran_bar(true);
  const NormalModes r = solve_normal_modes(m);
  ASSERT_EQ(r.eigenvalues.size(), 4);
  EXPECT_EQ(r.normalization, ModeNormalization::Max);
  const double cycles[4] = {1.068719E+01, 6.281653E+01, 1.663460E+02, 2.899396E+02};
  const double gen_mass[4] = {6.800571E-04, 9.499997E-04, 1.461918E-03, 1.590132E-03};
  const double gen_stiff[4] = {3.066423E+00, 1.479896E+02, 1.597008E+03, 5.277256E+03};
  for (int j = 0; j < 4; ++j) {
    // 7 printed digits: good to 4.7e-7 relative at most; measured (2026-11-28) 2.9e-7
    EXPECT_NEAR(r.cycles()(j) / cycles[j], 1.0, 1e-6) << "mode " << j + 1;
    EXPECT_NEAR(r.generalized_mass(j) / gen_mass[j], 1.0, 2e-6) << "mode " << j + 1;  // 7 printed digits
    EXPECT_NEAR(r.generalized_stiffness(j) / gen_stiff[j], 1.0, 2e-6) << "mode " << j + 1;
  }
  // eigenvector 1: T3 of grids 2..5 and R2 of grid 5 as printed
  const auto t3 = [&](int grid) { return r.shapes_g(r.dofs.grid_dof(grid - 1, 3), 0); };
  EXPECT_NEAR(t3(2), 9.586856E-02, 1e-7);
  EXPECT_NEAR(t3(3), 3.359532E-01, 1e-7);
  EXPECT_NEAR(t3(5), 1.0, 1e-12);
  EXPECT_NEAR(r.shapes_g(r.dofs.grid_dof(4, 5), 0), -1.398892E-02, 1e-8);
  EXPECT_EQ(r.shapes_g.col(0).head(6).norm(), 0.0);  // grid 1 is clamped
}

// BAR-FF-GIV: NORM = POINT (grid 5, T3); two rigid-body modes, then the elastic ones.
TEST(NormalModes, MystranBarFfPointNormalisation) {
  const fem::Model m = test::mystran_bar(false);
  const NormalModes r = solve_normal_modes(m);
  ASSERT_EQ(r.eigenvalues.size(), 4);
  EXPECT_LT(r.cycles()(1), 1e-4 * r.cycles()(2));
  EXPECT_NEAR(r.cycles()(2) / 5.911978E+01, 1.0, 1e-6);  // 7 printed digits (see above)
  EXPECT_NEAR(r.cycles()(3) / 1.500817E+02, 1.0, 1e-6);
  EXPECT_NEAR(r.generalized_mass(2) / 9.738369E-04, 1.0, 2e-6);
  EXPECT_NEAR(r.generalized_mass(3) / 1.943250E-03, 1.0, 2e-6);
  for (int j = 0; j < 4; ++j) EXPECT_NEAR(r.shapes_g(r.dofs.grid_dof(4, 3), j), 1.0, 1e-12) << "mode " << j + 1;
}

TEST(NormalModes, CountOverridesNd) {
  const fem::Model m = test::mystran_bar(true);
  ModesOptions o;
  o.count = 2;
  const NormalModes r = solve_normal_modes(m, o);
  ASSERT_EQ(r.eigenvalues.size(), 2);
  EXPECT_NEAR(r.cycles()(1) / 6.281653E+01, 1.0, 1e-6);
}

/// Free aluminium plate 0.6 x 0.4 x 3 mm of nx x ny CQUAD4 (24 x 16: 2,550 dofs, the Krylov
/// backends run).
fem::Model free_plate(int nx = 24, int ny = 16) {
  fem::Model m = test::quad_plate(nx, ny, 0.6, 0.4, 0.003, 7.0e10, 0.33, 2700);
  test::finalize_for_test(m);
  return m;
}

void expect_six_rigid_body_modes(const NormalModes& r) {
  const double f7 = r.cycles()(6);
  int rigid = 0;
  for (Eigen::Index j = 0; j < r.cycles().size(); ++j) rigid += r.cycles()(j) < 1e-4 * f7;
  EXPECT_EQ(rigid, 6) << to_string(r.stats.backend_used);
  EXPECT_GT(f7, 10.0);  // a 0.6 m x 3 mm plate: its first free mode is tens of Hz
}

// Free-free model: exactly six modes below 1e-4 of the first elastic frequency, with Spectra,
// ARPACK and block Lanczos, which agree on the elastic modes.
TEST(NormalModes, FreePlateHasSixRigidBodyModesWithEveryKrylovBackend) {
  const fem::Model m = free_plate();
  std::vector<NormalModes> results;
  for (auto backend : {linalg::EigenBackend::Spectra, linalg::EigenBackend::Arpack, linalg::EigenBackend::Block}) {
    ModesOptions o;
    o.count = 14;
    o.backend = backend;
    results.push_back(solve_normal_modes(m, o));
    const NormalModes& r = results.back();
    ASSERT_EQ(r.eigenvalues.size(), 14) << to_string(backend);
    EXPECT_EQ(r.stats.backend_used, backend);
    expect_six_rigid_body_modes(r);
    EXPECT_LT((r.generalized_mass.array() - 1.0).abs().maxCoeff(), 1e-10);  // NORM = MASS (no METHOD)
    EXPECT_LT((r.generalized_stiffness - r.eigenvalues).cwiseAbs().maxCoeff(), 1e-8 * r.eigenvalues(13));
  }
  for (std::size_t b = 1; b < results.size(); ++b)
    for (int j = 6; j < 14; ++j)
      EXPECT_NEAR(results[0].eigenvalues(j) / results[b].eigenvalues(j), 1.0, 1e-10) << "backend " << b << " mode " << j + 1;
}

// The Krylov paths (the default block Lanczos and Spectra) against the dense solution of the whole
// pencil, on a smaller free plate.
TEST(NormalModes, KrylovMatchesTheDenseSolution) {
  const fem::Model m = free_plate(10, 7);  // 528 dofs
  ModesOptions o;
  o.count = 12;
  o.backend = linalg::EigenBackend::Dense;
  const NormalModes dense = solve_normal_modes(m, o);
  EXPECT_EQ(dense.stats.backend_used, linalg::EigenBackend::Dense);
  expect_six_rigid_body_modes(dense);
  for (auto backend : {ModesOptions{}.backend, linalg::EigenBackend::Spectra}) {
    o.backend = backend;
    const NormalModes krylov = solve_normal_modes(m, o);
    EXPECT_EQ(krylov.stats.backend_used, backend);
    for (int j = 6; j < 12; ++j)
      EXPECT_NEAR(krylov.eigenvalues(j) / dense.eigenvalues(j), 1.0, 1e-10) << to_string(backend) << " mode " << j + 1;
  }
}

// EIGRL F1/F2 (Hz) without ND: every mode in the band, none outside; F1 above zero drops the
// rigid-body modes.
TEST(NormalModes, EigrlFrequencyBand) {
  fem::Model m = free_plate();
  ModesOptions o;
  o.count = 20;
  const NormalModes all = solve_normal_modes(m, o);
  const double f1 = 0.5 * (all.cycles()(8) + all.cycles()(9)), f2 = 0.5 * (all.cycles()(15) + all.cycles()(16));
  fem::EigenMethod band;
  band.sid = 3;
  band.f1 = f1;
  band.f2 = f2;
  m.eigen_methods.push_back(band);
  m.case_control.global.method = 3;
  const NormalModes r = solve_normal_modes(m);
  ASSERT_EQ(r.eigenvalues.size(), 7);  // modes 10..16
  for (int j = 0; j < 7; ++j) EXPECT_NEAR(r.eigenvalues(j) / all.eigenvalues(j + 9), 1.0, 1e-10);
}

/// The message of the InputError solve_normal_modes throws for `m` (a failure if it throws none).
std::string modes_input_error(const fem::Model& m) {
  try {
    solve_normal_modes(m);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

// Each refusal names the deck, the card (EIGR 1) or case-control entry and what the user must give.
TEST(NormalModes, MissingOrUndefinedMethodIsAnInputError) {
  fem::Model m = test::mystran_bar(true);
  m.case_control.global.method.reset();
  EXPECT_EQ(modes_input_error(m),
            "BAR-CC-GIV.DAT: case control selects no METHOD (EIGRL/EIGR) for normal modes; add METHOD = <sid> or give "
            "the number of modes with --count");
  m.case_control.global.method = 9;
  EXPECT_EQ(modes_input_error(m), "BAR-CC-GIV.DAT: case control METHOD: the global case control: METHOD = 9 selects no "
                                  "EIGRL or EIGR card; normal modes (SOL 103) cannot run without it");
  m.case_control.global.method = 1;
  m.eigen_methods[0].norm = "LARGEST";
  EXPECT_EQ(modes_input_error(m), "BAR-CC-GIV.DAT: EIGR 1: NORM 'LARGEST' is not MASS, MAX or POINT");
  m.eigen_methods[0].norm = "MAX";
  m.eigen_methods[0].nd.reset();  // nothing bounds the number of modes
  EXPECT_EQ(modes_input_error(m),
            "BAR-CC-GIV.DAT: EIGR 1: neither ND (number of roots) nor F2 (upper frequency) is given, so nothing bounds "
            "the number of modes; set one of them or use --count");
}


/// MYSTRAN's GUYAN-03 deck (MYSTRANsolver/MYSTRAN_Benchmark, Benchmark_Decks/EB-GUYAN-03-GIV.DAT and
/// the 12.0 test runs' Eigen/Sparse/Current/GUYAN-03-GIV.DAT, commit ad765ad), transcribed card by
/// card: two CBARs of 10 along x (PBAR 10: A = .01, I1 = I2 = J = .1; MAT1 10: E = 1e7, nu = .33,
/// rho = .1), GRDSET PS 1345 (bending in the x-y plane: T2, R3 free), SPC1 123 26 101, ASET1 26 103,
/// PARAM WTMASS .002591, EIGR GIV for all modes.
fem::Model guyan_beam(bool aset) {
  fem::Model m;
  m.files = {"GUYAN-03-GIV.DAT"};
  m.grdset.present = true;
  m.grdset.ps = test::mask("1345");
  for (int i = 0; i < 3; ++i) test::add_grid(m, 101 + i, 10.0 * i, 0, 0);
  test::add_mat1(m, 10, 1.0e7, 0.33, 0.1);
  test::add_pbar(m, 10, 10, 0.01, 0.1, 0.1, 0.1);
  test::add_cbar(m, 11, 10, 101, 102, {0, 1, 0});
  test::add_cbar(m, 12, 10, 102, 103, {0, 1, 0});
  test::add_spc1(m, 123, test::mask("26"), 101);
  if (aset) m.aset.push_back({103, test::mask("26"), {}});
  m.params.push_back(fem::Param{"WTMASS", {".002591"}, {}});
  fem::EigenMethod method;
  method.sid = 1;
  method.is_eigr = true;
  method.method = "GIV";
  method.nd = 10;
  m.eigen_methods.push_back(method);
  m.case_control.global.spc = 123;
  m.case_control.global.method = 1;
  test::finalize_for_test(m);
  return m;
}

// Guyan reduction to ASET1 26 103 (the tip's T2, R3), checked against a hand-computed condensation:
// - K_aa_bar is the exact tip stiffness of the cantilever (cubic beam elements reproduce the static
//   deflection): the inverse of the flexibility [[L^3/3EI, L^2/2EI], [L^2/2EI, L/EI]], L = 20;
// - the omitted grid 102 follows the static shape: for tip (w, theta) = K_bar^-1 (P, M) the
//   cantilever's w(x) = P x^2 (3L - x) / 6EI + M x^2 / 2EI at x = 10 (Timoshenko & Gere, table G-1),
//   so w_102 = g . (w, theta), g = [l^2 (3L - l) / 6EI, l^2 / 2EI] K_bar;
// - the CBAR lumped mass is translational: WTMASS rho A l = 2.591e-5 at grid 102, half at 103, so
//   M_aa_bar = m g g^T + diag(m / 2, 0);
// and the 2 x 2 eigenproblem solved in closed form. MYSTRAN 12.0 prints the same two eigenvalues
// (Eigen/Sparse/Archive/GUYAN-03-GIV.arc: 2.413794E+07, 1.481072E+09); the full model's (no ASET)
// differ: two finite eigenvalues too (the rotations are massless), each below the Guyan one (the
// condensed model is a Rayleigh-Ritz approximation of the full one: its eigenvalues are upper bounds).
TEST(NormalModes, GuyanReductionToTheAsetMatchesHandCondensationAndMystran) {
  const double E = 1e7, I = 0.1, l = 10, L = 20, EI = E * I, m = 0.002591 * 0.1 * 0.01 * l;
  const double a = L * L * L / (3 * EI), b = L * L / (2 * EI), c = L / EI, det = a * c - b * b;
  const double K[2][2] = {{c / det, -b / det}, {-b / det, a / det}};
  const double h[2] = {l * l * (3 * L - l) / (6 * EI), l * l / (2 * EI)};
  const double g[2] = {h[0] * K[0][0] + h[1] * K[1][0], h[0] * K[0][1] + h[1] * K[1][1]};
  const double M[2][2] = {{m * g[0] * g[0] + m / 2, m * g[0] * g[1]}, {m * g[0] * g[1], m * g[1] * g[1]}};
  const double qa = M[0][0] * M[1][1] - M[0][1] * M[0][1];
  const double qb = -(K[0][0] * M[1][1] + K[1][1] * M[0][0] - 2 * K[0][1] * M[0][1]);
  const double qc = K[0][0] * K[1][1] - K[0][1] * K[0][1];
  const double disc = std::sqrt(qb * qb - 4 * qa * qc);
  const double hand[2] = {(-qb - disc) / (2 * qa), (-qb + disc) / (2 * qa)};
  const double mystran[2] = {2.413794E+07, 1.481072E+09};

  const NormalModes r = solve_normal_modes(guyan_beam(true));
  ASSERT_TRUE(r.guyan.has_value());
  EXPECT_EQ(r.guyan->a_dofs, 2);
  EXPECT_EQ(r.guyan->o_dofs, 2);  // grid 102's T2 and R3
  ASSERT_EQ(r.eigenvalues.size(), 2);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(r.eigenvalues(k) / hand[k], 1.0, 1e-10) << "mode " << k + 1;
    EXPECT_NEAR(r.eigenvalues(k) / mystran[k], 1.0, 5e-7) << "mode " << k + 1;  // 7 printed digits
  }
  // the omitted grid's motion is the static shape of the tip's: w_102 = g . (w_103, theta_103)
  for (int k = 0; k < 2; ++k) {
    const double w = r.shapes_g(r.dofs.grid_dof(2, 2), k), th = r.shapes_g(r.dofs.grid_dof(2, 6), k);
    EXPECT_NEAR(r.shapes_g(r.dofs.grid_dof(1, 2), k), g[0] * w + g[1] * th, 1e-12 * std::abs(w)) << "mode " << k + 1;
  }
  // generalised mass: the modes are mass-normalised on the reduced mass
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(r.generalized_mass(k), 1.0, 1e-12);

  const NormalModes full = solve_normal_modes(guyan_beam(false));
  EXPECT_FALSE(full.guyan.has_value());
  ASSERT_EQ(full.eigenvalues.size(), 2);
  for (int k = 0; k < 2; ++k) EXPECT_LT(full.eigenvalues(k), r.eigenvalues(k) * (1 - 1e-4)) << "mode " << k + 1;
}

// OMIT1 of the same dofs' complement gives the same a-set; a dof both in ASET and held by an SPC is
// an error naming the ASET card, as Nastran's mutually exclusive sets.
TEST(NormalModes, OmitGivesTheSameReductionAndConflictsAreErrors) {
  fem::Model m = guyan_beam(false);
  m.omit.push_back({102, test::mask("26"), {}});
  test::finalize_for_test(m);
  const NormalModes r = solve_normal_modes(m), a = solve_normal_modes(guyan_beam(true));
  ASSERT_TRUE(r.guyan.has_value());
  EXPECT_FALSE(r.guyan->from_aset);
  ASSERT_EQ(r.eigenvalues.size(), 2);
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(r.eigenvalues(k) / a.eigenvalues(k), 1.0, 1e-12);

  fem::Model bad = guyan_beam(true);
  bad.aset.push_back({101, test::mask("2"), {}});
  test::finalize_for_test(bad);
  try {
    solve_normal_modes(bad);
    FAIL() << "an SPC'd dof in the a-set was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ASET/ASET1: grid 101 component 2 is in the a-set but also constrained"),
              std::string::npos)
        << e.what();
  }
}
}  // namespace
}  // namespace seflex::solutions
