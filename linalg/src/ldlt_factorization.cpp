// Eigen SimplicialLDLT backend of SparseFactorization, METIS fill-reducing ordering.
// LDL^T without pivoting: factorises symmetric indefinite matrices (K - sigma M with sigma inside the
// spectrum) as long as no pivot vanishes, and reports the inertia (negative pivots = Sturm count).
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "backends.hpp"
#include "metis_ordering.hpp"

namespace seflex::linalg {
namespace {

/// Eigen ordering functor: METIS nested dissection on the compressed graph (metis_ordering.hpp).
struct MetisNestedDissection {
  template <typename MatrixType>
  void operator()(const MatrixType& A, Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>& Pinv) const {
    const std::vector<std::int64_t> perm = nested_dissection_ordering(A);
    Pinv.resize(A.cols());
    for (Eigen::Index k = 0; k < A.cols(); ++k) Pinv.indices()(k) = static_cast<int>(perm[static_cast<std::size_t>(k)]);
  }
};

class LdltFactorization final : public SparseFactorization {
 public:
  FactorizationBackend backend() const override { return FactorizationBackend::EigenLdlt; }
  bool positive_definite_only() const override { return false; }
  std::optional<Eigen::Index> negative_pivots() const override {
    if (!factorized_) return std::nullopt;
    return negative_;
  }
  const FactorizationStats& stats() const override { return stats_; }

  void factorize(const SparseMatrixd& A) override {
    SEFLEX_DEMAND(A.rows() == A.cols(), "factorize: matrix must be square");
    factorized_ = false;
    const bool same_pattern = analysed_ && same_lower_pattern(A);
    if (!same_pattern) {
      ldlt_.analyzePattern(A);
      store_lower_pattern(A);
      analysed_ = true;
      ++stats_.symbolic_analyses;
    }
    ldlt_.factorize(A);
    ++stats_.numeric_factorizations;
    stats_.rows = A.rows();
    stats_.factor_nonzeros = static_cast<double>(ldlt_.matrixL().nestedExpression().nonZeros()) + static_cast<double>(A.rows());
    stats_.flops = 0;

    // A pivot that vanished (exactly, as Eigen reports it, or to round-off relative to the
    // diagonal it came from) means A is singular: the solution would be garbage, so refuse.
    const Eigen::VectorXd& D = ldlt_.vectorD();
    const auto& pinv = ldlt_.permutationPinv().indices();
    Eigen::VectorXd diag = A.diagonal().cwiseAbs();
    negative_ = 0;
    stats_.min_pivot_ratio = 1.0;
    for (Eigen::Index k = 0; k < D.size(); ++k) {
      const Eigen::Index column = pinv(k);
      const double scale = diag(column) > 0 ? diag(column) : 1.0;
      stats_.min_pivot_ratio = std::min(stats_.min_pivot_ratio, std::abs(D(k)) / scale);
      if (!(std::abs(D(k)) > kPivotTolerance * scale)) throw singular(column);
      if (D(k) < 0) ++negative_;
    }
    if (ldlt_.info() != Eigen::Success) throw singular(-1);
    factorized_ = true;
  }

  void solve_in_place(Eigen::Ref<Eigen::MatrixXd> B) override {
    SEFLEX_DEMAND(factorized_, "solve before a successful factorize");
    SEFLEX_DEMAND(B.rows() == stats_.rows, "solve: right-hand side has the wrong number of rows");
    if (B.cols() == 0 || B.rows() == 0) return;
    B = ldlt_.solve(B).eval();
    stats_.solve_columns += B.cols();
    ++stats_.solve_calls;
  }

 private:
  static FactorizationError singular(Eigen::Index column) {
    return FactorizationError(FactorizationError::Kind::Singular, column,
                              "LDL^T factorisation: matrix is singular (zero pivot at column " + std::to_string(column) + ")");
  }
  bool same_lower_pattern(const SparseMatrixd& A) const {
    if (A.cols() + 1 != static_cast<Eigen::Index>(colptr_.size())) return false;
    std::size_t k = 0;
    for (Eigen::Index j = 0; j < A.cols(); ++j) {
      for (SparseMatrixd::InnerIterator it(A, j); it; ++it) {
        if (it.row() < j) continue;
        if (k >= rowind_.size() || rowind_[k] != it.row()) return false;
        ++k;
      }
      if (static_cast<Eigen::Index>(k) != colptr_[static_cast<std::size_t>(j) + 1]) return false;
    }
    return k == rowind_.size();
  }
  void store_lower_pattern(const SparseMatrixd& A) {
    colptr_.assign(1, 0);
    rowind_.clear();
    for (Eigen::Index j = 0; j < A.cols(); ++j) {
      for (SparseMatrixd::InnerIterator it(A, j); it; ++it)
        if (it.row() >= j) rowind_.push_back(it.row());
      colptr_.push_back(static_cast<Eigen::Index>(rowind_.size()));
    }
  }

  Eigen::SimplicialLDLT<SparseMatrixd, Eigen::Lower, MetisNestedDissection> ldlt_;
  std::vector<Eigen::Index> colptr_, rowind_;
  FactorizationStats stats_;
  Eigen::Index negative_ = 0;
  bool analysed_ = false, factorized_ = false;
};

}  // namespace

std::unique_ptr<SparseFactorization> make_ldlt_factorization() { return std::make_unique<LdltFactorization>(); }

}  // namespace seflex::linalg
