#pragma once
// The Newton iteration matrix of FFRF-LM, [s (K T + gamma/(beta h) C + beta' M) + dG^T mu/dq T, G^T; G T, 0]
// (ffrf_integrator.cpp), factorised from its triplets. Up to Data::kDenseDofs unknowns (the demo's
// arrays: 101 coordinates + 30 multipliers) a dense LU with partial pivoting, sized once and then
// free of heap allocation, as the AIC integrator's (Data::factorize); above, the sparse LU with
// its pattern analysed once (it allocates per factorisation). Duplicate triplets are summed in their
// order, as Eigen's setFromTriplets sums them.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <vector>

namespace seflex::mbd::detail {

class FfrfIterationMatrix {
 public:
  using Triplets = std::vector<Eigen::Triplet<double>>;
  /// Factorise the n x n matrix of T. False when it is singular (dense: a zero or non-finite pivot;
  /// sparse: the LU fails even after a fresh pattern analysis).
  bool factorize(const Triplets& T, int n);
  /// x = -A^-1 r with the last factorisation (x resized only when its size differs).
  void solve_negated(const Eigen::VectorXd& r, Eigen::VectorXd& x) const;
  /// The last factorised matrix, dense (for condition estimates).
  Eigen::MatrixXd matrix() const;
  bool dense() const { return dense_path_; }

 private:
  bool dense_path_ = true;
  Eigen::MatrixXd dense_;
  Eigen::PartialPivLU<Eigen::MatrixXd> dense_lu_;
  Eigen::SparseMatrix<double> sparse_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
  bool analyzed_ = false;
};

}  // namespace seflex::mbd::detail
