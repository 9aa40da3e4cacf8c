#pragma once
// Factorisation of the Newton iteration matrix with each flexible body's modal coordinates condensed
// first (internal to the implicit integrator). The modal dofs eta_b of body b couple only to the
// dofs of b's clique (its interface nodes and whatever those depend on), so the matrix, ordered
// [retained dofs r; eta_1; ...; eta_B], is an arrowhead:
//   S = [S_rr  S_re ; S_er  diag(S_ee,b)],   S_re,b non-zero only on the columns c_b of b's clique.
// Block elimination (the Schur complement):
//   S^ = S_rr - sum_b S_rc,b S_ee,b^-1 S_cr,b   (a dense LU of the retained dofs only),
//   x_r = S^-1 (r_r - sum_b S_rc,b S_ee,b^-1 r_e,b),   x_e,b = S_ee,b^-1 (r_e,b - S_ec,b x_r).
// On the demo's 3-D array (71 dofs, 3 x 10 modal) the dense LU shrinks to 41 x 41, a quarter of the
// work of the full one. S_ee,b = K_ee + gamma' C_ee + beta' M_ee is dominated by the modal mass and
// is pivoted within its block. Where the pattern is not an arrowhead (e.g. a force element on a
// modal dof) the whole matrix is factorised densely. No allocation after the first factorisation.
// Real (the generalized-alpha and Radau IIA real systems) or complex (Radau IIA's complex system,
// radau5.cpp): CondensedLuT<double>, CondensedLuT<std::complex<double>>.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <complex>
#include <type_traits>
#include <vector>

#include "seflex/mbd/model.hpp"

namespace seflex::mbd::detail {

/// Dense LU with partial pivoting by the squared modulus, unblocked (right-looking rank-1 updates),
/// for the complex systems: Eigen's PartialPivLU compares complex moduli by hypot, and its blocked
/// kernel does not pay at these sizes. On a 41 x 41 complex matrix (the demo's retained dofs) 35
/// against 54-60 us, on the 10 x 10 modal blocks 0.95 against 1.9 us (-O3 -march=x86-64-v3, the
/// 2-core Xeon host, 2026-12-07). Real matrices keep Eigen's (no faster at 41 x 41: 12.2 against
/// 10.6-12.2 us). The same pivots as PartialPivLU wherever the largest modulus is unique.
template <class Scalar>
class SquaredModulusLu {
 public:
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  SquaredModulusLu() = default;
  explicit SquaredModulusLu(Eigen::Index n) : lu_(n, n), rows_(n) {}
  /// L (unit lower) and U of P A = L U in one matrix, as PartialPivLU::matrixLU.
  const Matrix& matrixLU() const { return lu_; }
  void compute(const Matrix& A) {
    lu_ = A;
    const Eigen::Index n = A.rows();
    rows_.resize(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      Eigen::Index p = 0;
      lu_.col(k).tail(n - k).cwiseAbs2().maxCoeff(&p);
      p += k;
      rows_[k] = static_cast<int>(p);
      if (p != k) lu_.row(k).swap(lu_.row(p));
      const Scalar pivot = lu_(k, k);
      if (pivot == Scalar(0)) continue;  // singular: the caller's pivot test (regular) says so
      const Eigen::Index r = n - k - 1;
      lu_.col(k).tail(r) /= pivot;
      lu_.bottomRightCorner(r, r).noalias() -= lu_.col(k).tail(r) * lu_.row(k).tail(r);
    }
  }
  /// X = A^-1 X (a vector or the columns of a matrix).
  template <class Rhs>
  void solve_in_place(Rhs& x) const {
    for (Eigen::Index k = 0; k < lu_.rows(); ++k)
      if (rows_[k] != k) x.row(k).swap(x.row(rows_[k]));
    lu_.template triangularView<Eigen::UnitLower>().solveInPlace(x);
    lu_.template triangularView<Eigen::Upper>().solveInPlace(x);
  }

 private:
  Matrix lu_;
  Eigen::VectorXi rows_;  ///< step k swapped rows k and rows_[k]
};

template <class Scalar>
class CondensedLuT {
 public:
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  using Sparse = Eigen::SparseMatrix<Scalar>;
  using Lu = std::conditional_t<std::is_same_v<Scalar, double>, Eigen::PartialPivLU<Matrix>, SquaredModulusLu<Scalar>>;

  /// Whether S (its pattern; analysed at the first call) condenses to at most `max_dense` retained
  /// dofs: above that the caller's sparse LU is the better choice.
  bool applicable(const Model& model, const Sparse& S, int max_dense) {
    if (!ready_ || static_cast<Eigen::Index>(pos_.size()) != S.rows()) setup(model, S);
    return dense_size() <= max_dense;
  }
  /// Factorise S (on the model's dof numbering; pattern fixed after the first call). False when S
  /// is singular (a zero or non-finite pivot relative to the largest entry, as Data::factorize).
  bool factorize(const Model& model, const Sparse& S);
  /// x = -S^-1 r with the last factorisation.
  void solve_negated(const Vector& r, Vector& x);
  /// Size of the dense factorisation (retained dofs, or all of them without condensation).
  int dense_size() const { return static_cast<int>(Srr_.rows()); }

 private:
  struct Block {
    int first = 0, m = 0;   ///< the body's modal dofs first .. first + m - 1
    std::vector<int> c;     ///< retained positions coupled to them (sorted)
    Matrix See, Sec, Sce, X, T;  ///< X = See^-1 Sec, T = Sce X
    Lu lu;
    Vector y;               ///< See^-1 r_e of a solve
  };
  void setup(const Model& model, const Sparse& S);

  bool ready_ = false;
  std::vector<int> pos_;    ///< per dof: position among the retained dofs, or -1 - block index
  std::vector<int> kept_;   ///< retained dofs in order
  std::vector<Block> blocks_;
  std::vector<Scalar*> dest_;  ///< per stored entry of S (value order): where it goes
  Matrix Srr_;
  Lu lu_;
  Vector rr_, xr_;
};

using CondensedLu = CondensedLuT<double>;
using CondensedLuComplex = CondensedLuT<std::complex<double>>;

}  // namespace seflex::mbd::detail
