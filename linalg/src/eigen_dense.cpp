// Dense backend: the transformed pencil as a symmetric standard problem. With K - sigma M = L L^T,
// K x = lambda M x  <=>  C z = theta z,  C = L^-1 M L^-T,  z = L^T x,  theta = 1/(lambda - sigma).
// C is symmetric positive semi-definite; its zero eigenvalues are the infinite eigenvalues of a
// singular M and are never among the nev largest the caller asks for (nev <= rank bound of M).
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <limits>

#include "shift_invert.hpp"

namespace seflex::linalg {

KrylovResult solve_dense(const SparseMatrixd& K, const SparseMatrixd& M, double sigma, int nev) {
  const Eigen::Index n = K.rows();
  const SparseMatrixd Kf = K.selfadjointView<Eigen::Lower>(), Mf = M.selfadjointView<Eigen::Lower>();
  Eigen::MatrixXd A = Eigen::MatrixXd(Kf) - sigma * Eigen::MatrixXd(Mf);
  Eigen::LLT<Eigen::MatrixXd> llt(A);
  SEFLEX_DEMAND(llt.info() == Eigen::Success, "dense eigensolver: K - sigma M is not positive definite");
  Eigen::MatrixXd C = Eigen::MatrixXd(Mf);
  llt.matrixL().solveInPlace(C);                                // L^-1 M
  C.transposeInPlace();                                        // M L^-T
  llt.matrixL().solveInPlace(C);                                // L^-1 M L^-T
  C = 0.5 * (C + C.transpose()).eval();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(C);
  SEFLEX_DEMAND(eig.info() == Eigen::Success, "dense eigensolver did not converge");
  KrylovResult result;
  // Zero theta (to round-off) are the infinite eigenvalues of a singular M: never returned.
  const double floor = static_cast<double>(n) * std::numeric_limits<double>::epsilon() * eig.eigenvalues().cwiseAbs().maxCoeff();
  Eigen::Index k = 0;
  while (k < std::min<Eigen::Index>(nev, n) && eig.eigenvalues()(n - 1 - k) > floor) ++k;
  result.theta = eig.eigenvalues().tail(k).reverse();
  Eigen::MatrixXd Z = eig.eigenvectors().rightCols(k).rowwise().reverse();
  llt.matrixU().solveInPlace(Z);                                // x = L^-T z
  result.vectors = Z;
  result.converged = true;
  return result;
}

}  // namespace seflex::linalg
