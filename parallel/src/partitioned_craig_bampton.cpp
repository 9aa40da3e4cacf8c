// Craig-Bampton on a partitioned assembly (partitioned_craig_bampton.hpp).
#include "seflex/parallel/partitioned_craig_bampton.hpp"

#include <petscis.h>

#include <chrono>
#include <cmath>
#include <numeric>

#include "petsc_support.hpp"
#include "seflex/common/error.hpp"
#include "slepc_pencil.hpp"

namespace seflex::parallel {
namespace {

using Clock = std::chrono::steady_clock;
using OwnedIS = detail::Owned<IS, ISDestroy>;

void allreduce_sum(Eigen::MatrixXd& A) {
  if (A.size() == 0) return;
  SEFLEX_DEMAND(MPI_Allreduce(MPI_IN_PLACE, A.data(), static_cast<int>(A.size()), MPI_DOUBLE, MPI_SUM,
                              PETSC_COMM_WORLD) == MPI_SUCCESS,
                "MPI_Allreduce failed");
}

/// A X for the rows this rank owns (X: this rank's rows [lo, hi) of an n x k matrix in A's numbering).
Eigen::MatrixXd local_product(Mat A, const Eigen::MatrixXd& X_local) {
  detail::OwnedVec x, y;
  SEFLEX_PETSC(MatCreateVecs(A, x.out(), y.out()));
  const Eigen::Index rows = X_local.rows();
  Eigen::MatrixXd AX(rows, X_local.cols());
  for (Eigen::Index k = 0; k < X_local.cols(); ++k) {
    PetscScalar* v = nullptr;
    SEFLEX_PETSC(VecGetArrayWrite(x.get(), &v));
    Eigen::Map<Eigen::VectorXd>(v, rows) = X_local.col(k);
    SEFLEX_PETSC(VecRestoreArrayWrite(x.get(), &v));
    SEFLEX_PETSC(MatMult(A, x.get(), y.get()));
    const PetscScalar* w = nullptr;
    SEFLEX_PETSC(VecGetArrayRead(y.get(), &w));
    AX.col(k) = Eigen::Map<const Eigen::VectorXd>(w, rows);
    SEFLEX_PETSC(VecRestoreArrayRead(y.get(), &w));
  }
  return AX;
}

/// Gathers every rank's rows (counts `local` each, in rank order) of a k-column matrix onto every rank.
Eigen::MatrixXd gather_rows(const Eigen::MatrixXd& mine, Eigen::Index total) {
  int size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  std::vector<PetscInt> ranges(static_cast<std::size_t>(size) + 1, 0);
  const auto my_rows = static_cast<PetscInt>(mine.rows());
  SEFLEX_DEMAND(MPI_Allgather(&my_rows, 1, MPIU_INT, ranges.data() + 1, 1, MPIU_INT, PETSC_COMM_WORLD) == MPI_SUCCESS,
                "MPI_Allgather failed");
  std::partial_sum(ranges.begin(), ranges.end(), ranges.begin());
  SEFLEX_DEMAND(ranges.back() == total, "gather_rows: the ranks' rows do not add up");
  Eigen::MatrixXd all(total, mine.cols());
  detail::allgather_rows(ranges.data(), mine.data(), my_rows, all);
  return all;
}

}  // namespace

reduction::CraigBamptonBasis craig_bampton_partitioned(const PartitionedSystem& system,
                                                       const std::vector<Eigen::Index>& boundary,
                                                       const reduction::CraigBamptonOptions& options) {
  const Eigen::Index n = system.n_free();
  reduction::demand_valid_request(options, boundary);
  Mat K = system.pencil().K.get(), M = system.pencil().M.get();

  reduction::CraigBamptonBasis cb;
  cb.boundary = boundary;
  std::vector<char> on_boundary(static_cast<std::size_t>(n), 0);
  for (Eigen::Index f : boundary) {
    SEFLEX_DEMAND(f >= 0 && f < n, "Craig-Bampton: boundary dof out of range");
    SEFLEX_DEMAND(!on_boundary[static_cast<std::size_t>(f)], "Craig-Bampton: boundary dof " + std::to_string(f) + " given twice");
    on_boundary[static_cast<std::size_t>(f)] = 1;
  }
  for (Eigen::Index f = 0; f < n; ++f)
    if (!on_boundary[static_cast<std::size_t>(f)]) cb.interior.push_back(f);
  const auto nb = static_cast<Eigen::Index>(boundary.size()), ni = static_cast<Eigen::Index>(cb.interior.size());
  cb.stats.n_free = n;
  cb.stats.n_boundary = nb;
  cb.stats.n_interior = ni;

  // This rank's rows: [lo, hi) of the partition numbering; its interior rows in increasing p.
  PetscInt lo = 0, hi = 0;
  SEFLEX_PETSC(MatGetOwnershipRange(K, &lo, &hi));
  const Eigen::Index local = hi - lo;
  std::vector<PetscInt> interior_p;
  for (PetscInt p = lo; p < hi; ++p)
    if (!on_boundary[static_cast<std::size_t>(system.p_to_f[static_cast<std::size_t>(p)])]) interior_p.push_back(p);
  const auto local_i = static_cast<Eigen::Index>(interior_p.size());
  const Eigen::Index nl = options.interior_loads.cols();  // load cases riding on the constraint-mode solve
  SEFLEX_DEMAND(nl == 0 || options.interior_loads.rows() == n, "Craig-Bampton: interior_loads must have one row per f-dof");

  // K_ib columns: the interior rows of K e_b (one product per boundary dof).
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(local, nb);  // Psi's boundary part, this rank's rows
  for (Eigen::Index k = 0; k < nb; ++k) {
    const Eigen::Index p = system.f_to_p[static_cast<std::size_t>(boundary[static_cast<std::size_t>(k)])];
    if (p >= lo && p < hi) E(p - lo, k) = 1.0;
  }
  const Eigen::MatrixXd KE = local_product(K, E);

  // K_ii and M_ii: the interior block of the distributed matrices (rows in rank order of interior_p).
  detail::OwnedMat K_ii, M_ii, F;
  OwnedIS is;
  SEFLEX_PETSC(ISCreateGeneral(PETSC_COMM_WORLD, static_cast<PetscInt>(local_i), interior_p.data(), PETSC_COPY_VALUES, is.out()));
  Eigen::MatrixXd Psi_local = E;  // this rank's rows of Psi (partition numbering)
  Eigen::MatrixXd Y_local = Eigen::MatrixXd::Zero(local, nl);  // this rank's rows of K_ii^-1 F_i, 0 on b
  if (ni > 0) {
    SEFLEX_PETSC(MatCreateSubMatrix(K, is.get(), is.get(), MAT_INITIAL_MATRIX, K_ii.out()));
    SEFLEX_PETSC(MatCreateSubMatrix(M, is.get(), is.get(), MAT_INITIAL_MATRIX, M_ii.out()));
    // Constraint modes Psi_i = -K_ii^-1 K_ib and the static responses K_ii^-1 F_i of the interior
    // loads: one factorisation, one multi-column solve (n_b + n_l right-hand sides).
    const auto t0 = Clock::now();
    SEFLEX_PETSC(MatSetOption(K_ii.get(), MAT_SPD, PETSC_TRUE));
    SEFLEX_PETSC(MatGetFactor(K_ii.get(), MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, F.out()));
    MatFactorInfo info;
    SEFLEX_PETSC(MatFactorInfoInitialize(&info));
    SEFLEX_PETSC(MatCholeskyFactorSymbolic(F.get(), K_ii.get(), nullptr, &info));
    const auto t1 = Clock::now();
    SEFLEX_PETSC(MatCholeskyFactorNumeric(F.get(), K_ii.get(), &info));
    detail::throw_if_factor_failed(F.get(), "Craig-Bampton: K_ii");
    const auto t2 = Clock::now();
    detail::OwnedMat rhs, x;
    SEFLEX_PETSC(MatCreateDense(PETSC_COMM_WORLD, static_cast<PetscInt>(local_i), PETSC_DECIDE, static_cast<PetscInt>(ni),
                                static_cast<PetscInt>(nb + nl), nullptr, rhs.out()));
    PetscScalar* a = nullptr;
    PetscInt lda = 0;
    SEFLEX_PETSC(MatDenseGetLDA(rhs.get(), &lda));
    SEFLEX_PETSC(MatDenseGetArrayWrite(rhs.get(), &a));
    for (Eigen::Index k = 0; k < nb; ++k)
      for (Eigen::Index q = 0; q < local_i; ++q) a[k * lda + q] = -KE(interior_p[static_cast<std::size_t>(q)] - lo, k);
    for (Eigen::Index k = 0; k < nl; ++k)
      for (Eigen::Index q = 0; q < local_i; ++q) {
        const PetscInt p = interior_p[static_cast<std::size_t>(q)];
        a[(nb + k) * lda + q] = options.interior_loads(system.p_to_f[static_cast<std::size_t>(p)], k);
      }
    SEFLEX_PETSC(MatDenseRestoreArrayWrite(rhs.get(), &a));
    SEFLEX_PETSC(MatDuplicate(rhs.get(), MAT_DO_NOT_COPY_VALUES, x.out()));
    SEFLEX_PETSC(MatMatSolve(F.get(), rhs.get(), x.get()));
    const PetscScalar* xa = nullptr;
    PetscInt xlda = 0;
    SEFLEX_PETSC(MatDenseGetLDA(x.get(), &xlda));
    SEFLEX_PETSC(MatDenseGetArrayRead(x.get(), &xa));
    for (Eigen::Index k = 0; k < nb; ++k)
      for (Eigen::Index q = 0; q < local_i; ++q) Psi_local(interior_p[static_cast<std::size_t>(q)] - lo, k) = xa[k * xlda + q];
    for (Eigen::Index k = 0; k < nl; ++k)
      for (Eigen::Index q = 0; q < local_i; ++q) Y_local(interior_p[static_cast<std::size_t>(q)] - lo, k) = xa[(nb + k) * xlda + q];
    SEFLEX_PETSC(MatDenseRestoreArrayRead(x.get(), &xa));
    linalg::FactorizationStats& fs = cb.stats.interior_factorization;
    fs.rows = ni;
    fs.factor_nonzeros = detail::mumps_factor_nonzeros(F.get());
    fs.symbolic_analyses = fs.numeric_factorizations = fs.solve_calls = 1;
    fs.solve_columns = nb + nl;
    fs.seconds_symbolic = std::chrono::duration<double>(t1 - t0).count();
    fs.seconds_numeric = std::chrono::duration<double>(t2 - t1).count();
    fs.seconds_solve = std::chrono::duration<double>(Clock::now() - t2).count();
    F.reset();
  }

  // Fixed-interface modes of (K_ii, M_ii): SLEPc, as reduction::craig_bampton's solve_eigenproblem path.
  Eigen::MatrixXd X_sub(ni, 0);  // rows: the interior block's numbering (interior_p of rank 0, then rank 1, ...)
  Eigen::VectorXd lambda(0);
  const std::optional<double> lambda_max =
      options.fmax_hz ? std::optional<double>(std::pow(2.0 * 3.14159265358979323846 * *options.fmax_hz, 2)) : std::nullopt;
  if (ni > 0 && !(options.modes && *options.modes == 0)) {
    linalg::EigenOptions eo;
    auto solve = [&](std::optional<int> count, std::optional<double> limit) {
      eo.count = count;
      eo.lambda_max = limit;
      linalg::EigenSolution s = detail::solve_pencil(K_ii.get(), M_ii.get(), eo);
      cb.stats.eigen = s.stats;
      ++cb.stats.eigen_solutions;
      return s;
    };
    linalg::EigenSolution sol;
    if (options.modes) {
      sol = solve(static_cast<int>(std::min<Eigen::Index>(*options.modes + options.extra_modes, ni)), std::nullopt);
    } else {
      sol = solve(std::nullopt, lambda_max);
      const auto below = sol.eigenvalues.size();
      if (options.extra_modes > 0 && below < ni)
        sol = solve(static_cast<int>(std::min<Eigen::Index>(below + options.extra_modes, ni)), std::nullopt);
    }
    X_sub = std::move(sol.vectors);
    lambda = std::move(sol.eigenvalues);
  }
  Eigen::Index m = 0;
  if (options.modes) m = std::min<Eigen::Index>(*options.modes, lambda.size());
  else
    while (m < lambda.size() && lambda(m) <= *lambda_max) ++m;
  cb.eigenvalues = lambda.head(m);
  cb.neglected_eigenvalues = lambda.tail(lambda.size() - m);
  // This rank's rows of Phi: its interior rows are a contiguous run of the block's numbering.
  Eigen::Index first_sub = 0;
  {
    long mine = static_cast<long>(local_i), before = 0;
    SEFLEX_DEMAND(MPI_Exscan(&mine, &before, 1, MPI_LONG, MPI_SUM, PETSC_COMM_WORLD) == MPI_SUCCESS, "MPI_Exscan failed");
    int rank = 0;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    first_sub = rank == 0 ? 0 : static_cast<Eigen::Index>(before);
  }
  Eigen::MatrixXd Phi_local = Eigen::MatrixXd::Zero(local, m);
  if (m > 0)
    for (Eigen::Index q = 0; q < local_i; ++q)
      Phi_local.row(interior_p[static_cast<std::size_t>(q)] - lo) = X_sub.row(first_sub + q).head(m);

  // Reduced matrices from each rank's rows, summed.
  const Eigen::MatrixXd KPsi = local_product(K, Psi_local), MPsi = local_product(M, Psi_local);
  Eigen::MatrixXd Kbb = Psi_local.transpose() * KPsi, Mbb = Psi_local.transpose() * MPsi,
                  Mqb = Phi_local.transpose() * MPsi;
  allreduce_sum(Kbb);
  allreduce_sum(Mbb);
  allreduce_sum(Mqb);
  const Eigen::Index nr = nb + m;
  cb.K = Eigen::MatrixXd::Zero(nr, nr);
  cb.M = Eigen::MatrixXd::Zero(nr, nr);
  cb.K.topLeftCorner(nb, nb) = 0.5 * (Kbb + Kbb.transpose());
  cb.K.diagonal().tail(m) = cb.eigenvalues;
  cb.M.topLeftCorner(nb, nb) = 0.5 * (Mbb + Mbb.transpose());
  if (m > 0) {
    cb.M.bottomLeftCorner(m, nb) = Mqb;
    cb.M.topRightCorner(nb, m) = Mqb.transpose();
    cb.M.bottomRightCorner(m, m).setIdentity();
  }

  // Psi, Phi and the static responses gathered, rows in the f-set order.
  const Eigen::MatrixXd Psi_p = gather_rows(Psi_local, n), Phi_p = gather_rows(Phi_local, n);
  const Eigen::MatrixXd Y_p = nl > 0 ? gather_rows(Y_local, n) : Eigen::MatrixXd(n, 0);
  cb.Psi.resize(n, nb);
  cb.Phi.resize(n, m);
  cb.static_responses.resize(nl > 0 ? n : 0, nl);
  for (Eigen::Index p = 0; p < n; ++p) {
    const Eigen::Index f = system.p_to_f[static_cast<std::size_t>(p)];
    cb.Psi.row(f) = Psi_p.row(p);
    if (m > 0) cb.Phi.row(f) = Phi_p.row(p);
    if (nl > 0) cb.static_responses.row(f) = Y_p.row(p);
  }
  return cb;
}

}  // namespace seflex::parallel
