// FFRF-LM iteration matrix: dense LU up to Data::kDenseDofs unknowns, sparse LU above.
#include "ffrf/ffrf_iteration_matrix.hpp"

#include <cmath>

#include "seflex/mbd/data.hpp"

namespace seflex::mbd::detail {

bool FfrfIterationMatrix::factorize(const Triplets& T, int n) {
  dense_path_ = n <= Data::kDenseDofs;
  if (dense_path_) {
    dense_.setZero(n, n);
    for (const auto& t : T) dense_(t.row(), t.col()) += t.value();
    dense_lu_.compute(dense_);
    // PartialPivLU does not report singularity: an exactly zero or non-finite pivot marks it, as the
    // sparse LU reports it (a numerically singular but nonzero pivot is accepted by both, as before:
    // the unscaled index-3 system at small steps, tests/mbd/ffrf_system_test.cpp).
    const auto pivots = dense_lu_.matrixLU().diagonal().cwiseAbs();
    return std::isfinite(pivots.sum()) && pivots.minCoeff() > 0.0;
  }
  sparse_.resize(n, n);
  sparse_.setFromTriplets(T.begin(), T.end());
  if (!analyzed_) {
    lu_.analyzePattern(sparse_);
    analyzed_ = true;
  }
  lu_.factorize(sparse_);
  if (lu_.info() != Eigen::Success) {
    lu_.analyzePattern(sparse_);  // the pattern may have changed (a multiplier became zero)
    lu_.factorize(sparse_);
  }
  return lu_.info() == Eigen::Success;
}

void FfrfIterationMatrix::solve_negated(const Eigen::VectorXd& r, Eigen::VectorXd& x) const {
  if (dense_path_)
    x = dense_lu_.solve(r);
  else
    x = lu_.solve(r);
  x = -x;
}

Eigen::MatrixXd FfrfIterationMatrix::matrix() const { return dense_path_ ? dense_ : Eigen::MatrixXd(sparse_); }

}  // namespace seflex::mbd::detail
