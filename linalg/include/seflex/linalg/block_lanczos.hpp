#pragma once
// Block shift-invert Lanczos on a factorisation of K - sigma M (linalg; public for reduction/). Used for
// - the fixed-interface modes of a Craig-Bampton reduction, from the factorisation of K_ii that the
//   constraint modes already needed (shift 0: K_ii is positive definite when the interface holds the
//   interior), so the reduction factorises K_ii once (craig_bampton.cpp);
// - the `block` backend of solve_eigenproblem (eigensolver.cpp), the default of `seflex modes`.
// Every application of the operator is a block solve (BLAS-3 in the supernodal factor) instead of a
// single-vector one (docs/solvers.md, docs/benchmarks.md). Tested through craig_bampton() and
// solve_eigenproblem().
//
// Method (Grimes, Lewis & Simon, SIAM J. Matrix Anal. Appl. 15(1), 1994, the block shift-invert
// Lanczos of MSC Nastran's EIGRL): OP = K^-1 M, self-adjoint in the M inner product. The start
// block is OP X0 (X0 random), so the basis lies in range(OP) and massless dofs need no care. Each
// step appends OP Q_j, M-orthogonalised twice against the whole basis (full reorthogonalisation, no
// restarts) and within itself; T = V^T M OP V is the projected operator, and the Ritz pair (theta, c)
// has the residual ||OP y - theta y||_M = ||R_{j+1} c_j|| (c_j: the last block of c). A pair counts as
// converged when that residual is <= tol * theta. The lowest pairs are accepted as a prefix: the
// search stops when the `count` lowest (or all below lambda_max and `extra` more) have converged.
// With `locked` vectors X (M-orthonormal) every block is also M-orthogonalised against X, i.e. the
// operator is P OP P with P = I - X X^T M (deflation: the eigenpairs not in span(X)).
// Eigenvalues are those of the factorised pencil: 1/theta = lambda - sigma.
#include <Eigen/Core>
#include <optional>

#include "seflex/linalg/sparse_factorization.hpp"

namespace seflex::linalg::detail {

struct BlockLanczosOptions {
  std::optional<Eigen::Index> count;  ///< lowest pairs wanted
  std::optional<double> lambda_max;   ///< or: all pairs up to this eigenvalue ...
  Eigen::Index extra = 0;             ///< ... and this many more above it
  Eigen::Index block = 8;             ///< block size (4-8 fastest on the 100k-dof panel, 30 modes)
  Eigen::Index max_basis = 600;       ///< give up (nullopt) beyond this many basis vectors
  double tolerance = 1e-10;
  unsigned seed = 20261121u;
  const Eigen::MatrixXd* locked = nullptr;  ///< M-orthonormal vectors deflated from the operator (or none)
};

struct BlockLanczosResult {
  Eigen::VectorXd eigenvalues;  ///< ascending, 1/theta = lambda - sigma
  Eigen::MatrixXd vectors;      ///< M-orthonormal
  int block_solves = 0;
  Eigen::Index basis_size = 0;
};

/// Columns of the symmetric M (one triangle or both stored) holding a nonzero: an upper bound of
/// rank(M), the number of finite eigenvalues.
Eigen::Index mass_rank_bound(const SparseMatrixd& M);

/// Lowest eigenpairs of K x = lambda M x, `factor` holding K - sigma M (positive definite), M symmetric
/// positive semi-definite (lower triangle read). nullopt if the basis would exceed max_basis (the
/// caller then uses the restarted eigensolver). Fewer pairs than asked when the finite spectrum
/// (rank of M) is exhausted.
std::optional<BlockLanczosResult> block_lanczos_lowest(SparseFactorization& factor, const SparseMatrixd& M,
                                                       const BlockLanczosOptions& options);

}  // namespace seflex::linalg::detail
