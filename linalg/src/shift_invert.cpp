// The (deflated) shift-invert operator shared by the Krylov backends.
#include "shift_invert.hpp"

namespace seflex::linalg {

ShiftInvertOperator::ShiftInvertOperator(SparseFactorization& factor, const SparseMatrixd& M, const Eigen::MatrixXd& locked)
    : factor_(factor), M_(M), mass_(M), X_(locked), scratch_(M.rows()) {
  SEFLEX_DEMAND(locked.cols() == 0 || locked.rows() == M.rows(), "locked vectors have the wrong size");
  if (X_.cols() > 0) MX_ = mass_(X_);
}

void ShiftInvertOperator::apply_M(const double* x, double* y) const { mass_.apply(x, y); }

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

}  // namespace seflex::linalg
