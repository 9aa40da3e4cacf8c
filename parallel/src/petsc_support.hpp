#pragma once
// PETSc plumbing shared by the distributed backends (private to parallel/).
#include <petscmat.h>

#include <Eigen/Core>
#include <string>

#include "seflex/linalg/sparse_factorization.hpp"

namespace seflex::parallel::detail {

/// Throws InvariantError naming `what` and PETSc's message when ierr != 0.
void check(PetscErrorCode ierr, const char* what);
#define SEFLEX_PETSC(call) ::seflex::parallel::detail::check((call), #call)

/// Owns a PETSc object (Mat, Vec, KSP, EPS...) and destroys it with `destroy`.
template <class T, PetscErrorCode (*destroy)(T*)>
class Owned {
 public:
  Owned() = default;
  ~Owned() { reset(); }
  Owned(const Owned&) = delete;
  Owned& operator=(const Owned&) = delete;
  T* out() { reset(); return &p_; }  ///< for the PETSc call that creates it
  T get() const { return p_; }
  void reset() {
    if (p_ != nullptr) (void)destroy(&p_);  // destructors do not throw; a failed destroy only leaks
    p_ = nullptr;
  }

 private:
  T p_ = nullptr;
};
using OwnedMat = Owned<Mat, MatDestroy>;
using OwnedVec = Owned<Vec, VecDestroy>;

/// The distributed f-set K and M of a partitioned assembly (partitioned_system.hpp): MATSBAIJ,
/// K's pattern holds M's.
struct PetscPencil {
  OwnedMat K, M;
};

/// A + beta B (both n x n symmetric, lower triangles read; B may be null) as a distributed MATSBAIJ
/// (upper triangle, block size 1) on PETSC_COMM_WORLD: each rank inserts its own block of rows
/// (PETSc's default contiguous split). Every rank passes the same A and B.
void make_upper_sbaij(const linalg::SparseMatrixd& A, const linalg::SparseMatrixd* B, double beta, Mat* out);

/// Allgathers the rows [ranges[r], ranges[r+1]) that rank r holds in `local` (column-major, rows x k,
/// leading dimension lda) into `full` (n x k) on every rank.
void allgather_rows(const PetscInt* ranges, const double* local, PetscInt lda, Eigen::Ref<Eigen::MatrixXd> full);

/// Factor nonzeros MUMPS reports for F (INFOG(29)); 0 if unknown.
double mumps_factor_nonzeros(Mat F);

/// Throws linalg::FactorizationError if the numeric factorisation F failed (not positive definite).
void throw_if_factor_failed(Mat F, const char* what);

}  // namespace seflex::parallel::detail
