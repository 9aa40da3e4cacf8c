// The (deflated) shift-invert operator shared by the Krylov backends.
#include "shift_invert.hpp"

namespace seflex::reduction {

ShiftInvertOperator::ShiftInvertOperator(SparseFactorization& factor, const SparseMatrixd& M, const Eigen::MatrixXd& locked)
    : factor_(factor), M_(M), X_(locked), scratch_(M.rows()) {
  SEFLEX_DEMAND(locked.cols() == 0 || locked.rows() == M.rows(), "locked vectors have the wrong size");
  // Krylov methods multiply by M several times per step (every M inner product): keep the
  // cheapest form of it.
  for (Eigen::Index j = 0; j < M.outerSize() && M_is_diagonal_; ++j)
    for (SparseMatrixd::InnerIterator it(M, j); it; ++it)
      if (it.row() != j && it.value() != 0) M_is_diagonal_ = false;
  if (M_is_diagonal_) M_diagonal_ = M.diagonal();
  else M_full_ = M.selfadjointView<Eigen::Lower>();
  if (X_.cols() > 0) MX_ = M_.selfadjointView<Eigen::Lower>() * X_;
}

void ShiftInvertOperator::apply_M(const double* x, double* y) const {
  Eigen::Map<const Eigen::VectorXd> xv(x, rows());
  Eigen::Map<Eigen::VectorXd> yv(y, rows());
  if (M_is_diagonal_) yv = M_diagonal_.cwiseProduct(xv);
  else yv.noalias() = M_full_ * xv;
}

void ShiftInvertOperator::apply_inverse(const double* b, double* y) {
  Eigen::Map<const Eigen::VectorXd> bv(b, rows());
  Eigen::Map<Eigen::VectorXd> yv(y, rows());
  scratch_ = bv;
  if (X_.cols() > 0) scratch_.noalias() -= MX_ * (X_.transpose() * bv);  // P^T b
  factor_.solve_in_place(scratch_);
  yv = scratch_;
  if (X_.cols() > 0) yv.noalias() -= X_ * (MX_.transpose() * scratch_);  // P y
  ++applications_;
}

void ShiftInvertOperator::apply(const double* x, double* y) {
  Eigen::VectorXd b(rows());
  apply_M(x, b.data());
  apply_inverse(b.data(), y);
}

}  // namespace seflex::reduction
