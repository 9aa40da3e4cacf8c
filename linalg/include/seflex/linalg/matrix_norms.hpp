#pragma once
// Norms of symmetric sparse matrices (linalg/ and solutions/ statics).
#include <cmath>

#include "seflex/linalg/sparse_factorization.hpp"

namespace seflex::linalg {

/// ||A||_1 (= ||A||_inf) of the symmetric matrix whose lower triangle is read (full storage works too).
inline double norm1_symmetric(const SparseMatrixd& A) {
  Eigen::VectorXd colsum = Eigen::VectorXd::Zero(A.cols());
  for (Eigen::Index j = 0; j < A.outerSize(); ++j)
    for (SparseMatrixd::InnerIterator it(A, j); it; ++it) {
      if (it.row() < j) continue;
      colsum(j) += std::abs(it.value());
      if (it.row() != j) colsum(it.row()) += std::abs(it.value());
    }
  return colsum.size() ? colsum.maxCoeff() : 0.0;
}

}  // namespace seflex::linalg
