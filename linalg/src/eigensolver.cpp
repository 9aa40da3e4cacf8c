// Driver of the generalised eigensolution: shift, factorisation, Krylov runs with deflation and the
// completeness check, final Rayleigh-Ritz in the transformed space (eigensolver.hpp).
#include "seflex/linalg/eigensolver.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "seflex/linalg/block_lanczos.hpp"
#include "seflex/linalg/matrix_norms.hpp"
#include "shift_invert.hpp"

namespace seflex::linalg {

std::string_view to_string(EigenBackend backend) {
  switch (backend) {
    case EigenBackend::Spectra: return "spectra";
    case EigenBackend::Arpack: return "arpack";
    case EigenBackend::Dense: return "dense";
    case EigenBackend::Block: return "block";
    case EigenBackend::Slepc: return "slepc";
  }
  return "?";
}

std::optional<EigenBackend> parse_eigen_backend(std::string_view name) {
  if (name == "spectra") return EigenBackend::Spectra;
  if (name == "arpack") return EigenBackend::Arpack;
  if (name == "dense") return EigenBackend::Dense;
  if (name == "block") return EigenBackend::Block;
  return std::nullopt;
}

std::string_view eigen_backend_names() { return "block, spectra, arpack or dense"; }

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

constexpr double kDefaultShiftFactor = 1e-12;  // sigma = -kDefaultShiftFactor * median(K_ii / M_ii)
constexpr double kShiftRetryFactor = 1e3;
constexpr int kShiftRetries = 2;
constexpr int kProbeSize = 12;                 // block of the shift-calibration probe
constexpr int kProbeIterations = 3;
constexpr double kZeroModeGap = 1e-7;          // probe eigenvalues this far below the probe's top are "zero"
constexpr double kShiftFraction = 1e-3;        // calibrated sigma = -kShiftFraction * lowest nonzero eigenvalue
constexpr double kNearSingularPivot = 1e-8;  // min pivot ratio below which zero modes are suspected
constexpr int kCheckModes = 1;                 // modes sought by each completeness check (the top one)
constexpr int kCheckSubspace = 10;             // and its Krylov subspace
constexpr double kCheckTolerance = 1e-4;       // Lanczos tolerance of the check (detection only)
constexpr int kRangeBatch = 20;
constexpr Eigen::Index kDenseLimit = 1000;       // largest model solved densely without being asked                // modes per run when only a frequency range bounds the count

/// sigma below the spectrum, scaled by the typical stiffness-to-mass ratio of the model.
double default_shift(const SparseMatrixd& K, const SparseMatrixd& M) {
  const Eigen::VectorXd k = K.diagonal(), m = M.diagonal();
  std::vector<double> ratios;
  for (Eigen::Index i = 0; i < k.size(); ++i)
    if (m(i) > 0 && k(i) > 0) ratios.push_back(k(i) / m(i));
  if (ratios.empty()) return -1.0;
  auto mid = ratios.begin() + static_cast<std::ptrdiff_t>(ratios.size() / 2);
  std::nth_element(ratios.begin(), mid, ratios.end());
  return -kDefaultShiftFactor * *mid;
}

/// Lower triangle of K - sigma M without stored zeros (a flat shell's membrane and bending dofs
/// then decouple in the graph, which halves the factor).
SparseMatrixd shifted_lower(const SparseMatrixd& K, const SparseMatrixd& M, double sigma) {
  SparseMatrixd A = SparseMatrixd(K.triangularView<Eigen::Lower>()) - sigma * SparseMatrixd(M.triangularView<Eigen::Lower>());
  A.prune(0.0, 0.0);
  return A;
}

/// Factorise K - sigma M, moving sigma down if the matrix is not positive definite numerically.
void factorize_shifted(SparseFactorization& factor, const SparseMatrixd& K, const SparseMatrixd& M, double& sigma,
                       bool may_move, EigenStats& stats) {
  const auto t0 = Clock::now();
  struct AddTime {
    EigenStats& s;
    Clock::time_point t;
    ~AddTime() { s.seconds_factorization += seconds_since(t); }
  } add_time{stats, t0};
  for (int attempt = 0;; ++attempt) {
    try {
      factor.factorize(shifted_lower(K, M, sigma));
      ++stats.factorizations;
      return;
    } catch (const FactorizationError&) {
      ++stats.factorizations;
      if (!may_move || attempt >= kShiftRetries || sigma >= 0) throw;
      sigma *= kShiftRetryFactor;
    }
  }
}

/// Append the columns of V to X, M-orthogonalised against X and each other (twice, for safety).
void append_orthonormal(Eigen::MatrixXd& X, const Eigen::MatrixXd& V, const SparseMatrixd& M) {
  if (V.cols() == 0) return;
  Eigen::MatrixXd W = V;
  for (int pass = 0; pass < 2; ++pass) {
    if (X.cols() > 0) {
      const Eigen::MatrixXd MW = M.selfadjointView<Eigen::Lower>() * W;
      W.noalias() -= X * (X.transpose() * MW);
    }
    const Eigen::MatrixXd MW = M.selfadjointView<Eigen::Lower>() * W;
    Eigen::MatrixXd G = W.transpose() * MW;
    G = 0.5 * (G + G.transpose()).eval();
    Eigen::LLT<Eigen::MatrixXd> llt(G);
    SEFLEX_DEMAND(llt.info() == Eigen::Success, "eigenvectors are not M-independent");
    llt.matrixU().solveInPlace<Eigen::OnTheRight>(W);  // W <- W L^-T, so that W^T M W = I
  }
  const Eigen::Index k = X.cols();
  X.conservativeResize(V.rows(), k + W.cols());
  X.rightCols(W.cols()) = W;
}

/// M-orthonormal basis of span(W) by modified Gram-Schmidt, twice, dropping columns that are
/// dependent to round-off. Unlike a Gram-matrix (Cholesky) orthonormalisation it keeps directions
/// that are 1e-12 of the others, which a block dominated by zero-eigenvalue modes needs.
Eigen::MatrixXd orthonormal_basis_mgs(const Eigen::MatrixXd& W, const SparseMatrixd& M) {
  Eigen::MatrixXd Q(W.rows(), W.cols());
  Eigen::Index k = 0;
  Eigen::VectorXd Mv(W.rows());
  for (Eigen::Index j = 0; j < W.cols(); ++j) {
    Eigen::VectorXd v = W.col(j);
    Mv.noalias() = M.selfadjointView<Eigen::Lower>() * v;
    const double original = std::sqrt(std::max(0.0, v.dot(Mv)));
    for (int pass = 0; pass < 2; ++pass)
      for (Eigen::Index i = 0; i < k; ++i) {
        Mv.noalias() = M.selfadjointView<Eigen::Lower>() * v;
        v -= Q.col(i).dot(Mv) * Q.col(i);
      }
    Mv.noalias() = M.selfadjointView<Eigen::Lower>() * v;
    const double norm = std::sqrt(std::max(0.0, v.dot(Mv)));
    if (!(norm > 1e-14 * original)) continue;
    Q.col(k++) = v / norm;
  }
  return Q.leftCols(k);
}

/// Size of the largest group of (numerically) equal eigenvalues in an ascending list: neighbours
/// within 1e-6 relative, or within 1e-10 of the largest magnitude (the near-zero rigid-body modes).
Eigen::Index largest_cluster(const Eigen::VectorXd& lambda) {
  if (lambda.size() == 0) return 0;
  const double floor = 1e-10 * lambda.cwiseAbs().maxCoeff();
  Eigen::Index largest = 1, run = 1;
  for (Eigen::Index i = 1; i < lambda.size(); ++i) {
    const double gap = lambda(i) - lambda(i - 1);
    run = gap <= 1e-6 * std::max(std::abs(lambda(i)), std::abs(lambda(i - 1))) + floor ? run + 1 : 1;
    largest = std::max(largest, run);
  }
  return largest;
}

KrylovResult run_krylov(EigenBackend backend, ShiftInvertOperator& op, int nev, int ncv, double tol, int max_restarts,
                        unsigned seed) {
  return backend == EigenBackend::Arpack ? run_arpack(op, nev, ncv, tol, max_restarts, seed)
                                         : run_spectra(op, nev, ncv, tol, max_restarts, seed);
}

/// Krylov subspace size for nev wanted pairs: ARPACK's advice (at least 2 nev), bounded by the
/// dimension available.
int subspace_size(int nev, Eigen::Index available) {
  const Eigen::Index ncv = std::max<Eigen::Index>(2 * nev + 1, nev + 16);
  return static_cast<int>(std::min(ncv, available));
}

/// Rayleigh-Ritz of the pencil on span(X) in the transformed space; returns eigenvalues ascending
/// and purified, M-orthonormal vectors.
void transformed_rayleigh_ritz(SparseFactorization& factor, const SparseMatrixd& M, double sigma, Eigen::MatrixXd& X,
                               Eigen::VectorXd& lambda) {
  const Eigen::MatrixXd MX = M.selfadjointView<Eigen::Lower>() * X;
  Eigen::MatrixXd W = MX;
  factor.solve_in_place(W);  // W = OP X
  Eigen::MatrixXd H = MX.transpose() * W, G = MX.transpose() * X;
  H = 0.5 * (H + H.transpose()).eval();
  G = 0.5 * (G + G.transpose()).eval();
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ritz(H, G);
  SEFLEX_DEMAND(ritz.info() == Eigen::Success, "Rayleigh-Ritz: projected pencil could not be solved");
  const Eigen::Index m = X.cols();
  Eigen::VectorXd theta = ritz.eigenvalues().reverse();  // descending theta = ascending lambda
  Eigen::MatrixXd C = ritz.eigenvectors().rowwise().reverse();
  SEFLEX_DEMAND(m == 0 || theta.minCoeff() > 0, "Rayleigh-Ritz: non-positive theta (sigma above an eigenvalue?)");
  Eigen::MatrixXd Y = W * C;  // OP (X c) = theta (X c) + residual: purified Ritz vectors (times theta)
  for (Eigen::Index i = 0; i < m; ++i) Y.col(i) /= theta(i);
  Eigen::MatrixXd none(X.rows(), 0);
  append_orthonormal(none, Y, M);
  X = std::move(none);
  lambda = (sigma + theta.cwiseInverse().array()).matrix();
}

/// Shift calibration for models with (near-)zero eigenvalues (free-free, mechanisms with mass).
/// With sigma far closer to 0 than the first elastic eigenvalue, theta of the rigid-body modes
/// dwarfs the others and round-off of size eps * theta_max spoils the elastic modes; with sigma too
/// far down, the rigid-body copies no longer dominate enough for single-vector Lanczos to find all
/// of them. A few block inverse iterations with a Rayleigh-Ritz in the original pencil (exact to
/// eps * ||K|| for the zero modes, which is all that is needed to recognise them) estimate the
/// lowest nonzero eigenvalue lambda_e; sigma = -1e-3 lambda_e then keeps the zero modes dominant by
/// a factor 1e3 and the elastic modes within ~1e-12 of full precision. Returns nullopt if the probe
/// finds no zero modes (then the initial tiny shift is already right).
std::optional<double> calibrated_shift(SparseFactorization& factor, const SparseMatrixd& K, const SparseMatrixd& M,
                                       Eigen::Index finite, unsigned seed, EigenStats& stats) {
  const Eigen::Index b = std::min<Eigen::Index>({kProbeSize, finite - 1, K.rows() - 1});
  if (b < 2) return std::nullopt;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd X(K.rows(), b);
  for (Eigen::Index j = 0; j < b; ++j)
    for (Eigen::Index i = 0; i < K.rows(); ++i) X(i, j) = uniform(rng);
  for (int it = 0; it < kProbeIterations; ++it) {
    Eigen::MatrixXd Y = M.selfadjointView<Eigen::Lower>() * X;
    factor.solve_in_place(Y);
    stats.operator_applications += X.cols();
    X = orthonormal_basis_mgs(Y, M);
  }
  if (X.cols() < 2) return std::nullopt;
  const Eigen::MatrixXd Kr = X.transpose() * (K.selfadjointView<Eigen::Lower>() * X);
  const Eigen::MatrixXd Mr = X.transpose() * (M.selfadjointView<Eigen::Lower>() * X);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ritz(0.5 * (Kr + Kr.transpose()), 0.5 * (Mr + Mr.transpose()),
                                                                  Eigen::EigenvaluesOnly);
  if (ritz.info() != Eigen::Success) return std::nullopt;
  const Eigen::VectorXd mu = ritz.eigenvalues();
  const double top = mu(mu.size() - 1);
  if (!(top > 0) || !(mu(0) < kZeroModeGap * top)) return std::nullopt;
  for (Eigen::Index i = 0; i < mu.size(); ++i)
    if (mu(i) >= kZeroModeGap * top) return -kShiftFraction * mu(i);
  return std::nullopt;
}

}  // namespace

EigenSolution solve_eigenproblem(const SparseMatrixd& K, const SparseMatrixd& M, const EigenOptions& options) {
  SEFLEX_DEMAND(K.rows() == K.cols() && M.rows() == M.cols() && K.rows() == M.rows(),
                "eigenproblem: K and M must be square and of the same size");
  SEFLEX_DEMAND(options.count.has_value() || options.lambda_max.has_value(),
                "eigenproblem: give a mode count or an upper frequency bound");
  SEFLEX_DEMAND(!options.count || *options.count >= 0, "eigenproblem: negative mode count");
  if (options.external) return options.external(K, M, options);
  SEFLEX_DEMAND(options.backend != EigenBackend::Slepc,
                "eigenproblem: the slepc backend is parallel/'s; pass it as EigenOptions::external");
  const Eigen::Index n = K.rows();
  EigenSolution solution;
  solution.eigenvalues.resize(0);
  solution.vectors.resize(n, 0);
  solution.backward_errors.resize(0);
  EigenStats& stats = solution.stats;

  const Eigen::Index finite = detail::mass_rank_bound(M);
  const Eigen::Index wanted = options.count ? std::min<Eigen::Index>(*options.count, finite) : finite;
  if (n == 0 || wanted == 0) return solution;

  double sigma = options.shift ? *options.shift : default_shift(K, M);
  stats.shift = sigma;
  auto factor = make_factorization(options.factorization);
  factorize_shifted(*factor, K, M, sigma, !options.shift, stats);
  // Dense when asked, when small, or when (nearly) all finite eigenpairs are wanted of a model
  // small enough for O(n^3): a Krylov space needs room beyond the wanted pairs.
  const bool dense = options.backend == EigenBackend::Dense || n <= options.dense_below ||
                     (options.count && wanted + 1 >= finite && n <= kDenseLimit);
  // Only a nearly singular K - sigma M (tiny pivots: zero-eigenvalue modes) needs the calibration.
  if (!options.shift && factor->stats().min_pivot_ratio < kNearSingularPivot) {
    const auto t0 = Clock::now();
    const auto better = calibrated_shift(*factor, K, M, finite, 4242u, stats);
    stats.seconds_calibration = seconds_since(t0);
    if (better && *better < sigma) {
      sigma = *better;
      factorize_shifted(*factor, K, M, sigma, true, stats);
    }
  }
  stats.shift = sigma;

  // Modes below lambda_min are computed too (extraction starts at the bottom of the spectrum).
  const double lambda_hi = options.lambda_max ? *options.lambda_max : std::numeric_limits<double>::infinity();
  auto in_range = [&](double l) {
    return (!options.lambda_min || l >= *options.lambda_min) && l <= lambda_hi;
  };

  Eigen::MatrixXd X(n, 0), Xritz;
  Eigen::VectorXd lambda_ritz;
  bool have_ritz = false;  // Xritz, lambda_ritz hold the Rayleigh-Ritz of the current X
  if (dense) {
    stats.backend_used = EigenBackend::Dense;
    const KrylovResult all = solve_dense(K, M, sigma, static_cast<int>(finite));
    append_orthonormal(X, all.vectors, M);
  } else {
    stats.backend_used = options.backend;
    unsigned seed = 20261121u;
    // Eigenvalues of span(X), ascending (one block solve).
    auto current = [&]() {
      Eigen::VectorXd lambda;
      Eigen::MatrixXd Xc = X;
      transformed_rayleigh_ritz(*factor, M, sigma, Xc, lambda);
      return lambda;
    };
    auto count_in_range = [&](const Eigen::VectorXd& lambda) {
      return static_cast<Eigen::Index>(std::count_if(lambda.data(), lambda.data() + lambda.size(), in_range));
    };
    // Main runs, from the bottom of the spectrum up: until `wanted` modes in range are found, or
    // the top of the range is passed.
    Eigen::Index have = 0;
    const auto t_main = Clock::now();
    // Block Lanczos: one run for a count or an upper bound (falls back to the restarted Lanczos
    // below for a count within a range, or when the basis would exceed its limit).
    bool main_done = false;
    if (options.backend == EigenBackend::Block) {
      stats.backend_used = EigenBackend::Spectra;
      if (!options.lambda_min && options.count.has_value() != options.lambda_max.has_value()) {
        detail::BlockLanczosOptions bo;
        if (options.count) bo.count = wanted;
        else bo.lambda_max = lambda_hi - sigma;
        bo.block = options.block_size;
        bo.tolerance = options.tolerance;
        bo.seed = seed++;
        const long columns = factor->stats().solve_columns;
        auto run = detail::block_lanczos_lowest(*factor, M, bo);
        stats.operator_applications += factor->stats().solve_columns - columns;
        ++stats.lanczos_runs;
        if (run) {
          append_orthonormal(X, run->vectors, M);
          stats.backend_used = EigenBackend::Block;
          main_done = true;
        }
      }
    }
    while (!main_done) {
      const Eigen::Index available = finite - X.cols();
      Eigen::Index batch = options.count ? wanted - have : kRangeBatch;
      batch = std::min(batch, available - 1);
      if (batch <= 0) break;
      ShiftInvertOperator op(*factor, M, X);
      const int nev = static_cast<int>(batch);
      const Eigen::Index room = std::min(available, n - X.cols());
      const int ncv = options.subspace > nev ? static_cast<int>(std::min<Eigen::Index>(options.subspace, room))
                                             : subspace_size(nev, room);
      const KrylovResult run = run_krylov(stats.backend_used, op, nev, ncv, options.tolerance, options.max_restarts, seed++);
      ++stats.lanczos_runs;
      stats.operator_applications += op.applications();
      if (!run.converged || run.vectors.cols() < nev)
        throw ConvergenceError("eigensolver (" + std::string(to_string(stats.backend_used)) + "): " +
                               std::to_string(run.vectors.cols()) + " of " + std::to_string(nev) +
                               " modes converged after " + std::to_string(run.restarts) + " restarts");
      append_orthonormal(X, run.vectors, M);
      if (options.count && !options.lambda_min && !options.lambda_max) break;  // exactly `wanted` found
      const Eigen::VectorXd lambda = current();
      have = count_in_range(lambda);
      if (lambda.maxCoeff() > lambda_hi || (options.count && have >= wanted)) break;
    }
    stats.seconds_lanczos = seconds_since(t_main);
    // Completeness: look for modes below the highest one kept, in the deflated operator. The
    // Rayleigh-Ritz of the last round is the final one when nothing was missed.
    const auto t_check = Clock::now();
    while (options.check_completeness) {
      const Eigen::Index available = std::min(finite, n) - X.cols();
      const int nev = static_cast<int>(std::min<Eigen::Index>(kCheckModes, available - 1));
      if (nev <= 0 || available <= nev + 1) break;
      Xritz = X;
      transformed_rayleigh_ritz(*factor, M, sigma, Xritz, lambda_ritz);
      const Eigen::VectorXd& lambda = lambda_ritz;
      // The highest eigenvalue that will be kept: the wanted-th one in range, or the range's top.
      double threshold = std::min(lambda_hi, lambda.maxCoeff());
      if (options.count) {
        Eigen::Index k = 0;
        for (Eigen::Index i = 0; i < lambda.size(); ++i)
          if (in_range(lambda(i)) && ++k == wanted) {
            threshold = lambda(i);
            break;
          }
      }
      // Block Lanczos from a random block of b vectors finds min(m, b) copies of an eigenvalue of
      // multiplicity m: copies can be missing only behind a cluster of b or more found ones.
      if (stats.backend_used == EigenBackend::Block && largest_cluster(lambda) < options.block_size) {
        have_ritz = true;
        break;
      }
      // Ritz values of the deflated operator are lower bounds of its eigenvalues, so a loose
      // tolerance cannot report a missed mode that is not there; only a detection is re-run to
      // full accuracy.
      auto is_missed = [&](double theta) { return sigma + 1.0 / theta < threshold - 1e-8 * std::abs(threshold); };
      // The dominant eigenpair(s) of the deflated operator, by the backend of the main run.
      auto check_run = [&](double tol) {
        const long columns = factor->stats().solve_columns;
        KrylovResult r;
        if (stats.backend_used == EigenBackend::Block) {
          detail::BlockLanczosOptions bo;
          bo.count = nev;
          bo.block = options.block_size;
          bo.tolerance = tol;
          bo.seed = seed;
          bo.locked = &X;
          if (auto b = detail::block_lanczos_lowest(*factor, M, bo)) {
            r.theta = b->eigenvalues.cwiseInverse();
            r.vectors = std::move(b->vectors);
            r.converged = true;
          }
        } else {
          ShiftInvertOperator op(*factor, M, X);
          const int ncv = static_cast<int>(std::min<Eigen::Index>(kCheckSubspace, available));
          r = run_krylov(stats.backend_used, op, nev, ncv, tol, options.max_restarts, seed);
        }
        stats.operator_applications += factor->stats().solve_columns - columns;
        ++stats.lanczos_runs;
        return r;
      };
      KrylovResult check = check_run(kCheckTolerance);
      if (check.theta.size() > 0 && is_missed(check.theta(0))) check = check_run(options.tolerance);
      ++seed;
      Eigen::MatrixXd missed(n, 0);
      for (Eigen::Index i = 0; i < check.theta.size(); ++i) {
        if (is_missed(check.theta(i))) {
          missed.conservativeResize(n, missed.cols() + 1);
          missed.col(missed.cols() - 1) = check.vectors.col(i);
        }
      }
      if (missed.cols() == 0) {
        have_ritz = true;
        break;
      }
      stats.missed_modes_recovered += static_cast<int>(missed.cols());
      append_orthonormal(X, missed, M);
    }
    stats.seconds_check = seconds_since(t_check);
  }

  // Final Rayleigh-Ritz, selection and backward errors.
  const auto t_post = Clock::now();
  if (have_ritz) {
    X = std::move(Xritz);
  } else {
    transformed_rayleigh_ritz(*factor, M, sigma, X, lambda_ritz);
  }
  const Eigen::VectorXd& lambda = lambda_ritz;
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < lambda.size() && static_cast<Eigen::Index>(keep.size()) < wanted; ++i)
    if (in_range(lambda(i))) keep.push_back(i);
  const auto m = static_cast<Eigen::Index>(keep.size());
  solution.eigenvalues.resize(m);
  solution.vectors.resize(n, m);
  for (Eigen::Index j = 0; j < m; ++j) {
    solution.eigenvalues(j) = lambda(keep[static_cast<std::size_t>(j)]);
    solution.vectors.col(j) = X.col(keep[static_cast<std::size_t>(j)]);
  }
  const Eigen::MatrixXd KX = K.selfadjointView<Eigen::Lower>() * solution.vectors;
  const Eigen::MatrixXd MX = M.selfadjointView<Eigen::Lower>() * solution.vectors;
  const double normK = norm1_symmetric(K), normM = norm1_symmetric(M);
  solution.backward_errors.resize(m);
  for (Eigen::Index j = 0; j < m; ++j) {
    const double l = solution.eigenvalues(j);
    solution.backward_errors(j) = (KX.col(j) - l * MX.col(j)).norm() /
                                  ((normK + std::abs(l) * normM) * solution.vectors.col(j).norm());
  }
  stats.factorization = factor->stats();
  stats.seconds_postprocess = seconds_since(t_post);
  return solution;
}

}  // namespace seflex::linalg
