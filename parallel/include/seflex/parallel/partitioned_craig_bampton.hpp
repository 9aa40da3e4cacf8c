#pragma once
// Craig-Bampton reduction (reduction::craig_bampton's contract, formulas and result) on the
// matrices of a partitioned assembly (partitioned_system.hpp): no rank holds the whole K or M.
//
//   Psi_i = -K_ii^-1 K_ib   (MUMPS Cholesky of the distributed K_ii, all n_b right-hand sides in one
//                            MatMatSolve; K_ib columns = the interior rows of K e_b, one product each)
//   K_ii phi = lambda M_ii phi   (SLEPc Krylov-Schur, slepc_eigensolver.hpp, on the distributed
//                                 interior blocks: MatCreateSubMatrix of the partitioned K and M)
//   K_red = [Psi^T K Psi, 0; 0, diag(lambda)],  M_red = [Psi^T M Psi, Psi^T M Phi; Phi^T M Psi, I]
// with the products Psi^T K Psi, Psi^T M Psi, Phi^T M Psi summed from each rank's rows.
// Psi (n_f x n_b) and Phi (n_f x m) are gathered on every rank (f-set rows), as the replicated path.
// options.interior_loads (n_f x k, on every rank): their static responses K_ii^-1 F_i ride on the
// constraint modes' MatMatSolve (n_b + k right-hand sides, counted in the factorisation statistics)
// and are gathered into static_responses (f-set rows, zero on the boundary) like Psi.
// Modes: `modes` + extra_modes (or all up to fmax_hz, then extra_modes more), as the serial code.
//
// Collective on PETSC_COMM_WORLD; needs a parallel::Session. Throws InvariantError for bad options or
// boundary indices, FactorizationError (column -1: MUMPS does not name it) if K_ii is not positive
// definite, ConvergenceError if Krylov-Schur stops short.
#include <vector>

#include "seflex/parallel/partitioned_system.hpp"
#include "seflex/reduction/craig_bampton.hpp"

namespace seflex::parallel {

/// `boundary`: f-set indices (PartitionedSystem's f numbering), in the order of Psi's columns.
reduction::CraigBamptonBasis craig_bampton_partitioned(const PartitionedSystem& system,
                                                       const std::vector<Eigen::Index>& boundary,
                                                       const reduction::CraigBamptonOptions& options);

}  // namespace seflex::parallel
