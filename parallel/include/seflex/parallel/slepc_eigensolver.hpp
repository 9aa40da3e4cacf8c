#pragma once
// Distributed generalised eigensolution K x = lambda M x on PETSc + SLEPc (docs/distributed.md):
// the linalg::ExternalEigensolver of `seflex modes/reduce --backend slepc`.
//
// Method
// - Every rank passes the same K and M (n x n, symmetric, lower triangles read); each rank copies its
//   contiguous block of rows (PETSc's default split, ~n/P rows) into distributed symmetric PETSc
//   matrices (MATSBAIJ, upper triangle), so the factor and the Krylov vectors are distributed.
// - Shift-invert: A = K - sigma M with sigma below the spectrum (sigma = -1e-12 median(K_ii/M_ii), as
//   the serial backends), factorised once by MUMPS (Cholesky, distributed); SLEPc's Krylov-Schur
//   finds the largest theta of M x = theta A x (a GHEP whose B = A is positive definite even when M
//   is singular: massless dofs have theta = 0 and are never wanted), lambda = sigma + 1/theta.
// - A count runs once; a frequency bound (lambda_max alone) or lambda_min doubles the number of
//   requested pairs until the range is covered.
// - The converged vectors are gathered onto every rank (n x m each) and refined by Rayleigh-Ritz on
//   (K, M) in their span, X^T K X and X^T M X summed from each rank's rows of the distributed
//   products (M-orthonormal vectors): the same EigenSolution as the serial backends, on every rank.
// Collective on PETSC_COMM_WORLD; needs a parallel::Session.
// Throws linalg::FactorizationError if MUMPS finds A not positive definite (column unknown: -1),
// ConvergenceError if Krylov-Schur stops short of the wanted pairs, InvariantError on PETSc failures.
#include "seflex/parallel/partitioned_system.hpp"
#include "seflex/linalg/eigensolver.hpp"

namespace seflex::parallel {

linalg::EigenSolution slepc_eigenproblem(const linalg::SparseMatrixd& K, const linalg::SparseMatrixd& M,
                                            const linalg::EigenOptions& options);

/// The same method on the matrices of a partitioned assembly (nothing replicated but the gathered
/// vectors): vectors n_free x m in the serial f numbering (PartitionedSystem::f_to_g), on every rank.
linalg::EigenSolution slepc_eigenproblem_partitioned(const PartitionedSystem& system, const linalg::EigenOptions& options);

}  // namespace seflex::parallel
