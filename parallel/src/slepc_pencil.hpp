#pragma once
// The distributed eigensolver's core on PETSc matrices (private to parallel/; slepc_eigensolver.hpp
// states the method).
#include <petscmat.h>

#include "seflex/linalg/eigensolver.hpp"

namespace seflex::parallel::detail {

/// Lowest eigenpairs of K x = lambda M x, K and M distributed MATSBAIJ with K's pattern holding M's:
/// shift-invert Krylov-Schur on a MUMPS factor of K - sigma M, the shift calibration, Rayleigh-Ritz.
/// Vectors (n x m, rows in the matrices' numbering) gathered on every rank. Collective.
linalg::EigenSolution solve_pencil(Mat K, Mat M, const linalg::EigenOptions& options);

}  // namespace seflex::parallel::detail
