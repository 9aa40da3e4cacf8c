#pragma once
// Generalised symmetric eigenproblem K x = lambda M x for the lowest eigenpairs of an FE model
// (lambda = omega^2, rad^2/s^2). Backends, one file each:
//   - Block (default): block shift-invert Lanczos with full reorthogonalisation, no restarts
//     (block_lanczos.hpp; the method of MSC Nastran's EIGRL): each step is one multi-column solve;
//   - Spectra: implicitly restarted Lanczos (SymGEigsShiftSolver, shift-invert mode);
//   - Arpack: dsaupd/dseupd, shift-invert mode 3 (bmat = 'G', which = 'LM');
//   - Dense: LAPACK-style dense solution of the transformed problem, for small models.
//
// Method (docs/solvers.md)
// - Spectral transformation with the M inner product: OP = (K - sigma M)^-1 M, theta = 1/(lambda - sigma).
//   M may be singular (lumped mass with massless rotations): OP's range holds exactly the finite
//   eigenvectors, the Lanczos vectors start and stay in it, and the final Ritz vectors are purified
//   by one more application of OP (Ericsson & Ruhe 1980; Nour-Omid, Parlett, Ericsson & Jensen 1987).
// - sigma lies below the spectrum: sigma = -1e-10 * median(K_ii / M_ii) unless given, so K - sigma M
//   is positive definite (Cholesky works) even for free-free models, whose rigid-body modes are then
//   the dominant eigenvalues of OP. If the factorisation still fails, sigma moves down by 1e3 (twice)
//   before the model is declared a mechanism.
// - Completeness: single-vector Lanczos can miss copies of a multiple eigenvalue (six rigid-body
//   modes, symmetric structures). After the wanted modes are found, a second Lanczos run on OP
//   deflated of them (P OP P, P = I - X X^T M) looks for anything left below the highest mode found;
//   what it finds is merged and the check repeats until nothing is missing.
// - Final Rayleigh-Ritz in the transformed space: H = X^T M OP X gives theta (accurate also for
//   rigid-body modes, whose lambda = sigma + 1/theta is ~1e-16 |sigma| instead of eps * ||K||), the
//   purified vectors OP X c / theta are M-orthonormalised.
#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>

#include "seflex/linalg/sparse_factorization.hpp"

namespace seflex::linalg {

/// Slepc is the distributed backend of parallel/ (SEFLEX_MPI builds): linalg/ never runs it itself,
/// it arrives through EigenOptions::external and is never parsed from an --eigensolver name.
enum class EigenBackend : std::uint8_t { Spectra, Arpack, Dense, Block, Slepc };

/// "spectra", "arpack", "dense" or "block".
std::string_view to_string(EigenBackend backend);
std::optional<EigenBackend> parse_eigen_backend(std::string_view name);
/// The names parse_eigen_backend accepts, for messages: "block, spectra, arpack or dense".
std::string_view eigen_backend_names();

struct EigenSolution;
struct EigenOptions;
/// An eigensolver outside linalg/ (parallel/'s SLEPc backend): same contract as solve_eigenproblem.
using ExternalEigensolver = std::function<EigenSolution(const SparseMatrixd& K, const SparseMatrixd& M,
                                                        const EigenOptions& options)>;

/// Which eigenpairs to compute and how. Every range bound is in eigenvalue units (rad/s)^2.
struct EigenOptions {
  /// Number of lowest eigenpairs wanted (Nastran ND); nullopt = all in [lambda_min, lambda_max]
  /// (then lambda_max is required).
  std::optional<int> count = 10;
  std::optional<double> lambda_min;  ///< keep eigenvalues >= lambda_min (Nastran F1, as (2 pi F1)^2)
  std::optional<double> lambda_max;  ///< keep eigenvalues <= lambda_max (Nastran F2)
  /// Block by measurement (docs/solvers.md). Block handles a count or an upper bound alone; a count
  /// with a range, or a basis beyond its limit, falls back to Spectra (EigenStats::backend_used).
  EigenBackend backend = EigenBackend::Block;
  int block_size = 8;                  ///< block of the Block backend (>= the largest multiplicity)
  FactorizationBackend factorization = kDefaultFactorization;
  /// Models with at most this many dofs are solved densely whatever the backend (exact, fast).
  int dense_below = 200;
  double tolerance = 1e-10;            ///< Lanczos convergence: ||OP x - theta x||_M <= tol |theta|
  std::optional<double> shift;         ///< sigma; must lie below the wanted eigenvalues
  bool check_completeness = true;      ///< run the deflated missing-mode check
  int subspace = 0;                    ///< Krylov subspace size of the main run; 0 = automatic
  int max_restarts = 1000;
  /// When set, solve_eigenproblem hands the whole problem to it (every other backend option is then
  /// only passed along): the seam through which parallel/ plugs in the distributed SLEPc solver.
  ExternalEigensolver external;
};

/// Counters of the work done (for summaries and benchmarks).
struct EigenStats {
  double shift = 0;                    ///< sigma used
  int factorizations = 0;              ///< numeric factorisations of K - sigma M
  long operator_applications = 0;      ///< OP x products (one sparse solve each)
  int lanczos_runs = 0;                ///< main run(s) + completeness checks
  int missed_modes_recovered = 0;      ///< modes found by the completeness check
  EigenBackend backend_used = EigenBackend::Spectra;
  FactorizationStats factorization;
  // Wall time of the phases (benchmarks and summaries; never used by the algorithm).
  double seconds_factorization = 0, seconds_calibration = 0, seconds_lanczos = 0, seconds_check = 0,
         seconds_postprocess = 0;
};

struct EigenSolution {
  Eigen::VectorXd eigenvalues;         ///< m, ascending, (rad/s)^2
  Eigen::MatrixXd vectors;             ///< n x m, M-orthonormal: X^T M X = I
  /// Backward error per mode: ||K x - lambda M x|| / ((||K||_1 + |lambda| ||M||_1) ||x||).
  Eigen::VectorXd backward_errors;
  EigenStats stats;
};

/// Lowest eigenpairs of K x = lambda M x (both n x n symmetric, lower triangles read; K positive
/// semi-definite, M positive semi-definite, K + |sigma| M positive definite).
/// Returns min(count, number of finite eigenvalues) pairs within [lambda_min, lambda_max].
/// Throws FactorizationError if K - sigma M cannot be factorised (a mechanism: a dof with neither
/// stiffness nor mass), ConvergenceError if Lanczos does not converge, InvariantError on bad sizes.
EigenSolution solve_eigenproblem(const SparseMatrixd& K, const SparseMatrixd& M, const EigenOptions& options);

}  // namespace seflex::linalg
