// Distributed shift-invert Krylov-Schur on SLEPc with a MUMPS factor (slepc_eigensolver.hpp).
#include "seflex/parallel/slepc_eigensolver.hpp"

#include <slepceps.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <vector>

#include "petsc_support.hpp"
#include "slepc_pencil.hpp"
#include "seflex/common/error.hpp"

namespace seflex::parallel {
namespace {

using linalg::SparseMatrixd;
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// First sigma = -kDefaultShiftFactor * median(K_ii / M_ii): larger than the serial backends' 1e-12 (they
// calibrate with a block probe first), small enough for the wanted modes of the usual models to stay
// well separated in theta, and recalibrated below when zero modes show up.
constexpr double kDefaultShiftFactor = 1e-6;
constexpr PetscInt kRangeBatch = 20;           // pairs per run when only a frequency bound limits the count
constexpr double kInfiniteRatio = 1e6;         // lambda above this times max(K_jj / M_jj): a massless direction
constexpr int kCalibrationPasses = 3;          // solutions at most, with the recalibrated shifts
constexpr double kZeroModeGap = 1e-7;          // eigenvalues below this fraction of the largest found are "zero"
constexpr double kShiftFraction = 1e-3;        // recalibrated sigma = -kShiftFraction * lowest nonzero eigenvalue
constexpr double kShiftRecalibration = 10;     // recalibrate only when that moves sigma by more than this factor

using OwnedEps = detail::Owned<EPS, EPSDestroy>;

/// K_jj / M_jj of every dof with mass and stiffness, gathered from all ranks (any order).
std::vector<double> diagonal_ratios(Mat K, Mat M) {
  detail::OwnedVec dk, dm;
  SEFLEX_PETSC(MatCreateVecs(K, dk.out(), nullptr));
  SEFLEX_PETSC(MatCreateVecs(K, dm.out(), nullptr));
  SEFLEX_PETSC(MatGetDiagonal(K, dk.get()));
  SEFLEX_PETSC(MatGetDiagonal(M, dm.get()));
  PetscInt local = 0;
  SEFLEX_PETSC(VecGetLocalSize(dk.get(), &local));
  const PetscScalar *k = nullptr, *m = nullptr;
  SEFLEX_PETSC(VecGetArrayRead(dk.get(), &k));
  SEFLEX_PETSC(VecGetArrayRead(dm.get(), &m));
  std::vector<double> mine;
  for (PetscInt i = 0; i < local; ++i)
    if (m[i] > 0 && k[i] > 0) mine.push_back(k[i] / m[i]);
  SEFLEX_PETSC(VecRestoreArrayRead(dk.get(), &k));
  SEFLEX_PETSC(VecRestoreArrayRead(dm.get(), &m));
  int size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  std::vector<int> counts(static_cast<std::size_t>(size)), displs(static_cast<std::size_t>(size), 0);
  const int mine_count = static_cast<int>(mine.size());
  SEFLEX_DEMAND(MPI_Allgather(&mine_count, 1, MPI_INT, counts.data(), 1, MPI_INT, PETSC_COMM_WORLD) == MPI_SUCCESS,
                "MPI_Allgather failed");
  std::partial_sum(counts.begin(), counts.end() - 1, displs.begin() + 1);
  std::vector<double> all(static_cast<std::size_t>(displs.back() + counts.back()));
  SEFLEX_DEMAND(MPI_Allgatherv(mine.data(), mine_count, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                               MPI_DOUBLE, PETSC_COMM_WORLD) == MPI_SUCCESS,
                "MPI_Allgatherv failed");
  return all;
}

double default_shift(std::vector<double> ratio) {
  if (ratio.empty()) return -1.0;
  std::nth_element(ratio.begin(), ratio.begin() + static_cast<std::ptrdiff_t>(ratio.size() / 2), ratio.end());
  return -kDefaultShiftFactor * ratio[ratio.size() / 2];
}

double one_norm(Mat A) {
  PetscReal v = 0;
  SEFLEX_PETSC(MatNorm(A, NORM_1, &v));
  return v;
}

void allreduce_sum(double* data, int count) {
  SEFLEX_DEMAND(MPI_Allreduce(MPI_IN_PLACE, data, count, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD) == MPI_SUCCESS,
                "MPI_Allreduce failed");
}

/// One shift-invert Krylov-Schur solution at sigma on the distributed K and M (K's pattern holds M's).
linalg::EigenSolution solve_shifted(Mat K, Mat Mp, double sigma, double lambda_infinite,
                                       const linalg::EigenOptions& options) {
  PetscInt n = 0;
  SEFLEX_PETSC(MatGetSize(K, &n, nullptr));
  linalg::EigenSolution solution;
  linalg::EigenStats& stats = solution.stats;
  stats.backend_used = linalg::EigenBackend::Slepc;
  stats.shift = sigma;

  // A = K - sigma M (positive definite) and M, distributed by rows; M x = theta A x, theta = 1/(lambda - sigma).
  const auto t0 = Clock::now();
  detail::OwnedMat A;
  SEFLEX_PETSC(MatDuplicate(K, MAT_COPY_VALUES, A.out()));
  SEFLEX_PETSC(MatAXPY(A.get(), -sigma, Mp, SUBSET_NONZERO_PATTERN));
  SEFLEX_PETSC(MatSetOption(A.get(), MAT_SPD, PETSC_TRUE));
  OwnedEps eps;
  SEFLEX_PETSC(EPSCreate(PETSC_COMM_WORLD, eps.out()));
  SEFLEX_PETSC(EPSSetOperators(eps.get(), Mp, A.get()));
  SEFLEX_PETSC(EPSSetProblemType(eps.get(), EPS_GHEP));
  SEFLEX_PETSC(EPSSetType(eps.get(), EPSKRYLOVSCHUR));
  SEFLEX_PETSC(EPSSetWhichEigenpairs(eps.get(), EPS_LARGEST_REAL));
  SEFLEX_PETSC(EPSSetTolerances(eps.get(), options.tolerance, options.max_restarts));
  ST st = nullptr;
  KSP ksp = nullptr;
  PC pc = nullptr;
  SEFLEX_PETSC(EPSGetST(eps.get(), &st));
  SEFLEX_PETSC(STSetType(st, STSHIFT));  // shift 0 on (M, A): the operator is A^-1 M, applied by the factor of A
  SEFLEX_PETSC(STGetKSP(st, &ksp));
  SEFLEX_PETSC(KSPSetType(ksp, KSPPREONLY));
  SEFLEX_PETSC(KSPGetPC(ksp, &pc));
  SEFLEX_PETSC(PCSetType(pc, PCCHOLESKY));
  SEFLEX_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  SEFLEX_PETSC(EPSSetFromOptions(eps.get()));  // PETSC_OPTIONS may tune it (e.g. -mat_mumps_icntl_14)

  const PetscInt want = options.count ? static_cast<PetscInt>(*options.count) : 0;
  PetscInt nev = std::min<PetscInt>(n, options.count ? want : kRangeBatch);
  std::vector<double> theta;
  std::vector<PetscInt> index;
  bool factorised = false;
  while (true) {
    const PetscInt ncv = std::min<PetscInt>(n, std::max<PetscInt>(2 * nev, nev + 15));
    SEFLEX_PETSC(EPSSetDimensions(eps.get(), nev, ncv, PETSC_DEFAULT));
    if (!factorised) {
      const auto ts = Clock::now();
      SEFLEX_PETSC(EPSSetUp(eps.get()));
      Mat F = nullptr;
      SEFLEX_PETSC(PCFactorGetMatrix(pc, &F));
      detail::throw_if_factor_failed(F, "normal modes: K - sigma M");
      stats.factorization.rows = n;
      stats.factorization.factor_nonzeros = detail::mumps_factor_nonzeros(F);
      stats.factorization.numeric_factorizations = stats.factorizations = 1;
      stats.seconds_factorization = seconds_since(ts) + std::chrono::duration<double>(ts - t0).count();
      factorised = true;
    }
    const auto ts = Clock::now();
    const PetscErrorCode ierr = EPSSolve(eps.get());
    if (ierr != 0) {  // a failed factorisation surfaces here when EPSSetUp deferred it
      Mat F = nullptr;
      if (PCFactorGetMatrix(pc, &F) == 0 && F != nullptr) detail::throw_if_factor_failed(F, "normal modes: K - sigma M");
      detail::check(ierr, "EPSSolve");
    }
    stats.seconds_lanczos += seconds_since(ts);
    ++stats.lanczos_runs;
    PetscInt nconv = 0;
    SEFLEX_PETSC(EPSGetConverged(eps.get(), &nconv));
    if (nconv < nev) {
      PetscInt its = 0;
      SEFLEX_PETSC(EPSGetIterationNumber(eps.get(), &its));
      throw ConvergenceError("normal modes (SLEPc Krylov-Schur, distributed): " + std::to_string(nconv) + " of " +
                             std::to_string(nev) + " eigenpairs converged after " + std::to_string(its) +
                             " restarts (tolerance " + std::to_string(options.tolerance) + ")");
    }
    theta.assign(static_cast<std::size_t>(nconv), 0.0);
    for (PetscInt i = 0; i < nconv; ++i) SEFLEX_PETSC(EPSGetEigenvalue(eps.get(), i, &theta[static_cast<std::size_t>(i)], nullptr));
    // Finite eigenvalues, ascending lambda (= descending theta), within [lambda_min, lambda_max].
    index.clear();
    std::vector<PetscInt> order(static_cast<std::size_t>(nconv));
    std::iota(order.begin(), order.end(), PetscInt{0});
    std::sort(order.begin(), order.end(), [&](PetscInt a, PetscInt b) { return theta[static_cast<std::size_t>(a)] > theta[static_cast<std::size_t>(b)]; });
    bool infinite_seen = false, above_seen = false;
    for (PetscInt i : order) {
      const double t = theta[static_cast<std::size_t>(i)];
      const double lambda = sigma + 1.0 / t;
      if (!(t > 0) || (lambda_infinite > 0 && lambda > lambda_infinite)) {
        infinite_seen = true;
        continue;
      }
      if (options.lambda_max && lambda > *options.lambda_max) {
        above_seen = true;
        continue;
      }
      if (options.lambda_min && lambda < *options.lambda_min) continue;
      if (options.count && static_cast<PetscInt>(index.size()) == want) continue;
      index.push_back(i);
    }
    const bool all = nconv >= n || infinite_seen;  // nothing finite left beyond the converged pairs
    if (all || above_seen || (options.count && static_cast<PetscInt>(index.size()) == want)) break;
    nev = std::min<PetscInt>(n, 2 * nev);
  }

  // Gather the vectors onto every rank, lambda from theta.
  const auto tp = Clock::now();
  const auto m = static_cast<Eigen::Index>(index.size());
  solution.eigenvalues.resize(m);
  solution.vectors.resize(n, m);
  if (m > 0) {
    detail::OwnedVec x;
    SEFLEX_PETSC(MatCreateVecs(A.get(), x.out(), nullptr));
    PetscInt begin = 0, end = 0;
    SEFLEX_PETSC(VecGetOwnershipRange(x.get(), &begin, &end));
    const PetscInt* ranges = nullptr;
    SEFLEX_PETSC(VecGetOwnershipRanges(x.get(), &ranges));
    const PetscInt local = end - begin;
    std::vector<double> block(static_cast<std::size_t>(local * m));
    for (Eigen::Index k = 0; k < m; ++k) {
      PetscScalar t = 0;
      SEFLEX_PETSC(EPSGetEigenpair(eps.get(), index[static_cast<std::size_t>(k)], &t, nullptr, x.get(), nullptr));
      solution.eigenvalues(k) = sigma + 1.0 / t;
      const PetscScalar* v = nullptr;
      SEFLEX_PETSC(VecGetArrayRead(x.get(), &v));
      std::copy_n(v, local, block.begin() + k * local);
      SEFLEX_PETSC(VecRestoreArrayRead(x.get(), &v));
    }
    detail::allgather_rows(ranges, block.data(), local, solution.vectors);
  }
  PetscInt solves = 0;
  SEFLEX_PETSC(KSPGetTotalIterations(ksp, &solves));
  stats.operator_applications = solves;
  stats.factorization.solve_columns = solves;

  // Rayleigh-Ritz on (K, M) in the span of the converged vectors (they come A-orthonormal, A = K - sigma M):
  // G = X^T M X, H = X^T K X, H c = lambda G c; X <- X C is M-orthonormal and lambda accurate to the
  // square of the vectors' error. Zero eigenvalues keep sigma + 1/theta (exact to ~1e-16 |sigma|; the
  // Rayleigh quotient only gives eps ||K||).
  Eigen::MatrixXd& X = solution.vectors;
  if (m > 0) {
    // X^T K X and X^T M X from the distributed products of this rank's rows, summed over the ranks.
    detail::OwnedVec x, y;
    SEFLEX_PETSC(MatCreateVecs(K, x.out(), y.out()));
    PetscInt begin = 0, end = 0;
    SEFLEX_PETSC(VecGetOwnershipRange(x.get(), &begin, &end));
    const Eigen::Index local = end - begin;
    Eigen::MatrixXd KX(local, m), MX(local, m);
    for (Eigen::Index k = 0; k < m; ++k) {
      PetscScalar* v = nullptr;
      SEFLEX_PETSC(VecGetArrayWrite(x.get(), &v));
      Eigen::Map<Eigen::VectorXd>(v, local) = X.col(k).segment(begin, local);
      SEFLEX_PETSC(VecRestoreArrayWrite(x.get(), &v));
      for (auto [A_, out] : {std::pair<Mat, Eigen::MatrixXd*>{K, &KX}, {Mp, &MX}}) {
        SEFLEX_PETSC(MatMult(A_, x.get(), y.get()));
        const PetscScalar* w = nullptr;
        SEFLEX_PETSC(VecGetArrayRead(y.get(), &w));
        out->col(k) = Eigen::Map<const Eigen::VectorXd>(w, local);
        SEFLEX_PETSC(VecRestoreArrayRead(y.get(), &w));
      }
    }
    Eigen::MatrixXd G = X.middleRows(begin, local).transpose() * MX, H = X.middleRows(begin, local).transpose() * KX;
    allreduce_sum(G.data(), static_cast<int>(G.size()));
    allreduce_sum(H.data(), static_cast<int>(H.size()));
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> rr(0.5 * (H + H.transpose()), 0.5 * (G + G.transpose()));
    if (rr.info() != Eigen::Success)
      throw ConvergenceError("normal modes (SLEPc, distributed): the converged eigenvectors are not independent in the "
                             "mass inner product");
    const Eigen::MatrixXd& C = rr.eigenvectors();
    X = X * C;
    const Eigen::VectorXd theta_lambda = solution.eigenvalues;  // sigma + 1/theta, ascending
    const double top = theta_lambda.cwiseAbs().maxCoeff();
    for (Eigen::Index k = 0; k < m; ++k)
      solution.eigenvalues(k) = std::abs(theta_lambda(k)) < kZeroModeGap * top ? theta_lambda(k) : rr.eigenvalues()(k);
    // Backward errors as the serial backends report them.
    const double nk = one_norm(K), nm = one_norm(Mp);
    const Eigen::MatrixXd R = KX * C - (MX * C) * solution.eigenvalues.asDiagonal();
    Eigen::VectorXd r2 = R.colwise().squaredNorm().transpose();
    allreduce_sum(r2.data(), static_cast<int>(r2.size()));
    solution.backward_errors.resize(m);
    for (Eigen::Index k = 0; k < m; ++k)
      solution.backward_errors(k) = std::sqrt(r2(k)) / ((nk + std::abs(solution.eigenvalues(k)) * nm) *
                                                         std::max(X.col(k).norm(), 1e-300));
  }
  stats.seconds_postprocess = seconds_since(tp);
  return solution;
}

}  // namespace

namespace detail {

linalg::EigenSolution solve_pencil(Mat K, Mat M, const linalg::EigenOptions& options) {
  const std::vector<double> ratios = diagonal_ratios(K, M);
  const double lambda_infinite = kInfiniteRatio * (ratios.empty() ? 0.0 : *std::max_element(ratios.begin(), ratios.end()));
  const double sigma = options.shift ? *options.shift : default_shift(ratios);
  linalg::EigenSolution s = solve_shifted(K, M, sigma, lambda_infinite, options);
  if (options.shift) return s;
  // Zero eigenvalues (free-free, mechanisms with mass) with a tiny sigma leave K - sigma M nearly
  // singular: the zero modes come poorly M-orthogonal and the others inaccurate. Solve again at a
  // shift scaled by the lowest nonzero eigenvalue found, as the serial backends calibrate theirs
  // (eigensolver.hpp), until the shift settles.
  linalg::EigenStats spent;
  for (int pass = 1; pass < kCalibrationPasses; ++pass) {
    const Eigen::VectorXd& lambda = s.eigenvalues;
    if (lambda.size() == 0) break;
    const double top = lambda.cwiseAbs().maxCoeff();
    if (!(top > 0) || !(std::abs(lambda(0)) < kZeroModeGap * top)) break;
    Eigen::Index nz = 0;
    while (nz < lambda.size() && lambda(nz) < kZeroModeGap * top) ++nz;
    if (nz == lambda.size()) break;
    const double better = -kShiftFraction * lambda(nz);
    if (!(better < kShiftRecalibration * s.stats.shift)) break;  // sigma is already of that order
    spent.seconds_calibration += s.stats.seconds_factorization + s.stats.seconds_lanczos + s.stats.seconds_postprocess;
    spent.factorizations += s.stats.factorizations;
    spent.lanczos_runs += s.stats.lanczos_runs;
    spent.operator_applications += s.stats.operator_applications;
    s = solve_shifted(K, M, better, lambda_infinite, options);
  }
  s.stats.seconds_calibration += spent.seconds_calibration;
  s.stats.factorizations += spent.factorizations;
  s.stats.lanczos_runs += spent.lanczos_runs;
  s.stats.operator_applications += spent.operator_applications;
  return s;
}

}  // namespace detail

linalg::EigenSolution slepc_eigenproblem(const SparseMatrixd& K, const SparseMatrixd& M,
                                            const linalg::EigenOptions& options) {
  SEFLEX_DEMAND(K.rows() == K.cols() && M.rows() == M.cols() && K.rows() == M.rows(),
                "eigenproblem: K and M must be square and of the same size");
  SEFLEX_DEMAND(options.count.has_value() || options.lambda_max.has_value(),
                "eigenproblem: give a mode count or an upper frequency bound");
  SEFLEX_DEMAND(!options.count || *options.count >= 0, "eigenproblem: negative mode count");
  if (K.rows() == 0 || (options.count && *options.count == 0)) {
    linalg::EigenSolution empty;
    empty.stats.backend_used = linalg::EigenBackend::Slepc;
    empty.eigenvalues.resize(0);
    empty.vectors.resize(K.rows(), 0);
    empty.backward_errors.resize(0);
    return empty;
  }
  // compressed inputs as they are (no replicated copy); others compressed into copies
  SparseMatrixd Kcopy, Mcopy;
  if (!K.isCompressed()) (Kcopy = K).makeCompressed();
  if (!M.isCompressed()) (Mcopy = M).makeCompressed();
  const SparseMatrixd& Kc = K.isCompressed() ? K : Kcopy;
  const SparseMatrixd& Mc = M.isCompressed() ? M : Mcopy;
  detail::OwnedMat Kp, Mp;
  detail::make_upper_sbaij(Kc, &Mc, 0.0, Kp.out());  // K with M's pattern too (K - sigma M in place)
  detail::make_upper_sbaij(Mc, nullptr, 0.0, Mp.out());
  return detail::solve_pencil(Kp.get(), Mp.get(), options);
}

linalg::EigenSolution slepc_eigenproblem_partitioned(const PartitionedSystem& system, const linalg::EigenOptions& options) {
  SEFLEX_DEMAND(options.count.has_value() || options.lambda_max.has_value(),
                "eigenproblem: give a mode count or an upper frequency bound");
  SEFLEX_DEMAND(!options.count || *options.count >= 0, "eigenproblem: negative mode count");
  const Eigen::Index n = system.n_free();
  if (n == 0 || (options.count && *options.count == 0)) {
    linalg::EigenSolution empty;
    empty.stats.backend_used = linalg::EigenBackend::Slepc;
    empty.eigenvalues.resize(0);
    empty.vectors.resize(n, 0);
    empty.backward_errors.resize(0);
    return empty;
  }
  linalg::EigenSolution s = detail::solve_pencil(system.pencil().K.get(), system.pencil().M.get(), options);
  Eigen::MatrixXd f(n, s.vectors.cols());  // rows from the partition numbering back to the f-set's
  for (Eigen::Index p = 0; p < n; ++p) f.row(system.p_to_f[static_cast<std::size_t>(p)]) = s.vectors.row(p);
  s.vectors = std::move(f);
  return s;
}

}  // namespace seflex::parallel
