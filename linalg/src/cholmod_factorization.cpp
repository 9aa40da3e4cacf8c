// CHOLMOD supernodal Cholesky backend of SparseFactorization (the only file that includes cholmod.h).
// Ordering: METIS nested dissection on the supervariable-compressed graph (metis_ordering.hpp),
// then CHOLMOD's weighted postordering; supernodal L L^T with BLAS-3 (OpenBLAS) for factorisation and multi-column solves.
#include <cholmod.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "backends.hpp"
#include "blas_threads.hpp"
#include "metis_ordering.hpp"

namespace seflex::linalg {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

class CholmodFactorization final : public SparseFactorization {
 public:
  CholmodFactorization() {
    cholmod_l_start(&common_);
    common_.print = 0;                 // library code never prints
    common_.error_handler = nullptr;
    common_.nmethods = 1;
    common_.method[0].ordering = CHOLMOD_GIVEN;  // METIS on the compressed graph (metis_ordering.hpp)
    common_.postorder = 1;
    common_.supernodal = CHOLMOD_SUPERNODAL;
    common_.final_ll = 1;
    common_.quick_return_if_not_posdef = 1;
  }
  ~CholmodFactorization() override {
    free_workspace();
    if (factor_ != nullptr) cholmod_l_free_factor(&factor_, &common_);
    cholmod_l_finish(&common_);
  }

  FactorizationBackend backend() const override { return FactorizationBackend::Cholmod; }
  bool positive_definite_only() const override { return true; }
  std::optional<Eigen::Index> negative_pivots() const override { return std::nullopt; }
  const FactorizationStats& stats() const override { return stats_; }

  void factorize(const SparseMatrixd& A) override {
    SEFLEX_DEMAND(A.rows() == A.cols(), "factorize: matrix must be square");
    auto t0 = Clock::now();
    const bool same_pattern = copy_lower(A);
    cholmod_sparse S = view();
    if (factor_ == nullptr || !same_pattern) {
      if (factor_ != nullptr) cholmod_l_free_factor(&factor_, &common_);
      free_workspace();
      stats_.seconds_numeric += seconds_since(t0);
      t0 = Clock::now();
      std::vector<std::int64_t> perm = nested_dissection_ordering(A);
      std::vector<SuiteSparse_long> user_perm(perm.begin(), perm.end());
      stats_.seconds_ordering += seconds_since(t0);
      t0 = Clock::now();
      factor_ = cholmod_l_analyze_p(&S, user_perm.data(), nullptr, 0, &common_);
      check_status("cholmod_l_analyze");
      SEFLEX_DEMAND(factor_ != nullptr, "cholmod_l_analyze returned no factor");
      ++stats_.symbolic_analyses;
      stats_.seconds_symbolic += seconds_since(t0);
      t0 = Clock::now();
    }
    struct AddTime {
      double& total;
      Clock::time_point t;
      ~AddTime() { total += seconds_since(t); }
    } add_time{stats_.seconds_numeric, t0};
    cholmod_l_factorize(&S, factor_, &common_);
    ++stats_.numeric_factorizations;
    stats_.rows = A.rows();
    stats_.flops = common_.fl;
    stats_.factor_nonzeros = common_.lnz;
    if (common_.status == CHOLMOD_NOT_POSDEF || factor_->minor < factor_->n) {
      const auto* perm = static_cast<const SuiteSparse_long*>(factor_->Perm);
      const Eigen::Index column = factor_->minor < factor_->n ? perm[factor_->minor] : -1;
      factorized_ = false;
      throw FactorizationError(FactorizationError::Kind::NotPositiveDefinite, column,
                               "Cholesky factorisation: matrix is not positive definite (elimination failed at column " +
                                   std::to_string(column) + ")");
    }
    check_status("cholmod_l_factorize");
    check_pivots();
    factorized_ = true;
  }

  void solve_in_place(Eigen::Ref<Eigen::MatrixXd> B) override {
    SEFLEX_DEMAND(factorized_, "solve before a successful factorize");
    SEFLEX_DEMAND(B.rows() == stats_.rows, "solve: right-hand side has the wrong number of rows");
    if (B.cols() == 0 || B.rows() == 0) return;
    const auto t0 = Clock::now();
    const BlasThreadScope single_thread(1);  // one BLAS call per supernode (blas_threads.hpp)
    cholmod_dense rhs{};
    rhs.nrow = static_cast<size_t>(B.rows());
    rhs.ncol = static_cast<size_t>(B.cols());
    rhs.d = static_cast<size_t>(B.outerStride());
    rhs.nzmax = rhs.d * rhs.ncol;
    rhs.x = B.data();
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    const int ok = cholmod_l_solve2(CHOLMOD_A, factor_, &rhs, nullptr, &x_, nullptr, &y_, &e_, &common_);
    SEFLEX_DEMAND(ok && x_ != nullptr, "cholmod_l_solve2 failed (status " + std::to_string(common_.status) + ")");
    const auto* x = static_cast<const double*>(x_->x);
    for (Eigen::Index j = 0; j < B.cols(); ++j)
      std::memcpy(B.col(j).data(), x + static_cast<size_t>(j) * x_->d, sizeof(double) * static_cast<size_t>(B.rows()));
    stats_.seconds_solve += seconds_since(t0);
    stats_.solve_columns += B.cols();
    ++stats_.solve_calls;
  }

 private:
  /// Copy the lower triangle of A into CHOLMOD's 64-bit column storage; true if the pattern is the
  /// one already analysed.
  bool copy_lower(const SparseMatrixd& A) {
    const Eigen::Index n = A.cols();
    std::vector<SuiteSparse_long> p(static_cast<size_t>(n) + 1, 0);
    for (Eigen::Index j = 0; j < n; ++j) {
      SuiteSparse_long count = 0;
      for (SparseMatrixd::InnerIterator it(A, j); it; ++it)
        if (it.row() >= j) ++count;
      p[static_cast<size_t>(j) + 1] = p[static_cast<size_t>(j)] + count;
    }
    std::vector<SuiteSparse_long> i(static_cast<size_t>(p.back()));
    values_.resize(static_cast<size_t>(p.back()));
    for (Eigen::Index j = 0; j < n; ++j) {
      auto k = static_cast<size_t>(p[static_cast<size_t>(j)]);
      for (SparseMatrixd::InnerIterator it(A, j); it; ++it)
        if (it.row() >= j) {
          i[k] = it.row();
          values_[k++] = it.value();
        }
    }
    const bool same = (p == colptr_) && (i == rowind_);
    if (!same) {
      colptr_ = std::move(p);
      rowind_ = std::move(i);
    }
    return same;
  }

  /// A pivot L_jj^2 that is round-off relative to the diagonal A_jj it came from means A is
  /// singular to working precision (e.g. an unsupported model in statics): the factorisation
  /// "succeeded" by luck of signs and its solutions would be garbage.
  void check_pivots() {
    const auto n = static_cast<SuiteSparse_long>(factor_->n);
    const auto* perm = static_cast<const SuiteSparse_long*>(factor_->Perm);
    const auto* super = static_cast<const SuiteSparse_long*>(factor_->super);
    const auto* pi = static_cast<const SuiteSparse_long*>(factor_->pi);
    const auto* px = static_cast<const SuiteSparse_long*>(factor_->px);
    const auto* x = static_cast<const double*>(factor_->x);
    double min_ratio = std::numeric_limits<double>::infinity();
    for (SuiteSparse_long s = 0; s < static_cast<SuiteSparse_long>(factor_->nsuper); ++s) {
      const SuiteSparse_long k1 = super[s], k2 = super[s + 1], nrows = pi[s + 1] - pi[s];
      for (SuiteSparse_long k = k1; k < k2; ++k) {
        const double l = x[px[s] + (k - k1) * nrows + (k - k1)];
        const SuiteSparse_long column = perm != nullptr ? perm[k] : k;
        const double a = diagonal(column);
        min_ratio = std::min(min_ratio, l * l / std::abs(a));
        if (!(l * l > kPivotTolerance * std::abs(a)))
          throw FactorizationError(FactorizationError::Kind::Singular, column,
                                   "Cholesky factorisation: matrix is singular to working precision (pivot " +
                                       std::to_string(l * l) + " of diagonal " + std::to_string(a) + " at column " +
                                       std::to_string(column) + ")");
      }
    }
    stats_.min_pivot_ratio = n > 0 ? min_ratio : 1.0;
  }

  /// A_jj from the stored lower triangle (the first entry of column j when present).
  double diagonal(SuiteSparse_long j) const {
    const auto k = static_cast<size_t>(colptr_[static_cast<size_t>(j)]);
    return k < rowind_.size() && k < static_cast<size_t>(colptr_[static_cast<size_t>(j) + 1]) && rowind_[k] == j ? values_[k] : 0.0;
  }

  cholmod_sparse view() {
    cholmod_sparse S{};
    S.nrow = S.ncol = colptr_.size() - 1;
    S.nzmax = rowind_.size();
    S.p = colptr_.data();
    S.i = rowind_.data();
    S.x = values_.data();
    S.stype = -1;  // lower triangle stored
    S.itype = CHOLMOD_LONG;
    S.xtype = CHOLMOD_REAL;
    S.dtype = CHOLMOD_DOUBLE;
    S.sorted = 1;  // Eigen keeps inner indices sorted in compressed mode
    S.packed = 1;
    return S;
  }

  void check_status(const char* what) {
    if (common_.status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
    SEFLEX_DEMAND(common_.status >= CHOLMOD_OK, std::string(what) + " failed (status " + std::to_string(common_.status) + ")");
  }

  void free_workspace() {
    if (x_ != nullptr) cholmod_l_free_dense(&x_, &common_);
    if (y_ != nullptr) cholmod_l_free_dense(&y_, &common_);
    if (e_ != nullptr) cholmod_l_free_dense(&e_, &common_);
  }

  cholmod_common common_{};
  cholmod_factor* factor_ = nullptr;
  cholmod_dense *x_ = nullptr, *y_ = nullptr, *e_ = nullptr;  // solve workspace, reused between solves
  std::vector<SuiteSparse_long> colptr_, rowind_;
  std::vector<double> values_;
  FactorizationStats stats_;
  bool factorized_ = false;
};

}  // namespace

std::unique_ptr<SparseFactorization> make_cholmod_factorization() { return std::make_unique<CholmodFactorization>(); }

}  // namespace seflex::linalg
