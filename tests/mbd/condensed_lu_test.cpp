// The Newton iteration matrix factorised with each body's modal coordinates condensed first
// (mbd/src/solvers/condensed_lu.hpp, a white-box test of an internal class): its solutions equal
// a full-pivoting dense solve of the same matrix, it condenses exactly the modal dofs, it falls back
// to the whole matrix when two bodies' modal dofs are coupled, and it reports a singular matrix; the
// same for Radau IIA's complex system, whose dense LU pivots by the squared modulus.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "mbd_models.hpp"
#include "seflex/mbd/assembly/assembly.hpp"
#include "seflex/mbd/data.hpp"
#include "seflex/mbd/state.hpp"
#include "solvers/condensed_lu.hpp"

namespace seflex::mbd {
namespace {

/// A three-link flexible pendulum chain with 3 fixed-interface modes per link, its iteration matrix
/// K + gp C + bp M at the initial state with a velocity (so C is not zero).
struct ChainMatrix {
  Model model;
  Eigen::SparseMatrix<double> S;
};

ChainMatrix chain_matrix() {
  test::ChainOptions o;
  o.bodies = 3;
  o.modes = 3;
  o.inertia = InertiaModel::Full;
  ChainMatrix out{test::pendulum_chain(o), {}};
  State s = initial_state(out.model);
  s.v.setConstant(0.3);
  Data data(out.model);
  assemble(out.model, s, data, AssemblyOptions{});
  const double h = 1e-3;
  combine_matrices(out.model, data, 1.0, 0.6 / h, 0.3 / (h * h), nullptr, out.S);
  return out;
}

double relative_error(const Eigen::VectorXd& x, const Eigen::VectorXd& ref) { return (x - ref).norm() / ref.norm(); }

TEST(CondensedLu, SolvesTheIterationMatrixLikeADenseFullPivotingSolve) {
  const ChainMatrix c = chain_matrix();
  const int n = c.model.num_dofs;
  ASSERT_EQ(n, 3 + 3 * 6 + 3 * 3);  // three hinges, each link's free tip node, 3 x 3 modal
  detail::CondensedLu lu;
  ASSERT_TRUE(lu.applicable(c.model, c.S, 150));
  EXPECT_EQ(lu.dense_size(), n - 9);  // exactly the modal dofs condensed
  ASSERT_TRUE(lu.factorize(c.model, c.S));
  const Eigen::MatrixXd A = Eigen::MatrixXd(c.S);
  const Eigen::FullPivLU<Eigen::MatrixXd> ref(A);
  for (int k = 0; k < 3; ++k) {
    const Eigen::VectorXd r = Eigen::VectorXd::Random(n);
    Eigen::VectorXd x;
    lu.solve_negated(r, x);
    EXPECT_LT(relative_error(-x, ref.solve(r)), 1e-12);
  }
  // Refactorising new values on the same pattern.
  Eigen::SparseMatrix<double> S2 = c.S;
  for (int i = 0; i < S2.nonZeros(); ++i) S2.valuePtr()[i] *= 1.0 + 0.01 * std::sin(i);
  for (int i = 0; i < n; ++i) S2.coeffRef(i, i) += 1.0;  // on the diagonal: the pattern stays
  ASSERT_EQ(S2.nonZeros(), c.S.nonZeros());
  ASSERT_TRUE(lu.factorize(c.model, S2));
  const Eigen::VectorXd r = Eigen::VectorXd::Random(n);
  Eigen::VectorXd x;
  lu.solve_negated(r, x);
  EXPECT_LT(relative_error(-x, Eigen::FullPivLU<Eigen::MatrixXd>(Eigen::MatrixXd(S2)).solve(r)), 1e-12);
}

TEST(CondensedLu, CouplingBetweenTwoBodiesModesFactorisesTheWholeMatrix) {
  const ChainMatrix c = chain_matrix();
  const int n = c.model.num_dofs;
  const int e1 = c.model.flexible_bodies[0].eta_dof, e2 = c.model.flexible_bodies[1].eta_dof;
  Eigen::SparseMatrix<double> S = c.S;
  S.coeffRef(e1, e2) = 1.0;  // e.g. a force element between two bodies' modal coordinates
  S.coeffRef(e2, e1) = 1.0;
  S.makeCompressed();
  detail::CondensedLu lu;
  ASSERT_TRUE(lu.applicable(c.model, S, 150));
  EXPECT_EQ(lu.dense_size(), n);
  ASSERT_TRUE(lu.factorize(c.model, S));
  const Eigen::VectorXd r = Eigen::VectorXd::Random(n);
  Eigen::VectorXd x;
  lu.solve_negated(r, x);
  EXPECT_LT(relative_error(-x, Eigen::FullPivLU<Eigen::MatrixXd>(Eigen::MatrixXd(S)).solve(r)), 1e-12);
  EXPECT_FALSE(lu.applicable(c.model, S, n - 1));  // larger than the caller's dense limit
}

TEST(CondensedLu, ReportsASingularMatrix) {
  const ChainMatrix c = chain_matrix();
  Eigen::SparseMatrix<double> S = c.S;
  // A modal block without stiffness or mass: its pivots vanish.
  const int e = c.model.flexible_bodies[2].eta_dof;
  for (int j = 0; j < S.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(S, j); it; ++it)
      if (it.row() == e || j == e) it.valueRef() = 0.0;
  detail::CondensedLu lu;
  EXPECT_FALSE(lu.factorize(c.model, S));
  // A retained dof without stiffness or mass.
  S = c.S;
  for (int j = 0; j < S.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(S, j); it; ++it)
      if (it.row() == 0 || j == 0) it.valueRef() = 0.0;
  EXPECT_FALSE(lu.factorize(c.model, S));
}

// Radau IIA-5's complex system K + mu C + mu^2 M (radau5.cpp), mu = (alpha + i beta) / h, against a
// full-pivoting dense solve; and a singular modal block reported as in the real case.
TEST(CondensedLu, SolvesRadausComplexSystemLikeADenseFullPivotingSolve) {
  test::ChainOptions o;
  o.bodies = 3;
  o.modes = 3;
  o.inertia = InertiaModel::Full;
  const Model model = test::pendulum_chain(o);
  State s = initial_state(model);
  s.v.setConstant(0.3);
  Data data(model);
  assemble(model, s, data, AssemblyOptions{});
  Eigen::SparseMatrix<double> K, C, M;
  combine_matrices(model, data, 1.0, 0.0, 0.0, nullptr, K);
  combine_matrices(model, data, 0.0, 1.0, 0.0, nullptr, C);
  combine_matrices(model, data, 0.0, 0.0, 1.0, nullptr, M);
  const double h = 1e-2;
  const std::complex<double> mu(2.6810828736277521 / h, 3.0504301992474105 / h);  // Radau IIA-5's complex eigenvalue
  const Eigen::SparseMatrix<std::complex<double>> S =
      K.cast<std::complex<double>>() + mu * C.cast<std::complex<double>>() + (mu * mu) * M.cast<std::complex<double>>();
  const int n = model.num_dofs;
  detail::CondensedLuComplex lu;
  ASSERT_TRUE(lu.applicable(model, S, 150));
  EXPECT_EQ(lu.dense_size(), n - 9);
  ASSERT_TRUE(lu.factorize(model, S));
  const Eigen::MatrixXcd A = Eigen::MatrixXcd(S);
  const Eigen::FullPivLU<Eigen::MatrixXcd> ref(A);
  for (int k = 0; k < 3; ++k) {
    const Eigen::VectorXcd r = Eigen::VectorXcd::Random(n);
    Eigen::VectorXcd x;
    lu.solve_negated(r, x);
    EXPECT_LT((-x - ref.solve(r)).norm() / ref.solve(r).norm(), 1e-12);
  }
  Eigen::SparseMatrix<std::complex<double>> Z = S;
  const int e = model.flexible_bodies[1].eta_dof;
  for (int j = 0; j < Z.outerSize(); ++j)
    for (Eigen::SparseMatrix<std::complex<double>>::InnerIterator it(Z, j); it; ++it)
      if (it.row() == e || j == e) it.valueRef() = 0.0;
  EXPECT_FALSE(lu.factorize(model, Z));
}

// The complex dense LU: P A = L U to round-off, and the pivots of Eigen's PartialPivLU (largest
// modulus; unique on a random matrix).
TEST(CondensedLu, SquaredModulusLuFactorsAsPartialPivLu) {
  std::srand(11);
  const Eigen::MatrixXcd A = Eigen::MatrixXcd::Random(41, 41);
  detail::SquaredModulusLu<std::complex<double>> lu(41);
  lu.compute(A);
  const Eigen::PartialPivLU<Eigen::MatrixXcd> ref(A);
  EXPECT_LT((lu.matrixLU() - ref.matrixLU()).norm() / ref.matrixLU().norm(), 1e-13);
  Eigen::MatrixXcd X = Eigen::MatrixXcd::Random(41, 3);
  const Eigen::MatrixXcd B = X;
  lu.solve_in_place(X);
  EXPECT_LT((A * X - B).norm() / B.norm(), 1e-13);
}

}  // namespace
}  // namespace seflex::mbd
