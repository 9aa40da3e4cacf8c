// Normal modes of the external validation decks (tests/data/validation, MYSTRAN 12.0 / 17 results;
// provenance in its README.md), read with the Nastran reader and solved with the fem library's
// assembly and constraints and Eigen's dense symmetric eigensolver.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "seflex/fem/assembly.hpp"
#include "seflex/fem/components.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/io/nastran.hpp"
#include "test_support.hpp"

using namespace seflex;

namespace {

const double kPi = 3.14159265358979323846;

fem::Model deck(const char* rel) { return io::read_nastran(test::validation_dir() / rel); }

/// Finite eigenvalues (ascending) of K x = lambda M x, K + shift M positive definite, M singular
/// on the massless rotations (their infinite eigenvalues are dropped).
std::vector<double> eigenvalues(const fem::ConstrainedSystem& c, double shift = 0.0) {
  const Eigen::MatrixXd K(c.K_ff), M(c.M_ff);
  const Eigen::LLT<Eigen::MatrixXd> llt(K + shift * M);
  EXPECT_EQ(llt.info(), Eigen::Success);
  Eigen::MatrixXd C = llt.matrixL().solve(M);
  C = llt.matrixL().solve(C.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (C + C.transpose()));
  std::vector<double> lam;
  const double top = es.eigenvalues().maxCoeff();
  for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i)
    if (es.eigenvalues()[i] > 1e-12 * top) lam.push_back(1.0 / es.eigenvalues()[i] - shift);
  std::sort(lam.begin(), lam.end());
  return lam;
}

double hz(double lambda) { return std::sqrt(std::max(lambda, 0.0)) / (2 * kPi); }

fem::ConstrainedSystem constrained(const fem::Model& m, const fem::GlobalMatrices& g,
                                   const std::vector<Eigen::Index>& fixed = {}) {
  return fem::apply_constraints(m, g, m.case_control.global.spc, fixed);
}

}  // namespace

// BAR-CC-GIV: cantilever, 4 CBAR, WTMASS, lumped mass; MYSTRAN 10.68719 / 62.81653 / 166.3460 /
// 289.9396 Hz. The 7 printed digits are good to 4.7e-7 relative at most; measured (2026-11-28)
// largest difference 2.9e-7, tolerance 1e-6 (twice the print rounding; also for BAR-FF-GIV).
TEST(ValidationModes, BarCantilever) {
  const fem::Model m = deck("mystran_cbar_cantilever_and_freefree_modes/BAR-CC-GIV.DAT");
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  const auto lam = eigenvalues(constrained(m, g));
  const double ref[4] = {10.68719, 62.81653, 166.3460, 289.9396};
  ASSERT_GE(lam.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(hz(lam[i]) / ref[i], 1.0, 1e-6) << "mode " << i + 1;
}

// BAR-FF-GIV: the same bar free-free: two rigid modes, then 59.11978 / 150.0817 / 271.5359 Hz.
TEST(ValidationModes, BarFreeFree) {
  const fem::Model m = deck("mystran_cbar_cantilever_and_freefree_modes/BAR-FF-GIV.DAT");
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  const auto lam = eigenvalues(constrained(m, g), 1e4);
  ASSERT_EQ(lam.size(), 5u);
  EXPECT_LT(hz(lam[1]), 1e-4 * hz(lam[2]));
  const double ref[3] = {59.11978, 150.0817, 271.5359};
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(hz(lam[i + 2]) / ref[i], 1.0, 1e-6) << "mode " << i + 3;
}

// ALL-ELEM-TEST-GIV: CBAR (BAROR), CROD, CQUAD4, CTRIA3, CELAS1, MAT1 with G given, SPC set 998;
// MYSTRAN 34.46520 / 39.34327 / 63.02253 / 74.00890 Hz, expected agreement about 1 % (different
// shell formulations).
TEST(ValidationModes, MixedElements) {
  const fem::Model m = deck("mystran_mixed_cbar_crod_cquad4_ctria3_celas_modes/ALL-ELEM-TEST-GIV.DAT");
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  const auto lam = eigenvalues(constrained(m, g));
  const double ref[4] = {34.46520, 39.34327, 63.02253, 74.00890};
  ASSERT_GE(lam.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    std::printf("ALL-ELEM mode %d: %.5f Hz (MYSTRAN %.5f, ratio %.5f)\n", i + 1, hz(lam[i]), ref[i], hz(lam[i]) / ref[i]);
    // issue 3 asks 1 %; measured (2026-11-28) 3.6e-5 at most (the shell formulations differ):
    // tolerance 6e-5, about 1.7 times that
    EXPECT_NEAR(hz(lam[i]) / ref[i], 1.0, 6e-5) << "mode " << i + 1;
  }
}

// CB-EXAMPLE-12: CBAR frame with pin flags, CONM2 with offsets (one on an RBE2 dependent grid),
// SPC1; the SUPORT dofs (the Craig-Bampton boundary) held fixed: the fixed-interface eigenvalues
// are the diagonal of MYSTRAN 17's KXX (mystran17_run_CB_matrices.txt, 15 digits; MYSTRAN 12.0
// prints the same 3895.211 / 7011.163 / 8533.585). Measured (2026-11-28): 3.9e-15, round-off against
// the 15 printed digits; tolerance 1e-12.
TEST(ValidationModes, CraigBamptonFrameFixedInterface) {
  const fem::Model m = deck("mystran_craig_bampton_cbar_frame/CB-EXAMPLE-12.DAT");
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  std::vector<Eigen::Index> boundary;
  for (const fem::DofSetEntry& e : m.suport)
    for (int c = 1; c <= 6; ++c)
      if (fem::has_component(e.c, c)) boundary.push_back(g.dofs.grid_dof(m.grid_index.at(e.grid), c));
  ASSERT_EQ(boundary.size(), 8u);
  const fem::ConstrainedSystem c = constrained(m, g, boundary);
  EXPECT_EQ(std::count(c.status.begin(), c.status.end(), fem::DofStatus::Dependent), 6);
  const auto lam = eigenvalues(c);
  const double ref[3] = {3.89521138255555e+03, 7.01116273348857e+03, 8.53358493285352e+03};
  ASSERT_GE(lam.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(lam[i] / ref[i], 1.0, 1e-12) << "mode " << i + 1 << ": " << lam[i];
}
