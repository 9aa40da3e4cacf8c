// Generalised eigensolver against analytic spectra, an independent dense reference (massless dofs
// condensed exactly), MYSTRAN's beam frequencies, and between its backends.
#include "seflex/linalg/eigensolver.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <numbers>
#include <sstream>

#include "test_problems.hpp"

namespace seflex::linalg {
namespace {

using test::Pencil;

EigenOptions krylov(EigenBackend backend, int count) {
  EigenOptions o;
  o.backend = backend;
  o.count = count;
  o.dense_below = 0;  // force the Krylov backend even on small test problems
  return o;
}

double hz(double lambda) { return std::sqrt(std::abs(lambda)) / (2 * std::numbers::pi); }

/// X^T M X = I, and backward errors within the Lanczos tolerance asked for.
void expect_eigenpairs(const Pencil& p, const EigenSolution& s, double tol = EigenOptions{}.tolerance) {
  const Eigen::MatrixXd MX = p.M * s.vectors;
  const Eigen::MatrixXd G = s.vectors.transpose() * MX;
  EXPECT_LT((G - Eigen::MatrixXd::Identity(G.rows(), G.cols())).cwiseAbs().maxCoeff(), 1e-10);
  for (Eigen::Index j = 0; j < s.eigenvalues.size(); ++j) EXPECT_LT(s.backward_errors(j), tol) << "mode " << j;
}

class KrylovBackend : public ::testing::TestWithParam<EigenBackend> {};

// Fixed-fixed chain of 400 masses: 12 lowest eigenvalues to 1e-11 of the analytic values.
TEST_P(KrylovBackend, SpringChainMatchesTheAnalyticSpectrum) {
  const int n = 400;
  const Pencil p = test::spring_chain(n, 1.0e4, 0.5, true);
  const EigenSolution s = solve_eigenproblem(p.K, p.M, krylov(GetParam(), 12));
  ASSERT_EQ(s.eigenvalues.size(), 12);
  for (int j = 0; j < 12; ++j)
    EXPECT_NEAR(s.eigenvalues(j) / test::chain_eigenvalue(n, 1.0e4, 0.5, true, j + 1), 1.0, 1e-11) << "mode " << j + 1;
  expect_eigenpairs(p, s);
  EXPECT_EQ(s.stats.backend_used, GetParam());
  EXPECT_LT(s.stats.shift, 0.0);
}

// Half of the dofs massless: M is singular, eigenvalues are still those of the plain chain, and
// the eigenvectors carry no spurious component on the massless dofs (they satisfy K x = lambda M x
// row by row, including the massless rows).
TEST_P(KrylovBackend, SingularLumpedMassWithMasslessDofs) {
  const int n = 300;
  const Pencil p = test::chain_with_massless_nodes(n, 2.0e3, 0.25);
  const EigenSolution s = solve_eigenproblem(p.K, p.M, krylov(GetParam(), 10));
  ASSERT_EQ(s.eigenvalues.size(), 10);
  for (int j = 0; j < 10; ++j)
    EXPECT_NEAR(s.eigenvalues(j) / test::chain_eigenvalue(n, 2.0e3, 0.25, true, j + 1), 1.0, 1e-10) << "mode " << j + 1;
  expect_eigenpairs(p, s);
}

// Square Laplacian plate: eigenvalues (p, q) and (q, p) coincide. All copies must be found: the 20
// lowest agree with the analytic list, pairs included.
TEST_P(KrylovBackend, FindsEveryCopyOfDoubleEigenvaluesOfASquarePlate) {
  const int N = 30;
  const Pencil p = test::laplacian_plate(N);
  const std::vector<double> exact = test::laplacian_plate_eigenvalues(N);
  const EigenSolution s = solve_eigenproblem(p.K, p.M, krylov(GetParam(), 20));
  ASSERT_EQ(s.eigenvalues.size(), 20);
  for (int j = 0; j < 20; ++j) EXPECT_NEAR(s.eigenvalues(j), exact[static_cast<std::size_t>(j)], 1e-11) << "mode " << j + 1;
  expect_eigenpairs(p, s);
}

// Two identical, disconnected chains: every eigenvalue is exactly double, and a single-vector
// Krylov space sees only one combination of each pair. The completeness check (deflated Lanczos
// runs) must recover the other copies: the 10 lowest are the 5 lowest of one chain, twice each.
TEST_P(KrylovBackend, RecoversExactDuplicatesOfTwoIdenticalChains) {
  const int n = 150;
  const Pencil one = test::spring_chain(n, 5.0, 0.5, true);
  test::Triplets kt, mt;
  for (int copy = 0; copy < 2; ++copy)
    for (int j = 0; j < n; ++j) {
      for (test::Sparse::InnerIterator it(one.K, j); it; ++it) kt.emplace_back(it.row() + copy * n, j + copy * n, it.value());
      mt.emplace_back(j + copy * n, j + copy * n, 0.5);
    }
  const Pencil p{test::from_triplets(2 * n, kt), test::from_triplets(2 * n, mt)};
  const EigenSolution s = solve_eigenproblem(p.K, p.M, krylov(GetParam(), 10));
  ASSERT_EQ(s.eigenvalues.size(), 10);
  for (int j = 0; j < 10; ++j)
    EXPECT_NEAR(s.eigenvalues(j) / test::chain_eigenvalue(n, 5.0, 0.5, true, j / 2 + 1), 1.0, 1e-10) << "mode " << j + 1;
  expect_eigenpairs(p, s);
}

// Ten identical, disconnected chains: every eigenvalue has multiplicity 10, more than a block of 4
// holds. In exact arithmetic block Lanczos sees 4 copies of each; the completeness check (run
// because of the cluster of >= 4 equal eigenvalues) or round-off entering the block Krylov space
// must bring in the other six copies of the two lowest eigenvalues.
TEST(Eigensolver, BlockLanczosRecoversCopiesBeyondItsBlockSize) {
  const int n = 60, copies = 10;
  const Pencil one = test::spring_chain(n, 5.0, 0.5, true);
  test::Triplets kt, mt;
  for (int copy = 0; copy < copies; ++copy)
    for (int j = 0; j < n; ++j) {
      for (test::Sparse::InnerIterator it(one.K, j); it; ++it) kt.emplace_back(it.row() + copy * n, j + copy * n, it.value());
      mt.emplace_back(j + copy * n, j + copy * n, 0.5);
    }
  const Pencil p{test::from_triplets(copies * n, kt), test::from_triplets(copies * n, mt)};
  EigenOptions o = krylov(EigenBackend::Block, 20);
  o.block_size = 4;
  const EigenSolution s = solve_eigenproblem(p.K, p.M, o);
  ASSERT_EQ(s.eigenvalues.size(), 20);
  EXPECT_EQ(s.stats.backend_used, EigenBackend::Block);
  for (int j = 0; j < 20; ++j)
    EXPECT_NEAR(s.eigenvalues(j) / test::chain_eigenvalue(n, 5.0, 0.5, true, j / copies + 1), 1.0, 1e-10) << "mode " << j + 1;
  expect_eigenpairs(p, s);
}

// Free-floating truss with massless nodes: exactly six rigid-body modes, far below the first
// elastic one, spanning the rigid-body motions; elastic modes match the condensed dense reference.
TEST_P(KrylovBackend, FreeFreeTrussHasExactlySixRigidBodyModes) {
  const test::Truss truss = test::free_truss(5, 4, 3, 7.0e6, 1.5);
  const Pencil& p = truss.pencil;
  const Eigen::VectorXd ref = test::condensed_reference_eigenvalues(p);
  const EigenSolution s = solve_eigenproblem(p.K, p.M, krylov(GetParam(), 16));
  ASSERT_EQ(s.eigenvalues.size(), 16);
  const double f7 = hz(s.eigenvalues(6));
  int rigid = 0;
  for (int j = 0; j < 16; ++j)
    if (hz(s.eigenvalues(j)) < 1e-4 * f7) ++rigid;
  EXPECT_EQ(rigid, 6);
  for (int j = 6; j < 16; ++j) EXPECT_NEAR(s.eigenvalues(j) / ref(j), 1.0, 1e-10) << "mode " << j + 1;
  // The rigid-body motions lie in the span of the first six modes: R = X (X^T M R).
  const Eigen::MatrixXd X6 = s.vectors.leftCols(6);
  const Eigen::MatrixXd R = truss.rigid_modes;
  const Eigen::MatrixXd projected = X6 * (X6.transpose() * (p.M * R));
  EXPECT_LT((projected - R).norm() / R.norm(), 1e-8);
  expect_eigenpairs(p, s);
}

// Frequency range: the modes of the chain between the 3rd and the 8th eigenvalue (inclusive), no
// mode count given.
TEST_P(KrylovBackend, HonoursAnEigenvalueRange) {
  const int n = 200;
  const Pencil p = test::spring_chain(n, 1.0, 1.0, true);
  EigenOptions o = krylov(GetParam(), 0);
  o.count.reset();
  o.lambda_min = 0.999 * test::chain_eigenvalue(n, 1.0, 1.0, true, 3);
  o.lambda_max = 1.001 * test::chain_eigenvalue(n, 1.0, 1.0, true, 28);
  const EigenSolution s = solve_eigenproblem(p.K, p.M, o);
  ASSERT_EQ(s.eigenvalues.size(), 26);
  for (int j = 0; j < 26; ++j)
    EXPECT_NEAR(s.eigenvalues(j) / test::chain_eigenvalue(n, 1.0, 1.0, true, j + 3), 1.0, 1e-10);
  // and with a count: the 4 lowest at or above the 3rd
  o.count = 4;
  const EigenSolution four = solve_eigenproblem(p.K, p.M, o);
  ASSERT_EQ(four.eigenvalues.size(), 4);
  EXPECT_NEAR(four.eigenvalues(0) / test::chain_eigenvalue(n, 1.0, 1.0, true, 3), 1.0, 1e-10);
  EXPECT_NEAR(four.eigenvalues(3) / test::chain_eigenvalue(n, 1.0, 1.0, true, 6), 1.0, 1e-10);
}

INSTANTIATE_TEST_SUITE_P(Backends, KrylovBackend,
                         ::testing::Values(EigenBackend::Spectra, EigenBackend::Arpack, EigenBackend::Block),
                         [](const auto& param_info) { return std::string(to_string(param_info.param)); });

// Spectra, ARPACK and block Lanczos agree with each other on a model none has an analytic answer for.
TEST(Eigensolver, SpectraArpackAndBlockAgreeOnATruss) {
  const test::Truss truss = test::free_truss(4, 4, 4, 1.0e5, 0.2);
  const auto a = solve_eigenproblem(truss.pencil.K, truss.pencil.M, krylov(EigenBackend::Spectra, 24));
  ASSERT_EQ(a.eigenvalues.size(), 24);
  for (auto backend : {EigenBackend::Arpack, EigenBackend::Block}) {
    const auto b = solve_eigenproblem(truss.pencil.K, truss.pencil.M, krylov(backend, 24));
    ASSERT_EQ(b.eigenvalues.size(), 24);
    EXPECT_EQ(b.stats.backend_used, backend);
    for (int j = 6; j < 24; ++j)
      EXPECT_NEAR(a.eigenvalues(j) / b.eigenvalues(j), 1.0, 1e-11) << to_string(backend) << " mode " << j + 1;
  }
}

// The cantilever and free-free bars of the MYSTRAN validation decks BAR-CC-GIV / BAR-FF-GIV
// (../shared/validation/mystran_cbar_cantilever_and_freefree_modes; MYSTRAN 12.0): four CBARs of
// 25 in, E = 1e7, I = 0.1, A = 0.1, rho = 0.1, WTMASS = 0.002591, bending in the x-z plane,
// Nastran's lumped mass (no rotary inertia). The matrices are built by hand here; the frequencies
// are MYSTRAN's, to 1e-6 relative: its 7 printed digits are good to 4.7e-7 at most, and the deck-driven
// tests (tests/fem, tests/solutions/normal_modes_test.cpp) measured 2.9e-7 (2026-11-28).
TEST(Eigensolver, MystranBarFrequencies) {
  const double EI = 1.0e7 * 0.1, mass_per_length = 0.1 * 0.1 * 0.002591;
  for (auto backend : {EigenBackend::Dense, EigenBackend::Spectra}) {
    EigenOptions o;
    o.backend = backend;
    o.count = 4;
    const Pencil cc = test::lumped_beam(4, 100.0, EI, mass_per_length, true);
    const auto s = solve_eigenproblem(cc.K, cc.M, o);
    ASSERT_EQ(s.eigenvalues.size(), 4);  // 4 mass-carrying dofs: 4 finite eigenvalues
    const double cc_ref[] = {10.68719, 62.81653, 166.3460, 289.9396};
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(hz(s.eigenvalues(j)) / cc_ref[j], 1.0, 1e-6) << "BAR-CC mode " << j + 1;

    o.count = 5;
    const Pencil ff = test::lumped_beam(4, 100.0, EI, mass_per_length, false);
    const auto f = solve_eigenproblem(ff.K, ff.M, o);
    ASSERT_EQ(f.eigenvalues.size(), 5);
    const double ff_ref[] = {59.11978, 150.0817, 271.5359};
    EXPECT_LT(hz(f.eigenvalues(1)), 1e-4 * hz(f.eigenvalues(2)));  // two rigid-body modes
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(hz(f.eigenvalues(j + 2)) / ff_ref[j], 1.0, 1e-6) << "BAR-FF mode " << j + 3;
  }
}

// Small models go to the dense backend whatever was asked, with identical answers.
TEST(Eigensolver, SmallModelsAreSolvedDensely) {
  const Pencil p = test::chain_with_massless_nodes(20, 1.0, 1.0);
  EigenOptions o;
  o.count = 20;  // all finite eigenvalues
  const auto s = solve_eigenproblem(p.K, p.M, o);
  EXPECT_EQ(s.stats.backend_used, EigenBackend::Dense);
  ASSERT_EQ(s.eigenvalues.size(), 20);
  for (int j = 0; j < 20; ++j) EXPECT_NEAR(s.eigenvalues(j) / test::chain_eigenvalue(20, 1.0, 1.0, true, j + 1), 1.0, 1e-12);
  o.count = 50;  // more than there are: only the 20 finite ones
  EXPECT_EQ(solve_eigenproblem(p.K, p.M, o).eigenvalues.size(), 20);
}

// A dof with neither stiffness nor mass makes K - sigma M singular for every sigma: the error names it.
TEST(Eigensolver, MechanismIsReportedWithItsDof) {
  Pencil p = test::spring_chain(300, 1.0, 1.0, true);
  test::Triplets kt, mt;
  for (int j = 0; j < p.K.outerSize(); ++j)
    for (test::Sparse::InnerIterator it(p.K, j); it; ++it) kt.emplace_back(it.row(), it.col(), it.value());
  for (int i = 0; i < 300; ++i) mt.emplace_back(i, i, 1.0);
  const test::Sparse K = test::from_triplets(301, kt), M = test::from_triplets(301, mt);  // dof 300 is free
  try {
    solve_eigenproblem(K, M, krylov(EigenBackend::Spectra, 5));
    FAIL() << "no error for a dof without stiffness and mass";
  } catch (const FactorizationError& e) {
    EXPECT_EQ(e.column(), 300);
  }
}

TEST(Eigensolver, ParsesBackendNames) {
  EXPECT_EQ(parse_eigen_backend("spectra"), EigenBackend::Spectra);
  EXPECT_EQ(parse_eigen_backend("arpack"), EigenBackend::Arpack);
  EXPECT_EQ(parse_eigen_backend("block"), EigenBackend::Block);
  EXPECT_FALSE(parse_eigen_backend("lanczos").has_value());
  // Every name the messages offer parses and prints back as itself.
  std::string names(eigen_backend_names());
  for (const char* sep : {", ", " or "})
    for (std::size_t p = names.find(sep); p != std::string::npos; p = names.find(sep)) names.replace(p, std::strlen(sep), " ");
  std::istringstream in(names);
  int count = 0;
  for (std::string name; in >> name; ++count) {
    const auto b = parse_eigen_backend(name);
    ASSERT_TRUE(b.has_value()) << name;
    EXPECT_EQ(to_string(*b), name);
  }
  EXPECT_EQ(count, 4);
}

}  // namespace
}  // namespace seflex::linalg
