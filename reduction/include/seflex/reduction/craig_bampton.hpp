#pragma once
// Craig-Bampton reduction of a constrained FE model (the f-set of fem::apply_constraints) for any
// boundary set given dof by dof (Craig & Bampton, AIAA J. 6(7), 1968; formulation.md section 1.2):
//
//   U_f = [Psi  Phi] [q_b; eta],   Psi = [I; -K_ii^-1 K_ib],   K_ii phi_k = lambda_k M_ii phi_k
//
// with b the boundary dofs (in the order given: the columns of Psi) and i the rest of the f-set.
// - Constraint modes: ONE factorisation of K_ii and one solve with n_b right-hand sides. They are
//   kept raw (never orthonormalised): q_b is the boundary displacement itself.
// - Fixed-interface modes: the lowest m eigenpairs of (K_ii, M_ii), mass-normalised
//   (phi^T M_ii phi = I), zero on b; either `modes` of them or all up to `fmax_hz`. A few more
//   (`extra_modes`) are computed to report the first neglected frequency.
// - Reduced matrices, n = n_b + m:
//     K = [Psi^T K Psi, 0; 0, diag(lambda)],   M = [Psi^T M Psi, Psi^T M Phi; Phi^T M Psi, I]
//   (the zero and identity blocks hold to round-off by construction and are set exactly).
// Sizes: n_f = K_ff.rows(); Psi is n_f x n_b, Phi is n_f x m, rows in f-set order.
// Cost: one factorisation of K_ii; the constraint modes are one solve with n_b right-hand sides;
// the fixed-interface modes come from a block shift-invert Lanczos on the same factor (block solves,
// reduction/src/craig_bampton_modes.hpp), or for small interiors from solve_eigenproblem.
#include <Eigen/Core>
#include <cmath>
#include <optional>
#include <vector>

#include "seflex/linalg/eigensolver.hpp"
#include "seflex/linalg/sparse_factorization.hpp"
#include "seflex/superelement/superelement.hpp"

namespace seflex::reduction {

/// How many fixed-interface modes to keep: exactly one of `modes` and `fmax_hz`.
struct CraigBamptonOptions {
  std::optional<int> modes;       ///< keep this many (0 = static/Guyan constraint modes only)
  std::optional<double> fmax_hz;  ///< keep every mode up to this frequency (Hz)
  int extra_modes = 3;            ///< computed beyond the kept ones for the truncation report
  /// Interiors with at least this many dofs get their modes from a block shift-invert Lanczos on
  /// the factor of K_ii the constraint modes made (one factorisation in all, BLAS-3 solves); smaller
  /// ones, and requests beyond its basis limit, from solve_eigenproblem with `backend`.
  Eigen::Index block_lanczos_min_size = 2000;
  linalg::EigenBackend backend = linalg::EigenBackend::Spectra;
  linalg::FactorizationBackend factorization = linalg::kDefaultFactorization;
  /// Distributed backends (parallel/, SEFLEX_MPI): when set, K_ii is factorised by an object it makes
  /// (instead of make_factorization(factorization)) and the fixed-interface eigenproblems that do not
  /// use that factor go to `external` (EigenOptions::external).
  linalg::FactorizationMaker factorization_maker;
  linalg::ExternalEigensolver external;
  /// Loads (n_f x k, f-set rows) whose static response with the boundary held, K_ii^-1 F_i, is
  /// returned in CraigBamptonBasis::static_responses: one more block solve with the factor of K_ii
  /// (the inertia load cases of the geometric-stiffness invariants, stiffening.hpp).
  Eigen::MatrixXd interior_loads;
};

/// Figures of the work done.
struct CraigBamptonStats {
  Eigen::Index n_free = 0, n_boundary = 0, n_interior = 0;
  linalg::FactorizationStats interior_factorization;  ///< of K_ii (constraint modes)
  linalg::EigenStats eigen;                           ///< of the (last) solve_eigenproblem run, if any
  int eigen_solutions = 0;                    ///< solve_eigenproblem runs (0 with block Lanczos)
  int block_solves = 0;                       ///< block Lanczos: block solves with the factor of K_ii
  Eigen::Index krylov_basis = 0;              ///< block Lanczos: basis size at convergence
};

struct CraigBamptonBasis {
  std::vector<Eigen::Index> boundary;     ///< f-set indices of the boundary dofs, in column order of Psi
  std::vector<Eigen::Index> interior;     ///< f-set indices of the interior dofs, ascending
  Eigen::MatrixXd Psi;                    ///< n_f x n_b constraint modes (identity on b)
  Eigen::MatrixXd Phi;                    ///< n_f x m fixed-interface modes (zero on b), M-orthonormal
  Eigen::VectorXd eigenvalues;            ///< m kept, ascending, (rad/s)^2
  Eigen::VectorXd neglected_eigenvalues;  ///< the next fixed-interface eigenvalues (up to extra_modes)
  Eigen::MatrixXd K, M;                   ///< (n_b + m) square reduced matrices (see above)
  Eigen::MatrixXd static_responses;       ///< n_f x k: K_ii^-1 of options.interior_loads, zero on b
  CraigBamptonStats stats;
};

/// Invariants of a request (any backend): a mode count or a frequency limit, not both, neither
/// negative; a boundary set. Violations are programming errors (InvariantError).
void demand_valid_request(const CraigBamptonOptions& options, const std::vector<Eigen::Index>& boundary);

/// Reduce (K_ff, M_ff) (both triangles stored, symmetric) to the boundary f-dofs `boundary`.
/// Throws InvariantError for bad options or indices (empty, out of range, repeated),
/// FactorizationError if K_ii is singular (the boundary does not hold the interior: the column
/// names the f-dof), ConvergenceError if the eigensolver fails.
CraigBamptonBasis craig_bampton(const linalg::SparseMatrixd& K_ff, const linalg::SparseMatrixd& M_ff,
                                const std::vector<Eigen::Index>& boundary, const CraigBamptonOptions& options);

/// What the kept fixed-interface modes retain ("model no more than a scene needs").
/// R_b (n_b x 6): the boundary motion of the six unit rigid-body motions (translations x, y, z and
/// rotations about the reference point, in the boundary dofs' own components). With R = Psi R_b the
/// static interior motion, the participation of mode k is L_k = phi_k^T M R (1 x 6) and its
/// effective mass L_k^2; the fraction per direction is the sum over the kept modes over the sum
/// over all interior modes, (M R)_i^T M_ii^+ (M R)_i (= R_i^T M_ii R_i when M_ib R_b = 0, e.g. a
/// lumped mass matrix: the interior's own rigid-body mass and inertia). A direction without
/// interior mass counts as fully kept (1). Frequencies come from the basis (first neglected 0 if
/// none was computed).
se::TruncationReport truncation_report(const CraigBamptonBasis& basis, const linalg::SparseMatrixd& M_ff,
                                       const Eigen::MatrixXd& R_b);

/// Eigenvalues (ascending, (rad/s)^2) of a small dense pencil (K, M), K and M positive
/// semi-definite: the lowest `count` (all finite ones if count exceeds them). Directions of M below
/// 1e-12 of its largest eigenvalue are massless and condensed out (their stiffness must be
/// positive definite). For the free-free frequencies of a reduced model: rigid-body modes come out
/// at zero to round-off, elastic ones to working precision. Dense O(n^3): reduced models only.
Eigen::VectorXd small_pencil_eigenvalues(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, int count);

/// Frequency in Hz of an eigenvalue (negative round-off of rigid-body modes gives 0).
inline double eigenvalue_to_hz(double lambda) {
  return lambda > 0 ? std::sqrt(lambda) / (2.0 * 3.14159265358979323846) : 0.0;
}

}  // namespace seflex::reduction
