// What the kept fixed-interface modes retain: modal effective mass and frequencies
// (craig_bampton.hpp, truncation_report).
#include <algorithm>
#include <cmath>

#include "seflex/common/error.hpp"
#include "seflex/reduction/craig_bampton.hpp"

namespace seflex::reduction {

namespace {

/// z with (M_ii z)_i = B_i for B_i in the range of M_ii: a Cholesky solve on the interior dofs
/// whose mass diagonal is positive (a psd M has zero rows and columns where its diagonal is zero).
Eigen::MatrixXd solve_interior_mass(const linalg::SparseMatrixd& M_ff, const std::vector<Eigen::Index>& interior,
                                    const Eigen::MatrixXd& B_i, linalg::FactorizationBackend backend) {
  const auto n = M_ff.rows();
  std::vector<Eigen::Index> pos(static_cast<std::size_t>(n), -1), keep;
  for (std::size_t r = 0; r < interior.size(); ++r)
    if (M_ff.coeff(interior[r], interior[r]) > 0) {
      pos[static_cast<std::size_t>(interior[r])] = static_cast<Eigen::Index>(keep.size());
      keep.push_back(static_cast<Eigen::Index>(r));
    }
  const auto nk = static_cast<Eigen::Index>(keep.size());
  std::vector<Eigen::Triplet<double>> t;
  for (Eigen::Index c = 0; c < nk; ++c) {
    const Eigen::Index f = interior[static_cast<std::size_t>(keep[static_cast<std::size_t>(c)])];
    for (linalg::SparseMatrixd::InnerIterator it(M_ff, f); it; ++it) {
      const Eigen::Index r = pos[static_cast<std::size_t>(it.row())];
      if (r >= c) t.emplace_back(r, c, it.value());
    }
  }
  linalg::SparseMatrixd A(nk, nk);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::MatrixXd rhs(nk, B_i.cols());
  for (Eigen::Index c = 0; c < nk; ++c) rhs.row(c) = B_i.row(keep[static_cast<std::size_t>(c)]);
  auto factor = linalg::make_factorization(backend);
  factor->factorize(A);
  factor->solve_in_place(rhs);
  Eigen::MatrixXd z = Eigen::MatrixXd::Zero(B_i.rows(), B_i.cols());
  for (Eigen::Index c = 0; c < nk; ++c) z.row(keep[static_cast<std::size_t>(c)]) = rhs.row(c);
  return z;
}

}  // namespace

se::TruncationReport truncation_report(const CraigBamptonBasis& cb, const linalg::SparseMatrixd& M_ff,
                                       const Eigen::MatrixXd& R_b) {
  SEFLEX_DEMAND(R_b.rows() == cb.Psi.cols() && R_b.cols() == 6, "truncation report: R_b must be n_b x 6");
  SEFLEX_DEMAND(M_ff.rows() == cb.Psi.rows(), "truncation report: M does not match the basis");
  se::TruncationReport report;
  const Eigen::MatrixXd R = cb.Psi * R_b;  // static interior motion of the rigid boundary motions
  const Eigen::MatrixXd MR = M_ff * R;
  const auto ni = static_cast<Eigen::Index>(cb.interior.size());
  Eigen::MatrixXd R_i(ni, 6), MR_i(ni, 6);
  for (Eigen::Index r = 0; r < ni; ++r) {
    R_i.row(r) = R.row(cb.interior[static_cast<std::size_t>(r)]);
    MR_i.row(r) = MR.row(cb.interior[static_cast<std::size_t>(r)]);
  }
  // M_ib R_b = (M R)_i - M_ii R_i: zero for a lumped mass matrix, then z = R_i solves M_ii z = (M R)_i.
  Eigen::MatrixXd R_interior_only = R;
  for (Eigen::Index f : cb.boundary) R_interior_only.row(f).setZero();
  const Eigen::MatrixXd MRi_full = M_ff * R_interior_only;
  Eigen::MatrixXd coupling(ni, 6);
  for (Eigen::Index r = 0; r < ni; ++r)
    coupling.row(r) = MR_i.row(r) - MRi_full.row(cb.interior[static_cast<std::size_t>(r)]);
  Eigen::MatrixXd z = R_i;
  if (ni > 0 && coupling.cwiseAbs().maxCoeff() > 1e-14 * MR_i.cwiseAbs().maxCoeff())
    z = solve_interior_mass(M_ff, cb.interior, MR_i, linalg::kDefaultFactorization);

  const Eigen::MatrixXd L = cb.Phi.transpose() * MR;  // m x 6 participation factors
  for (int d = 0; d < 6; ++d) {
    const double total = ni > 0 ? MR_i.col(d).dot(z.col(d)) : 0.0;
    const double kept = L.rows() > 0 ? L.col(d).squaredNorm() : 0.0;
    // kept <= total in exact arithmetic (Bessel's inequality in the M_ii inner product); not
    // clamped, so that a broken basis shows.
    report.effective_mass_fraction[static_cast<std::size_t>(d)] = total > 0 ? kept / total : 1.0;
  }
  report.max_kept_hz = cb.eigenvalues.size() > 0 ? eigenvalue_to_hz(cb.eigenvalues.maxCoeff()) : 0.0;
  report.first_neglected_hz = cb.neglected_eigenvalues.size() > 0 ? eigenvalue_to_hz(cb.neglected_eigenvalues(0)) : 0.0;
  return report;
}

}  // namespace seflex::reduction
