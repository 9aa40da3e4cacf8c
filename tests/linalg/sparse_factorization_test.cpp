// Sparse factorisation backends: solves against the matrix itself, symbolic reuse, indefinite
// matrices (Sturm counts against analytic eigenvalues) and breakdown reporting.
#include "seflex/linalg/sparse_factorization.hpp"

#include <gtest/gtest.h>

#include "test_problems.hpp"

namespace seflex::linalg {
namespace {

using test::Pencil;

class FactorizationTest : public ::testing::TestWithParam<FactorizationBackend> {};

TEST_P(FactorizationTest, SolvesManyRightHandSidesOfALaplacianPlate) {
  const Pencil p = test::laplacian_plate(40);  // 1600 unknowns, symmetric positive definite
  auto f = make_factorization(GetParam());
  f->factorize(p.K);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(p.K.rows(), 7);
  const Eigen::MatrixXd X = f->solve(B);
  // residual of the solve against the matrix itself (Cholesky/LDL^T are backward stable)
  EXPECT_LT((p.K * X - B).norm() / B.norm(), 1e-13);
  EXPECT_EQ(f->stats().rows, 1600);
  EXPECT_GT(f->stats().factor_nonzeros, p.K.nonZeros() / 2);
}

TEST_P(FactorizationTest, ReadsOnlyTheLowerTriangle) {
  const Pencil p = test::laplacian_plate(12);
  const SparseMatrixd lower = p.K.triangularView<Eigen::Lower>();
  auto full = make_factorization(GetParam()), low = make_factorization(GetParam());
  full->factorize(p.K);
  low->factorize(lower);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(p.K.rows(), 3);
  EXPECT_LT((full->solve(B) - low->solve(B)).norm() / full->solve(B).norm(), 1e-14);
}

TEST_P(FactorizationTest, ReusesTheSymbolicAnalysisForTheSamePattern) {
  const Pencil p = test::laplacian_plate(10);
  auto f = make_factorization(GetParam());
  f->factorize(p.K);
  const SparseMatrixd K2 = 2.0 * p.K;  // same pattern, new values
  f->factorize(K2);
  EXPECT_EQ(f->stats().symbolic_analyses, 1);
  EXPECT_EQ(f->stats().numeric_factorizations, 2);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(p.K.rows());
  EXPECT_LT((K2 * f->solve(b) - b).norm() / b.norm(), 1e-13);
  const Pencil q = test::laplacian_plate(11);  // new pattern: analysed again
  f->factorize(q.K);
  EXPECT_EQ(f->stats().symbolic_analyses, 2);
}

TEST_P(FactorizationTest, EmptyBlockOfRightHandSidesIsANoOp) {
  const Pencil p = test::spring_chain(5, 1.0, 1.0, true);
  auto f = make_factorization(GetParam());
  f->factorize(p.K);
  Eigen::MatrixXd B(5, 0);
  EXPECT_NO_THROW(f->solve_in_place(B));
}

INSTANTIATE_TEST_SUITE_P(Backends, FactorizationTest,
                         ::testing::Values(FactorizationBackend::Cholmod, FactorizationBackend::EigenLdlt),
                         [](const auto& param_info) { return std::string(to_string(param_info.param)); });

// K - sigma M for a fixed-fixed chain with sigma between the analytic eigenvalues 7 and 8: LDL^T
// factorises it and its negative pivots count the eigenvalues below sigma (Sylvester's law of
// inertia); Cholesky refuses it.
TEST(Factorization, LdltGivesTheSturmCountOfAShiftedPencil) {
  const int n = 60;
  const Pencil p = test::spring_chain(n, 3.0, 2.0, true);
  const double sigma = 0.5 * (test::chain_eigenvalue(n, 3.0, 2.0, true, 7) + test::chain_eigenvalue(n, 3.0, 2.0, true, 8));
  const SparseMatrixd A = p.K - sigma * p.M;
  auto ldlt = make_factorization(FactorizationBackend::EigenLdlt);
  ldlt->factorize(A);
  ASSERT_TRUE(ldlt->negative_pivots().has_value());
  EXPECT_EQ(*ldlt->negative_pivots(), 7);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
  EXPECT_LT((A * ldlt->solve(b) - b).norm() / b.norm(), 1e-12);

  auto chol = make_factorization(FactorizationBackend::Cholmod);
  EXPECT_FALSE(chol->negative_pivots().has_value());
  try {
    chol->factorize(A);
    FAIL() << "Cholesky accepted an indefinite matrix";
  } catch (const FactorizationError& e) {
    EXPECT_EQ(e.kind(), FactorizationError::Kind::NotPositiveDefinite);
    EXPECT_GE(e.column(), 0);
    EXPECT_LT(e.column(), n);
  }
}

// A dof with no stiffness at all (column 3 of an otherwise positive definite matrix is zero):
// both backends name it.
TEST(Factorization, NamesTheColumnOfASingularMatrix) {
  test::Triplets t;
  for (int i = 0; i < 6; ++i)
    if (i != 3) t.emplace_back(i, i, 2.0 + i);
  t.emplace_back(1, 0, 0.5);
  t.emplace_back(0, 1, 0.5);
  const SparseMatrixd A = test::from_triplets(6, t);
  for (auto backend : {FactorizationBackend::Cholmod, FactorizationBackend::EigenLdlt}) {
    auto f = make_factorization(backend);
    try {
      f->factorize(A);
      FAIL() << to_string(backend) << " accepted a singular matrix";
    } catch (const FactorizationError& e) {
      EXPECT_EQ(e.column(), 3) << to_string(backend);
    }
  }
}

// The stiffness of a free-floating chain is positive semi-definite with the rigid translation in its
// null space: whatever the sign of round-off in the last pivot, both backends refuse it.
TEST(Factorization, RefusesASingularSemidefiniteStiffness) {
  const Pencil p = test::spring_chain(200, 4.0e5, 1.0, false);
  for (auto backend : {FactorizationBackend::Cholmod, FactorizationBackend::EigenLdlt}) {
    auto f = make_factorization(backend);
    EXPECT_THROW(f->factorize(p.K), FactorizationError) << to_string(backend);
  }
}

TEST(Factorization, ParsesBackendNames) {
  EXPECT_EQ(parse_factorization_backend("cholmod"), FactorizationBackend::Cholmod);
  EXPECT_EQ(parse_factorization_backend("ldlt"), FactorizationBackend::EigenLdlt);
  EXPECT_FALSE(parse_factorization_backend("lu").has_value());
}

}  // namespace
}  // namespace seflex::linalg
