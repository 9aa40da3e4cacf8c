#pragma once
// Sparse symmetric factorisation behind one small interface, one file per backend:
//   - Cholmod:   CHOLMOD supernodal Cholesky L L^T (METIS ordering, BLAS-3 on OpenBLAS);
//                positive definite matrices only. The default (docs/benchmarks.md, docs/solvers.md).
//   - EigenLdlt: Eigen's SimplicialLDLT with METIS fill-reducing ordering (Eigen/MetisSupport);
//                handles symmetric indefinite matrices without a zero pivot and reports the inertia
//                (number of negative pivots), i.e. the Sturm count of K - sigma M.
//
// Contract
// - A is square and symmetric; only its lower triangle is read (full or lower storage both work).
// - factorize() reuses the symbolic analysis (ordering, elimination tree) when A has exactly the
//   sparsity pattern of the previous call, so refactorising K - sigma M for a new sigma is cheap.
// - solve() solves A X = B in place for a block of right-hand sides (n x k, any k >= 0); blocks are
//   solved together (BLAS-3 in the supernodal backend), so pass many columns at once.
// - A non-positive pivot in a Cholesky backend, or a pivot that is round-off relative to the
//   diagonal it came from (|d_j| <= kPivotTolerance |A_jj|: A singular to working precision) in
//   either backend, throws FactorizationError naming the column of A (original numbering) where
//   elimination broke down; a caller that knows what the columns mean (a DofMap) turns it into an
//   InputError naming the grid and component.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "seflex/common/error.hpp"

namespace seflex::linalg {

using SparseMatrixd = Eigen::SparseMatrix<double>;  ///< column-major, int indices

/// Mumps is the distributed factorisation of parallel/ (SEFLEX_MPI builds): make_factorization
/// does not make it and parse_factorization_backend does not accept it; it arrives through a
/// FactorizationMaker (craig_bampton.hpp).
enum class FactorizationBackend : std::uint8_t { Cholmod, EigenLdlt, Mumps };

/// "cholmod", "ldlt" or "mumps".
std::string_view to_string(FactorizationBackend backend);
/// Parse "cholmod" / "ldlt"; nullopt for anything else.
std::optional<FactorizationBackend> parse_factorization_backend(std::string_view name);
/// The backend chosen by measurement on the 10k/100k/1M-dof plates (docs/benchmarks.md): Cholmod.
constexpr FactorizationBackend kDefaultFactorization = FactorizationBackend::Cholmod;

/// Pivots smaller than this fraction of their original diagonal are treated as zero (singular A).
constexpr double kPivotTolerance = 1e3 * 2.220446049250313e-16;

/// Elimination broke down: a non-positive pivot (Cholesky) or a zero pivot (LDL^T) at `column`.
class FactorizationError : public InvariantError {
 public:
  enum class Kind : std::uint8_t { NotPositiveDefinite, Singular };
  FactorizationError(Kind kind, Eigen::Index column, const std::string& message)
      : InvariantError(message), kind_(kind), column_(column) {}
  Kind kind() const { return kind_; }
  /// Column (= dof) of A, in A's own numbering, where elimination failed.
  Eigen::Index column() const { return column_; }

 private:
  Kind kind_;
  Eigen::Index column_;
};

/// Figures of the last factorisation (for benchmarks and the solution summaries).
struct FactorizationStats {
  Eigen::Index rows = 0;
  double factor_nonzeros = 0;     ///< entries of L (including the diagonal)
  double flops = 0;               ///< floating-point operations of the numeric factorisation (0 if unknown)
  /// min_j |pivot_j| / |A_jj|: near kPivotTolerance when A is close to singular (e.g. K + s M of a
  /// free-free model with a tiny s), O(1e-3..1) for a well-constrained stiffness.
  double min_pivot_ratio = 0;
  int symbolic_analyses = 0;      ///< how many times the pattern was (re)analysed
  int numeric_factorizations = 0;
  // Wall time, summed over all calls (benchmarks only; 0 where a backend does not split them).
  double seconds_ordering = 0;    ///< fill-reducing ordering (METIS)
  double seconds_symbolic = 0;    ///< symbolic analysis (elimination tree, supernodes)
  double seconds_numeric = 0;     ///< numeric factorisations, with the copy of A and the pivot check
  double seconds_solve = 0;       ///< solve_in_place
  long solve_columns = 0;         ///< right-hand sides solved
  int solve_calls = 0;            ///< solve_in_place calls
};

/// A factorisation object owns the factor and the solve workspace (it is state, not a function):
/// one object per matrix, not shared between threads.
class SparseFactorization {
 public:
  virtual ~SparseFactorization() = default;
  SparseFactorization() = default;
  SparseFactorization(const SparseFactorization&) = delete;
  SparseFactorization& operator=(const SparseFactorization&) = delete;

  virtual FactorizationBackend backend() const = 0;
  /// True if the backend factorises only positive definite matrices (Cholesky).
  virtual bool positive_definite_only() const = 0;

  /// Factorise A (n x n, lower triangle read). Throws FactorizationError on breakdown.
  virtual void factorize(const SparseMatrixd& A) = 0;

  /// Solve A X = B in place; B is n x k. Precondition: factorize() succeeded.
  virtual void solve_in_place(Eigen::Ref<Eigen::MatrixXd> B) = 0;

  /// Number of negative pivots of the last factorisation (= eigenvalues of the pencil (K, M) below
  /// sigma when A = K - sigma M, K positive definite on the null space of M). LDL^T backends only.
  virtual std::optional<Eigen::Index> negative_pivots() const = 0;

  virtual const FactorizationStats& stats() const = 0;

  /// X = A^-1 B.
  Eigen::MatrixXd solve(const Eigen::Ref<const Eigen::MatrixXd>& B) {
    Eigen::MatrixXd X = B;
    solve_in_place(X);
    return X;
  }
};

/// Makes a new, empty factorisation (a backend outside linalg/, e.g. parallel/'s MUMPS).
using FactorizationMaker = std::function<std::unique_ptr<SparseFactorization>()>;

/// A new, empty factorisation of the given backend (Cholmod or EigenLdlt; InvariantError for Mumps).
std::unique_ptr<SparseFactorization> make_factorization(FactorizationBackend backend = kDefaultFactorization);

}  // namespace seflex::linalg
