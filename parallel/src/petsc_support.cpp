// PETSc plumbing shared by the distributed backends (petsc_support.hpp).
#include "petsc_support.hpp"

#include <algorithm>
#include <vector>

#include "seflex/common/error.hpp"

namespace seflex::parallel::detail {

void check(PetscErrorCode ierr, const char* what) {
  if (ierr == 0) return;
  const char* text = nullptr;
  (void)PetscErrorMessage(ierr, &text, nullptr);
  throw InvariantError(std::string("PETSc error ") + std::to_string(static_cast<int>(ierr)) + " (" +
                       (text != nullptr ? text : "unknown") + ") in " + what);
}

namespace {

/// Row `i` of the upper triangle of A + beta B: column i of the lower triangles (rows >= i), merged.
void upper_row(const linalg::SparseMatrixd& A, const linalg::SparseMatrixd* B, double beta, PetscInt i,
               std::vector<PetscInt>& cols, std::vector<PetscScalar>& vals) {
  cols.clear();
  vals.clear();
  linalg::SparseMatrixd::InnerIterator a(A, i);
  while (a && a.row() < i) ++a;
  if (B == nullptr) {
    for (; a; ++a) {
      cols.push_back(static_cast<PetscInt>(a.row()));
      vals.push_back(a.value());
    }
    return;
  }
  linalg::SparseMatrixd::InnerIterator b(*B, i);
  while (b && b.row() < i) ++b;
  while (a || b) {
    if (b && (!a || b.row() < a.row())) {
      cols.push_back(static_cast<PetscInt>(b.row()));
      vals.push_back(beta * b.value());
      ++b;
    } else if (a && (!b || a.row() < b.row())) {
      cols.push_back(static_cast<PetscInt>(a.row()));
      vals.push_back(a.value());
      ++a;
    } else {
      cols.push_back(static_cast<PetscInt>(a.row()));
      vals.push_back(a.value() + beta * b.value());
      ++a;
      ++b;
    }
  }
}

}  // namespace

void make_upper_sbaij(const linalg::SparseMatrixd& A, const linalg::SparseMatrixd* B, double beta, Mat* out) {
  SEFLEX_DEMAND(A.cols() == A.rows() && A.isCompressed(), "make_upper_sbaij: A must be square and compressed");
  SEFLEX_DEMAND(B == nullptr || (B->rows() == A.rows() && B->cols() == A.cols() && B->isCompressed()),
                "make_upper_sbaij: B must match A and be compressed");
  PetscInt n = static_cast<PetscInt>(A.rows()), local = PETSC_DECIDE;
  SEFLEX_PETSC(PetscSplitOwnership(PETSC_COMM_WORLD, &local, &n));
  PetscInt end = 0;
  SEFLEX_DEMAND(MPI_Scan(&local, &end, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD) == MPI_SUCCESS, "MPI_Scan failed");
  const PetscInt begin = end - local;
  std::vector<PetscInt> d_nnz(static_cast<std::size_t>(local)), o_nnz(static_cast<std::size_t>(local));
  std::vector<PetscInt> cols;
  std::vector<PetscScalar> vals;
  for (PetscInt i = begin; i < end; ++i) {
    upper_row(A, B, beta, i, cols, vals);
    const auto d = std::count_if(cols.begin(), cols.end(), [&](PetscInt c) { return c < end; });
    d_nnz[static_cast<std::size_t>(i - begin)] = static_cast<PetscInt>(d);
    o_nnz[static_cast<std::size_t>(i - begin)] = static_cast<PetscInt>(cols.size()) - static_cast<PetscInt>(d);
  }
  SEFLEX_PETSC(MatCreate(PETSC_COMM_WORLD, out));
  SEFLEX_PETSC(MatSetSizes(*out, local, local, n, n));
  SEFLEX_PETSC(MatSetType(*out, MATSBAIJ));
  SEFLEX_PETSC(MatSeqSBAIJSetPreallocation(*out, 1, 0, d_nnz.data()));
  SEFLEX_PETSC(MatMPISBAIJSetPreallocation(*out, 1, 0, d_nnz.data(), 0, o_nnz.data()));
  SEFLEX_PETSC(MatSetOption(*out, MAT_IGNORE_LOWER_TRIANGULAR, PETSC_TRUE));
  for (PetscInt i = begin; i < end; ++i) {
    upper_row(A, B, beta, i, cols, vals);
    SEFLEX_PETSC(MatSetValues(*out, 1, &i, static_cast<PetscInt>(cols.size()), cols.data(), vals.data(), INSERT_VALUES));
  }
  SEFLEX_PETSC(MatAssemblyBegin(*out, MAT_FINAL_ASSEMBLY));
  SEFLEX_PETSC(MatAssemblyEnd(*out, MAT_FINAL_ASSEMBLY));
  SEFLEX_PETSC(MatSetOption(*out, MAT_SYMMETRIC, PETSC_TRUE));
}

void allgather_rows(const PetscInt* ranges, const double* local, PetscInt lda, Eigen::Ref<Eigen::MatrixXd> full) {
  int size = 1, rank = 0;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  const Eigen::Index n = full.rows(), k = full.cols();
  if (n == 0 || k == 0) return;
  // Columns in chunks so that every count fits an int.
  const Eigen::Index chunk = std::max<Eigen::Index>(1, (Eigen::Index{1} << 28) / n);
  const PetscInt my_rows = ranges[rank + 1] - ranges[rank];
  std::vector<double> send, recv(static_cast<std::size_t>(n * std::min(chunk, k)));
  std::vector<int> counts(static_cast<std::size_t>(size)), displs(static_cast<std::size_t>(size));
  for (Eigen::Index c0 = 0; c0 < k; c0 += chunk) {
    const Eigen::Index kc = std::min(chunk, k - c0);
    send.resize(static_cast<std::size_t>(my_rows * kc));
    for (Eigen::Index j = 0; j < kc; ++j)
      std::copy_n(local + (c0 + j) * lda, my_rows, send.begin() + j * my_rows);
    for (int r = 0; r < size; ++r) {
      counts[static_cast<std::size_t>(r)] = static_cast<int>((ranges[r + 1] - ranges[r]) * kc);
      displs[static_cast<std::size_t>(r)] = static_cast<int>(ranges[r] * kc);
    }
    SEFLEX_DEMAND(MPI_Allgatherv(send.data(), static_cast<int>(send.size()), MPI_DOUBLE, recv.data(), counts.data(),
                                 displs.data(), MPI_DOUBLE, PETSC_COMM_WORLD) == MPI_SUCCESS,
                  "MPI_Allgatherv failed");
    for (int r = 0; r < size; ++r) {
      const PetscInt rows = ranges[r + 1] - ranges[r];
      for (Eigen::Index j = 0; j < kc; ++j)
        for (PetscInt i = 0; i < rows; ++i)
          full(ranges[r] + i, c0 + j) = recv[static_cast<std::size_t>(displs[static_cast<std::size_t>(r)] + j * rows + i)];
    }
  }
}

double mumps_factor_nonzeros(Mat F) {
  PetscInt v = 0;
  if (MatMumpsGetInfog(F, 29, &v) != 0) return 0;
  return static_cast<double>(v);
}

void throw_if_factor_failed(Mat F, const char* what) {
  MatFactorError e = MAT_FACTOR_NOERROR;
  SEFLEX_PETSC(MatFactorGetError(F, &e));
  PetscInt infog1 = 0, infog2 = 0, negative = 0;
  (void)MatMumpsGetInfog(F, 12, &negative);  // negative pivots: A is indefinite
  if (e == MAT_FACTOR_NOERROR && negative == 0) return;
  (void)MatMumpsGetInfog(F, 1, &infog1);
  (void)MatMumpsGetInfog(F, 2, &infog2);
  if (e == MAT_FACTOR_NOERROR)
    throw linalg::FactorizationError(linalg::FactorizationError::Kind::NotPositiveDefinite, -1,
                                        std::string(what) + ": MUMPS Cholesky found " + std::to_string(negative) +
                                            " negative pivot(s): the matrix is not positive definite");
  throw linalg::FactorizationError(
      linalg::FactorizationError::Kind::NotPositiveDefinite, -1,
      std::string(what) + ": MUMPS Cholesky failed (INFOG(1) = " + std::to_string(infog1) + ", INFOG(2) = " +
          std::to_string(infog2) + "): the matrix is not positive definite");
}

}  // namespace seflex::parallel::detail
