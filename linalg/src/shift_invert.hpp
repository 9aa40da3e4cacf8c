#pragma once
// The shift-invert operator of the generalised eigenproblem and the Krylov backends that use it
// (private to linalg/; one source file per backend).
#include <Eigen/Core>

#include "mass_product.hpp"
#include "seflex/linalg/eigensolver.hpp"
#include "seflex/linalg/sparse_factorization.hpp"

namespace seflex::linalg {

/// OP = P (K - sigma M)^-1 M P with P = I - X X^T M the M-orthogonal projector away from the locked
/// (already found, M-orthonormal) vectors X; X may have no columns (P = I).
/// Not const: every application counts, and the factorisation owns solve workspace.
class ShiftInvertOperator {
 public:
  ShiftInvertOperator(SparseFactorization& factor, const SparseMatrixd& M, const Eigen::MatrixXd& locked);
  Eigen::Index rows() const { return M_.rows(); }
  /// y = M x.
  void apply_M(const double* x, double* y) const;
  /// y = P (K - sigma M)^-1 P^T b, for b = M x (so that apply_inverse(M x) = OP x).
  void apply_inverse(const double* b, double* y);
  /// y = OP x.
  void apply(const double* x, double* y);
  long applications() const { return applications_; }

 private:
  SparseFactorization& factor_;
  const SparseMatrixd& M_;
  MassProduct mass_;  // the cheapest form of M (Krylov methods multiply by it several times per step)
  const Eigen::MatrixXd& X_;
  Eigen::MatrixXd MX_;  // M X
  Eigen::VectorXd scratch_;
  long applications_ = 0;
};

/// Dominant eigenpairs theta of OP found by a Krylov method: theta descending, vectors
/// M-orthonormal (n x k, k <= nev converged ones).
struct KrylovResult {
  Eigen::VectorXd theta;
  Eigen::MatrixXd vectors;
  int restarts = 0;
  bool converged = false;
};

KrylovResult run_spectra(ShiftInvertOperator& op, int nev, int ncv, double tol, int max_restarts, unsigned seed);
KrylovResult run_arpack(ShiftInvertOperator& op, int nev, int ncv, double tol, int max_restarts, unsigned seed);

/// All finite eigenpairs of the pencil, densely: theta = 1/(lambda - sigma) of
/// C = L^-1 M L^-T with K - sigma M = L L^T; returns the nev largest theta (descending) and
/// x = L^-T z, M-orthonormal. Precondition: K - sigma M positive definite.
KrylovResult solve_dense(const SparseMatrixd& K, const SparseMatrixd& M, double sigma, int nev);

}  // namespace seflex::linalg
