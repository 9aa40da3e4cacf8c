// Distributed Cholesky by MUMPS through PETSc (mumps_factorization.hpp).
#include "seflex/parallel/mumps_factorization.hpp"

#include <chrono>

#include "petsc_support.hpp"

namespace seflex::parallel {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

class MumpsFactorization final : public linalg::SparseFactorization {
 public:
  linalg::FactorizationBackend backend() const override { return linalg::FactorizationBackend::Mumps; }
  bool positive_definite_only() const override { return true; }

  void factorize(const linalg::SparseMatrixd& A) override {
    const auto t0 = Clock::now();
    A_.reset();
    F_.reset();
    detail::make_upper_sbaij(A, nullptr, 0.0, A_.out());
    SEFLEX_PETSC(MatSetOption(A_.get(), MAT_SPD, PETSC_TRUE));
    SEFLEX_PETSC(MatGetFactor(A_.get(), MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, F_.out()));
    IS perm = nullptr;  // MUMPS orders itself
    MatFactorInfo info;
    SEFLEX_PETSC(MatFactorInfoInitialize(&info));
    const auto t1 = Clock::now();
    SEFLEX_PETSC(MatCholeskyFactorSymbolic(F_.get(), A_.get(), perm, &info));
    const auto t2 = Clock::now();
    SEFLEX_PETSC(MatCholeskyFactorNumeric(F_.get(), A_.get(), &info));
    detail::throw_if_factor_failed(F_.get(), "distributed factorisation");
    stats_.rows = A.rows();
    stats_.factor_nonzeros = detail::mumps_factor_nonzeros(F_.get());
    ++stats_.symbolic_analyses;
    ++stats_.numeric_factorizations;
    stats_.seconds_symbolic += std::chrono::duration<double>(t2 - t1).count();
    stats_.seconds_numeric += seconds_since(t2);
    stats_.seconds_ordering += std::chrono::duration<double>(t1 - t0).count();  // here: the copy into PETSc
  }

  void solve_in_place(Eigen::Ref<Eigen::MatrixXd> B) override {
    SEFLEX_DEMAND(F_.get() != nullptr, "MUMPS solve before factorize");
    SEFLEX_DEMAND(B.rows() == stats_.rows, "MUMPS solve: right-hand side has the wrong number of rows");
    if (B.cols() == 0) return;
    const auto t0 = Clock::now();
    const PetscInt* ranges = nullptr;
    SEFLEX_PETSC(MatGetOwnershipRanges(A_.get(), &ranges));
    PetscInt begin = 0, end = 0;
    SEFLEX_PETSC(MatGetOwnershipRange(A_.get(), &begin, &end));
    const auto k = static_cast<PetscInt>(B.cols());
    detail::OwnedMat rhs, x;
    SEFLEX_PETSC(MatCreateDense(PETSC_COMM_WORLD, end - begin, PETSC_DECIDE, B.rows(), k, nullptr, rhs.out()));
    PetscScalar* a = nullptr;
    SEFLEX_PETSC(MatDenseGetArrayWrite(rhs.get(), &a));
    PetscInt lda = 0;
    SEFLEX_PETSC(MatDenseGetLDA(rhs.get(), &lda));
    for (PetscInt j = 0; j < k; ++j)
      for (PetscInt i = begin; i < end; ++i) a[j * lda + (i - begin)] = B(i, j);
    SEFLEX_PETSC(MatDenseRestoreArrayWrite(rhs.get(), &a));
    SEFLEX_PETSC(MatDuplicate(rhs.get(), MAT_DO_NOT_COPY_VALUES, x.out()));
    SEFLEX_PETSC(MatMatSolve(F_.get(), rhs.get(), x.get()));
    const PetscScalar* xa = nullptr;
    SEFLEX_PETSC(MatDenseGetArrayRead(x.get(), &xa));
    PetscInt xlda = 0;
    SEFLEX_PETSC(MatDenseGetLDA(x.get(), &xlda));
    detail::allgather_rows(ranges, xa, xlda, B);
    SEFLEX_PETSC(MatDenseRestoreArrayRead(x.get(), &xa));
    stats_.seconds_solve += seconds_since(t0);
    stats_.solve_columns += B.cols();
    ++stats_.solve_calls;
  }

  std::optional<Eigen::Index> negative_pivots() const override { return std::nullopt; }
  const linalg::FactorizationStats& stats() const override { return stats_; }

 private:
  detail::OwnedMat A_, F_;
  linalg::FactorizationStats stats_;
};

}  // namespace

std::unique_ptr<linalg::SparseFactorization> make_mumps_factorization() {
  return std::make_unique<MumpsFactorization>();
}

}  // namespace seflex::parallel
