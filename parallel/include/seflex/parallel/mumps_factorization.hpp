#pragma once
// Distributed sparse Cholesky factorisation by MUMPS through PETSc, behind linalg's
// SparseFactorization interface (the FactorizationMaker of `seflex reduce --backend slepc`).
// - factorize(A): every rank passes the same A (lower triangle read); each rank copies its block of
//   rows into a distributed MATSBAIJ and MUMPS factorises it (Cholesky, positive definite A).
// - solve_in_place(B): every rank passes the same B (n x k); each rank hands its rows to MUMPS
//   (MatMatSolve: all k right-hand sides in one solve), and the solution is gathered back into B on
//   every rank.
// Collective on PETSC_COMM_WORLD; needs a parallel::Session. factorize() throws
// linalg::FactorizationError (column -1: MUMPS does not name it) when A is not positive definite.
#include <memory>

#include "seflex/linalg/sparse_factorization.hpp"

namespace seflex::parallel {

std::unique_ptr<linalg::SparseFactorization> make_mumps_factorization();

}  // namespace seflex::parallel
