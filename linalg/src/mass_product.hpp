#pragma once
// y = M x for a symmetric mass matrix in its cheapest form (private to linalg/): Krylov methods
// multiply by M several times per step (every M inner product), and Nastran's lumped mass is
// diagonal, where a coefficient-wise product is several times cheaper than a sparse symmetric one.
#include <Eigen/Core>

#include "seflex/linalg/sparse_factorization.hpp"

namespace seflex::linalg {

class MassProduct {
 public:
  /// M symmetric, lower triangle read (full storage also works).
  explicit MassProduct(const SparseMatrixd& M) {
    for (Eigen::Index j = 0; j < M.outerSize() && diagonal_; ++j)
      for (SparseMatrixd::InnerIterator it(M, j); it; ++it)
        if (it.row() != j && it.value() != 0) diagonal_ = false;
    if (diagonal_) d_ = M.diagonal();
    else full_ = M.selfadjointView<Eigen::Lower>();
  }
  Eigen::Index rows() const { return diagonal_ ? d_.size() : full_.rows(); }
  bool is_diagonal() const { return diagonal_; }
  /// M X for a block (or vector) X.
  template <typename Derived>
  Eigen::MatrixXd operator()(const Eigen::MatrixBase<Derived>& X) const {
    if (diagonal_) return d_.asDiagonal() * X;
    return full_ * X;
  }
  /// y = M x (raw arrays of rows() entries).
  void apply(const double* x, double* y) const {
    Eigen::Map<const Eigen::VectorXd> xv(x, rows());
    Eigen::Map<Eigen::VectorXd> yv(y, rows());
    if (diagonal_) yv = d_.cwiseProduct(xv);
    else yv.noalias() = full_ * xv;
  }

 private:
  bool diagonal_ = true;
  Eigen::VectorXd d_;   // M when it is diagonal (lumped mass)
  SparseMatrixd full_;  // otherwise both triangles, for a plain sparse product
};

}  // namespace seflex::linalg
