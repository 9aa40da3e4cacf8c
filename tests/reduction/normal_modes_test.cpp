// Normal-modes solution: MYSTRAN's bar decks (frequencies, normalisation, generalised mass and
// stiffness), free-free plates (rigid-body mode count, Spectra vs ARPACK vs dense), EIGRL ranges.
#include "seflex/reduction/normal_modes.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "fem_models.hpp"

namespace seflex::reduction {
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
    EXPECT_NEAR(r.cycles()(j) / cycles[j], 1.0, 1e-5) << "mode " << j + 1;
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
  EXPECT_NEAR(r.cycles()(2) / 5.911978E+01, 1.0, 1e-5);
  EXPECT_NEAR(r.cycles()(3) / 1.500817E+02, 1.0, 1e-5);
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
  EXPECT_NEAR(r.cycles()(1) / 6.281653E+01, 1.0, 1e-5);
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
  for (auto backend : {EigenBackend::Spectra, EigenBackend::Arpack, EigenBackend::Block}) {
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
  o.backend = EigenBackend::Dense;
  const NormalModes dense = solve_normal_modes(m, o);
  EXPECT_EQ(dense.stats.backend_used, EigenBackend::Dense);
  expect_six_rigid_body_modes(dense);
  for (auto backend : {ModesOptions{}.backend, EigenBackend::Spectra}) {
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

TEST(NormalModes, MissingOrUndefinedMethodIsAnInputError) {
  fem::Model m = test::mystran_bar(true);
  m.case_control.global.method.reset();
  EXPECT_THROW(solve_normal_modes(m), InputError);
  m.case_control.global.method = 9;
  try {
    solve_normal_modes(m);
    FAIL() << "no error for METHOD = 9";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("METHOD = 9"), std::string::npos) << e.what();
  }
  m.case_control.global.method = 1;
  m.eigen_methods[0].nd.reset();
  EXPECT_THROW(solve_normal_modes(m), InputError);  // nothing bounds the number of modes
}

}  // namespace
}  // namespace seflex::reduction
