// Block shift-invert Lanczos (block_lanczos.hpp).
#include "seflex/linalg/block_lanczos.hpp"

#include <cblas.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "blas_threads.hpp"
#include "mass_product.hpp"

namespace seflex::linalg::detail {

namespace {

constexpr double kDropTolerance = 1e-9;  // a column this small after orthogonalisation is dependent
// Cholesky QR is used when no column of the block loses more than this fraction of its M-norm to
// the others (cond(W) ~< 1e4: two passes then give orthogonality to round-off); else Gram-Schmidt.
constexpr double kCholeskyQrLimit = 1e-4;
// Full reorthogonalisation is repeated when it removed more than half of a column's squared M-norm
// (Daniel, Gragg, Kaufman & Stewart 1976: eta = 1/sqrt(2)).
constexpr double kReorthogonalizeAgain = 0.5;

/// BLAS dimension (32-bit: a million-dof basis is far from its limit).
int blas_int(Eigen::Index i) {
  SEFLEX_DEMAND(i >= 0 && i <= std::numeric_limits<int>::max(), "block Lanczos: dimension beyond the BLAS's int");
  return static_cast<int>(i);
}

/// C = A^T B (A n x p, B n x q, column-major, leading dimension n; C p x q with leading dimension ldc).
void gram(const double* A, Eigen::Index p, const double* B, Eigen::Index q, Eigen::Index n, double* C, Eigen::Index ldc) {
  cblas_dgemm(CblasColMajor, CblasTrans, CblasNoTrans, blas_int(p), blas_int(q), blas_int(n), 1.0, A, blas_int(n), B,
              blas_int(n), 0.0, C, blas_int(ldc));
}
Eigen::MatrixXd gram(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  Eigen::MatrixXd C(A.cols(), B.cols());
  gram(A.data(), A.cols(), B.data(), B.cols(), A.rows(), C.data(), C.rows());
  return C;
}
/// Y -= A C (A n x p, C p x q with leading dimension ldc, Y n x q; leading dimension n).
void subtract_product(const double* A, Eigen::Index p, const double* C, Eigen::Index ldc, Eigen::Index n, double* Y,
                      Eigen::Index q) {
  cblas_dgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, blas_int(n), blas_int(q), blas_int(p), -1.0, A, blas_int(n), C,
              blas_int(ldc), 1.0, Y, blas_int(n));
}
void subtract_product(const Eigen::MatrixXd& A, const Eigen::MatrixXd& C, Eigen::MatrixXd& Y) {
  subtract_product(A.data(), A.cols(), C.data(), C.rows(), A.rows(), Y.data(), Y.cols());
}

/// M-orthonormalise the columns of W among themselves (modified Gram-Schmidt, twice, with M Q kept
/// so that every inner product costs no sparse product): W = Q R with R (kept x W.cols()).
/// Columns that are dependent to round-off are dropped.
void orthonormalize_block_mgs(const MassProduct& M, const Eigen::MatrixXd& W, Eigen::MatrixXd& Q, Eigen::MatrixXd& R) {
  const Eigen::Index n = W.rows(), b = W.cols();
  Q.resize(n, b);
  Eigen::MatrixXd MQ(n, b);
  R = Eigen::MatrixXd::Zero(b, b);
  Eigen::Index k = 0;
  for (Eigen::Index j = 0; j < b; ++j) {
    Eigen::VectorXd w = W.col(j);
    Eigen::VectorXd Mw = M(w);
    const double original = std::sqrt(std::max(0.0, w.dot(Mw)));
    for (int pass = 0; pass < 2; ++pass)
      for (Eigen::Index i = 0; i < k; ++i) {
        const double r = Q.col(i).dot(Mw);
        w -= r * Q.col(i);
        Mw -= r * MQ.col(i);
        R(i, j) += r;
      }
    const double norm = std::sqrt(std::max(0.0, w.dot(Mw)));
    if (!(norm > kDropTolerance * original)) continue;
    Q.col(k) = w / norm;
    MQ.col(k) = Mw / norm;
    R(k, j) = norm;
    ++k;
  }
  Q.conservativeResize(n, k);
  R.conservativeResize(k, b);
}

/// The same by Cholesky QR, twice (CholQR2: G = W^T M W = U^T U, W <- W U^-1): two passes of
/// BLAS-3 over the block instead of b^2 vector operations; falls back to Gram-Schmidt for a nearly
/// dependent block.
void orthonormalize_block(const MassProduct& M, const Eigen::MatrixXd& W, Eigen::MatrixXd& Q, Eigen::MatrixXd& R) {
  const Eigen::Index b = W.cols();
  Q = W;
  R = Eigen::MatrixXd::Identity(b, b);
  for (int pass = 0; pass < 2; ++pass) {
    const Eigen::MatrixXd MQ = M(Q);
    Eigen::MatrixXd G = gram(Q, MQ);
    G = 0.5 * (G + G.transpose()).eval();
    const Eigen::LLT<Eigen::MatrixXd> llt(G);
    bool well_conditioned = llt.info() == Eigen::Success;
    const Eigen::MatrixXd U = llt.matrixU();
    for (Eigen::Index j = 0; j < b && well_conditioned; ++j)
      well_conditioned = U(j, j) > kCholeskyQrLimit * std::sqrt(G(j, j));
    if (!well_conditioned) {
      orthonormalize_block_mgs(M, W, Q, R);
      return;
    }
    cblas_dtrsm(CblasColMajor, CblasRight, CblasUpper, CblasNoTrans, CblasNonUnit, blas_int(Q.rows()), blas_int(b), 1.0,
                U.data(), blas_int(b), Q.data(), blas_int(Q.rows()));  // Q <- Q U^-1
    R = (U.triangularView<Eigen::Upper>() * R).eval();
  }
}

/// The Lanczos basis V, stored in column chunks: it grows without copying, and the products with it
/// are a few large matrix products instead of one per block. They go to the BLAS that CHOLMOD uses
/// (OpenBLAS: multithreaded, no packing copy of the tall basis as in Eigen's own product), which is
/// where the reorthogonalisation of a million-dof basis spends its time.
class ChunkedBasis {
 public:
  ChunkedBasis(Eigen::Index rows, Eigen::Index chunk) : rows_(rows), chunk_(chunk) {}
  Eigen::Index cols() const { return cols_; }
  void append(const Eigen::MatrixXd& Q) {
    if (chunks_.empty() || used_.back() + Q.cols() > chunks_.back().cols()) {
      chunks_.emplace_back(rows_, std::max(chunk_, Q.cols()));
      used_.push_back(0);
    }
    chunks_.back().middleCols(used_.back(), Q.cols()) = Q;
    used_.back() += Q.cols();
    cols_ += Q.cols();
  }
  /// V^T Y (cols() x Y.cols()).
  Eigen::MatrixXd transpose_times(const Eigen::MatrixXd& Y) const {
    SEFLEX_DEMAND(Y.rows() == rows_, "block Lanczos: product with a block of the wrong size");
    Eigen::MatrixXd C(cols_, Y.cols());
    Eigen::Index at = 0;
    for (std::size_t c = 0; c < chunks_.size(); at += used_[c], ++c)
      gram(chunks_[c].data(), used_[c], Y.data(), Y.cols(), rows_, C.data() + at, cols_);
    return C;
  }
  /// Y -= V C.
  void subtract_times(const Eigen::MatrixXd& C, Eigen::MatrixXd& Y) const {
    SEFLEX_DEMAND(Y.rows() == rows_ && C.rows() == cols_ && C.cols() == Y.cols(), "block Lanczos: product sizes");
    Eigen::Index at = 0;
    for (std::size_t c = 0; c < chunks_.size(); at += used_[c], ++c)
      subtract_product(chunks_[c].data(), used_[c], C.data() + at, cols_, rows_, Y.data(), Y.cols());
  }
  /// V C.
  Eigen::MatrixXd times(const Eigen::MatrixXd& C) const {
    Eigen::MatrixXd Y = Eigen::MatrixXd::Zero(rows_, C.cols());
    subtract_times(-C, Y);
    return Y;
  }

 private:
  Eigen::Index rows_, chunk_, cols_ = 0;
  std::vector<Eigen::MatrixXd> chunks_;
  std::vector<Eigen::Index> used_;
};

/// W <- W - X (X^T M W): M-orthogonal to the locked vectors (no-op without them).
void deflate(const Eigen::MatrixXd* X, const MassProduct& M, Eigen::MatrixXd& W) {
  if (X == nullptr || X->cols() == 0) return;
  subtract_product(*X, gram(*X, M(W)), W);
}

}  // namespace

Eigen::Index mass_rank_bound(const SparseMatrixd& M) {
  std::vector<char> nz(static_cast<std::size_t>(M.cols()), 0);
  for (Eigen::Index j = 0; j < M.outerSize(); ++j)
    for (SparseMatrixd::InnerIterator it(M, j); it; ++it)
      if (it.value() != 0) nz[static_cast<std::size_t>(j)] = nz[static_cast<std::size_t>(it.row())] = 1;
  return std::count(nz.begin(), nz.end(), 1);
}

std::optional<BlockLanczosResult> block_lanczos_lowest(SparseFactorization& factor, const SparseMatrixd& M,
                                                       const BlockLanczosOptions& o) {
  SEFLEX_DEMAND(o.count.has_value() != o.lambda_max.has_value(), "block Lanczos: give a count or an eigenvalue limit");
  SEFLEX_DEMAND(o.block >= 1 && o.tolerance > 0, "block Lanczos: bad options");
  const Eigen::Index n = M.rows();
  BlockLanczosResult res;
  res.eigenvalues.resize(0);
  res.vectors.resize(n, 0);
  const Eigen::Index locked = o.locked != nullptr ? o.locked->cols() : 0;
  SEFLEX_DEMAND(locked == 0 || o.locked->rows() == n, "block Lanczos: locked vectors have the wrong size");
  const Eigen::Index finite = mass_rank_bound(M) - locked;  // finite eigenvalues left to find
  if (n == 0 || finite <= 0 || (o.count && *o.count <= 0)) return res;

  // Start block OP X0: in range(OP), so massless directions never enter the basis.
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd W(n, std::min(o.block, finite));
  for (Eigen::Index j = 0; j < W.cols(); ++j)
    for (Eigen::Index i = 0; i < n; ++i) W(i, j) = uniform(rng);
  const BlasThreadScope single_thread(1);  // memory-bound products with the basis (blas_threads.hpp)
  const MassProduct mass(M);
  W = mass(W);
  factor.solve_in_place(W);
  ++res.block_solves;
  for (int pass = 0; pass < 2; ++pass) deflate(o.locked, mass, W);

  ChunkedBasis V(n, std::max<Eigen::Index>(4 * o.block, 32));  // basis blocks, M-orthonormal together
  Eigen::MatrixXd T(0, 0);                                     // V^T M OP V
  Eigen::MatrixXd R;
  Eigen::MatrixXd Qnew, Qprev;
  orthonormalize_block(mass, W, Qnew, R);
  Eigen::Index k = 0;
  for (;;) {
    // Append the new block.
    const Eigen::Index bj = Qnew.cols();
    V.append(Qnew);
    k += bj;
    // Next block: OP Q_j; the coefficients of its M-orthogonalisation are column block j of T.
    W = mass(Qnew);
    factor.solve_in_place(W);
    ++res.block_solves;
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(k, bj);
    // The three-term recurrence first (the last two blocks, cheap): it removes nearly all of W's
    // norm, so that one pass of block classical Gram-Schmidt against the whole basis then keeps it
    // M-orthogonal to round-off; a second pass only where that pass removed much (DGKS).
    deflate(o.locked, mass, W);
    {
      const Eigen::MatrixXd MW = mass(W);
      const Eigen::MatrixXd C = gram(Qnew, MW);
      H.bottomRows(bj) += C;
      if (Qprev.cols() > 0) {
        const Eigen::MatrixXd Cprev = gram(Qprev, MW);
        H.middleRows(k - bj - Qprev.cols(), Qprev.cols()) += Cprev;
        subtract_product(Qprev, Cprev, W);
      }
      subtract_product(Qnew, C, W);
    }
    for (int pass = 0; pass < 2; ++pass) {
      if (pass > 0) deflate(o.locked, mass, W);
      const Eigen::MatrixXd MW = mass(W);
      const Eigen::RowVectorXd before = W.cwiseProduct(MW).colwise().sum();
      const Eigen::MatrixXd C = V.transpose_times(MW);
      V.subtract_times(C, W);
      H += C;
      const Eigen::RowVectorXd removed = C.cwiseAbs2().colwise().sum();
      if ((removed.array() <= kReorthogonalizeAgain * before.array()).all()) break;
    }
    Qprev = std::move(Qnew);
    orthonormalize_block(mass, W, Qnew, R);
    T.conservativeResize(k, k);
    T.rightCols(bj) = H;
    T.bottomRows(bj).leftCols(k - bj) = H.topRows(k - bj).transpose();
    const bool exhausted = Qnew.cols() == 0 || k >= finite;

    // Rayleigh-Ritz in the transformed space; residual of pair i: ||R c_i(last block)||.
    const Eigen::MatrixXd Ts = 0.5 * (T + T.transpose());
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Ts);
    SEFLEX_DEMAND(es.info() == Eigen::Success, "block Lanczos: projected eigenproblem failed");
    std::vector<Eigen::Index> order;  // positive theta, descending = lambda ascending
    for (Eigen::Index i = k - 1; i >= 0; --i)
      if (es.eigenvalues()(i) > 0) order.push_back(i);
    Eigen::Index prefix = 0, below = 0;
    for (Eigen::Index i : order) {
      const double theta = es.eigenvalues()(i);
      const double residual = exhausted ? 0.0 : (R * es.eigenvectors().col(i).tail(bj)).norm();
      if (!(residual <= o.tolerance * theta)) break;
      ++prefix;
      if (o.lambda_max && 1.0 / theta <= *o.lambda_max) ++below;
    }
    const auto available = static_cast<Eigen::Index>(order.size());
    Eigen::Index take = -1;
    if (o.count) {
      if (prefix >= *o.count || exhausted) take = std::min<Eigen::Index>(*o.count, exhausted ? available : prefix);
    } else {
      const Eigen::Index need = below + std::max<Eigen::Index>(o.extra, 1);
      if (prefix >= need || exhausted) take = std::min(exhausted ? available : prefix, below + o.extra);
    }
    if (take >= 0) {
      res.basis_size = k;
      res.eigenvalues.resize(take);
      Eigen::MatrixXd C(k, take);
      for (Eigen::Index t = 0; t < take; ++t) {
        const Eigen::Index i = order[static_cast<std::size_t>(t)];
        res.eigenvalues(t) = 1.0 / es.eigenvalues()(i);
        C.col(t) = es.eigenvectors().col(i);
      }
      res.vectors = V.times(C);
      return res;
    }
    if (k + Qnew.cols() > o.max_basis) return std::nullopt;
  }
}

}  // namespace seflex::linalg::detail
