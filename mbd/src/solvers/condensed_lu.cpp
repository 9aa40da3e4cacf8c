// The iteration matrix factorised with the modal coordinates condensed body by body
// (condensed_lu.hpp).
#include "solvers/condensed_lu.hpp"

#include <algorithm>
#include <cmath>

#include "seflex/common/error.hpp"

namespace seflex::mbd::detail {

namespace {

/// The pivot test of Data::factorize: every pivot finite and above 1e-14 of the largest entry
/// (`scale2`: the square of that entry). Squared moduli throughout: a complex modulus by hypot cost
/// 4 % of a Radau IIA-5 run of sync-3d (perf), for the same comparisons.
template <class Lu>
bool regular(const Lu& lu, double scale2) {
  const auto pivots2 = lu.matrixLU().diagonal().cwiseAbs2();
  return pivots2.size() == 0 || (std::isfinite(pivots2.sum()) && pivots2.minCoeff() > 1e-28 * scale2);
}

/// x = A^-1 b with either factorisation (no allocation once x is sized).
template <class Matrix, class Rhs, class X>
void solve_into(const Eigen::PartialPivLU<Matrix>& lu, const Rhs& b, X& x) {
  x = lu.solve(b);
}
template <class Scalar, class Rhs, class X>
void solve_into(const SquaredModulusLu<Scalar>& lu, const Rhs& b, X& x) {
  x = b;
  lu.solve_in_place(x);
}

}  // namespace

template <class Scalar>
void CondensedLuT<Scalar>::setup(const Model& model, const Sparse& S) {
  const int n = static_cast<int>(S.rows());
  pos_.assign(static_cast<std::size_t>(n), 0);
  blocks_.clear();
  for (const auto& b : model.flexible_bodies) {
    const int m = model.superelement(b.se).m;
    if (m <= 0 || b.eta_dof < 0) continue;
    Block blk;
    blk.first = b.eta_dof;
    blk.m = m;
    for (int k = 0; k < m; ++k) pos_[static_cast<std::size_t>(b.eta_dof + k)] = -1 - static_cast<int>(blocks_.size());
    blocks_.push_back(std::move(blk));
  }
  kept_.clear();
  for (int i = 0; i < n; ++i)
    if (pos_[static_cast<std::size_t>(i)] >= 0) {
      pos_[static_cast<std::size_t>(i)] = static_cast<int>(kept_.size());
      kept_.push_back(i);
    }
  // The arrowhead test: no entry couples the modal dofs of two bodies; collect each block's columns.
  bool arrow = !blocks_.empty();
  std::vector<std::vector<char>> coupled(blocks_.size(), std::vector<char>(kept_.size(), 0));
  for (int j = 0; j < S.outerSize() && arrow; ++j)
    for (typename Sparse::InnerIterator it(S, j); it; ++it) {
      const int pi = pos_[static_cast<std::size_t>(it.row())], pj = pos_[static_cast<std::size_t>(j)];
      if (pi < 0 && pj < 0 && pi != pj) {
        arrow = false;
        break;
      }
      if (pi < 0 && pj >= 0) coupled[static_cast<std::size_t>(-1 - pi)][static_cast<std::size_t>(pj)] = 1;
      if (pj < 0 && pi >= 0) coupled[static_cast<std::size_t>(-1 - pj)][static_cast<std::size_t>(pi)] = 1;
    }
  if (!arrow) {  // factorise everything densely
    blocks_.clear();
    kept_.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) pos_[static_cast<std::size_t>(i)] = kept_[static_cast<std::size_t>(i)] = i;
  }
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    Block& blk = blocks_[b];
    for (std::size_t p = 0; p < kept_.size(); ++p)
      if (coupled[b][p]) blk.c.push_back(static_cast<int>(p));
    const auto nc = static_cast<Eigen::Index>(blk.c.size());
    blk.See.setZero(blk.m, blk.m);
    blk.Sec.setZero(blk.m, nc);
    blk.Sce.setZero(nc, blk.m);
    blk.X.setZero(blk.m, nc);
    blk.T.setZero(nc, nc);
    blk.y.setZero(blk.m);
    blk.lu = Lu(blk.m);
  }
  const auto nr = static_cast<Eigen::Index>(kept_.size());
  Srr_.setZero(nr, nr);
  lu_ = Lu(nr);
  rr_.setZero(nr);
  xr_.setZero(nr);
  // Destination of every stored entry (the matrices are sized for good: the pointers stay valid).
  auto local = [](const std::vector<int>& c, int p) {
    return static_cast<Eigen::Index>(std::lower_bound(c.begin(), c.end(), p) - c.begin());
  };
  dest_.clear();
  for (int j = 0; j < S.outerSize(); ++j) {
    const int pj = pos_[static_cast<std::size_t>(j)];
    for (typename Sparse::InnerIterator it(S, j); it; ++it) {
      const int pi = pos_[static_cast<std::size_t>(it.row())];
      if (pi >= 0 && pj >= 0) {
        dest_.push_back(&Srr_(pi, pj));
      } else if (pi < 0 && pj < 0) {
        Block& blk = blocks_[static_cast<std::size_t>(-1 - pi)];
        dest_.push_back(&blk.See(it.row() - blk.first, j - blk.first));
      } else if (pi < 0) {
        Block& blk = blocks_[static_cast<std::size_t>(-1 - pi)];
        dest_.push_back(&blk.Sec(it.row() - blk.first, local(blk.c, pj)));
      } else {
        Block& blk = blocks_[static_cast<std::size_t>(-1 - pj)];
        dest_.push_back(&blk.Sce(local(blk.c, pi), j - blk.first));
      }
    }
  }
  ready_ = true;
}

template <class Scalar>
bool CondensedLuT<Scalar>::factorize(const Model& model, const Sparse& S) {
  if (!ready_ || static_cast<Eigen::Index>(pos_.size()) != S.rows()) setup(model, S);
  SEFLEX_DEMAND(static_cast<std::size_t>(S.nonZeros()) == dest_.size(), "the iteration matrix keeps its pattern");
  Srr_.setZero();
  for (Block& blk : blocks_) {
    blk.See.setZero();
    blk.Sec.setZero();
    blk.Sce.setZero();
  }
  const Scalar* val = S.valuePtr();
  for (std::size_t k = 0; k < dest_.size(); ++k) *dest_[k] = val[k];
  // Apart from the scatter: a running maximum there was kept in memory (the stores through dest_ may
  // alias it), a store-to-load chain per entry.
  const double scale2 = Eigen::Map<const Vector>(val, S.nonZeros()).cwiseAbs2().maxCoeff();
  for (Block& blk : blocks_) {
    blk.lu.compute(blk.See);
    if (!regular(blk.lu, scale2)) return false;
    solve_into(blk.lu, blk.Sec, blk.X);
    blk.T.noalias() = blk.Sce * blk.X;
    const auto nc = static_cast<Eigen::Index>(blk.c.size());
    for (Eigen::Index b = 0; b < nc; ++b)
      for (Eigen::Index a = 0; a < nc; ++a) Srr_(blk.c[static_cast<std::size_t>(a)], blk.c[static_cast<std::size_t>(b)]) -= blk.T(a, b);
  }
  lu_.compute(Srr_);
  return regular(lu_, scale2);
}

template <class Scalar>
void CondensedLuT<Scalar>::solve_negated(const Vector& r, Vector& x) {
  if (x.size() != r.size()) x.resize(r.size());
  for (std::size_t p = 0; p < kept_.size(); ++p) rr_[static_cast<Eigen::Index>(p)] = r[kept_[p]];
  for (Block& blk : blocks_) {
    solve_into(blk.lu, r.segment(blk.first, blk.m), blk.y);
    // (a plain product: dot() would conjugate the row of a complex matrix)
    for (std::size_t a = 0; a < blk.c.size(); ++a) rr_[blk.c[a]] -= blk.Sce.row(static_cast<Eigen::Index>(a)).transpose().cwiseProduct(blk.y).sum();
  }
  solve_into(lu_, rr_, xr_);
  for (std::size_t p = 0; p < kept_.size(); ++p) x[kept_[p]] = -xr_[static_cast<Eigen::Index>(p)];
  for (Block& blk : blocks_) {
    for (std::size_t a = 0; a < blk.c.size(); ++a) blk.y.noalias() -= blk.X.col(static_cast<Eigen::Index>(a)) * xr_[blk.c[a]];
    x.segment(blk.first, blk.m) = -blk.y;
  }
}

template class CondensedLuT<double>;
template class CondensedLuT<std::complex<double>>;

}  // namespace seflex::mbd::detail
