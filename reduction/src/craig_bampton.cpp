// Generic Craig-Bampton reduction on the f-set (craig_bampton.hpp).
#include "seflex/reduction/craig_bampton.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "seflex/linalg/block_lanczos.hpp"
#include "seflex/common/error.hpp"

namespace seflex::reduction {

namespace {

constexpr double kMasslessFraction = 1e-12;  // M's eigenvalues below this fraction of the largest are zero

/// Columns `cols` and rows `rows` of the symmetric A (both triangles stored), as a sparse matrix.
/// row_pos / col_pos map an f index to its position in the block (-1 = not in it); rows must be
/// numbered increasingly with f so that each column stays sorted. lower_only keeps row >= column.
linalg::SparseMatrixd extract_block(const linalg::SparseMatrixd& A, const std::vector<Eigen::Index>& rows,
                            const std::vector<Eigen::Index>& row_pos, const std::vector<Eigen::Index>& cols,
                            bool lower_only) {
  const auto nc = static_cast<Eigen::Index>(cols.size()), nr = static_cast<Eigen::Index>(rows.size());
  linalg::SparseMatrixd B(nr, nc);
  std::vector<int> count(static_cast<std::size_t>(nc), 0);
  for (Eigen::Index c = 0; c < nc; ++c)
    for (linalg::SparseMatrixd::InnerIterator it(A, cols[static_cast<std::size_t>(c)]); it; ++it) {
      const Eigen::Index r = row_pos[static_cast<std::size_t>(it.row())];
      if (r >= 0 && (!lower_only || r >= c)) ++count[static_cast<std::size_t>(c)];
    }
  B.reserve(count);
  for (Eigen::Index c = 0; c < nc; ++c)
    for (linalg::SparseMatrixd::InnerIterator it(A, cols[static_cast<std::size_t>(c)]); it; ++it) {
      const Eigen::Index r = row_pos[static_cast<std::size_t>(it.row())];
      if (r >= 0 && (!lower_only || r >= c)) B.insert(r, c) = it.value();
    }
  B.makeCompressed();
  return B;
}

}  // namespace

void demand_valid_request(const CraigBamptonOptions& options, const std::vector<Eigen::Index>& boundary) {
  SEFLEX_DEMAND(options.modes.has_value() != options.fmax_hz.has_value(),
                "Craig-Bampton: give either a number of modes or a frequency limit");
  SEFLEX_DEMAND(!options.modes || *options.modes >= 0, "Craig-Bampton: negative mode count");
  SEFLEX_DEMAND(!options.fmax_hz || *options.fmax_hz > 0, "Craig-Bampton: the frequency limit must be positive");
  SEFLEX_DEMAND(options.extra_modes >= 0, "Craig-Bampton: negative extra mode count");
  SEFLEX_DEMAND(!boundary.empty(), "Craig-Bampton: empty boundary set");
}

CraigBamptonBasis craig_bampton(const linalg::SparseMatrixd& K_ff, const linalg::SparseMatrixd& M_ff,
                                const std::vector<Eigen::Index>& boundary, const CraigBamptonOptions& options) {
  const Eigen::Index n = K_ff.rows();
  SEFLEX_DEMAND(K_ff.cols() == n && M_ff.rows() == n && M_ff.cols() == n,
                "Craig-Bampton: K and M must be square, same size");
  demand_valid_request(options, boundary);

  CraigBamptonBasis cb;
  cb.boundary = boundary;
  std::vector<Eigen::Index> bpos(static_cast<std::size_t>(n), -1), ipos(static_cast<std::size_t>(n), -1);
  for (std::size_t k = 0; k < boundary.size(); ++k) {
    const Eigen::Index f = boundary[k];
    SEFLEX_DEMAND(f >= 0 && f < n, "Craig-Bampton: boundary dof out of range");
    SEFLEX_DEMAND(bpos[static_cast<std::size_t>(f)] < 0,
                  "Craig-Bampton: boundary dof " + std::to_string(f) + " given twice");
    bpos[static_cast<std::size_t>(f)] = static_cast<Eigen::Index>(k);
  }
  for (Eigen::Index f = 0; f < n; ++f)
    if (bpos[static_cast<std::size_t>(f)] < 0) {
      ipos[static_cast<std::size_t>(f)] = static_cast<Eigen::Index>(cb.interior.size());
      cb.interior.push_back(f);
    }
  const auto nb = static_cast<Eigen::Index>(boundary.size()), ni = static_cast<Eigen::Index>(cb.interior.size());
  cb.stats.n_free = n;
  cb.stats.n_boundary = nb;
  cb.stats.n_interior = ni;

  // Boundary rows of K (dense n_b x n_b) and the coupling K_ib (sparse n_i x n_b).
  const Eigen::MatrixXd K_bb = Eigen::MatrixXd(extract_block(K_ff, boundary, bpos, boundary, false));
  const linalg::SparseMatrixd K_ib = extract_block(K_ff, cb.interior, ipos, boundary, false);

  // Constraint modes: Psi_i = -K_ii^-1 K_ib, one factorisation, one block solve. The factor of
  // K_ii stays for the fixed-interface modes (block Lanczos at shift 0).
  Eigen::MatrixXd Psi_i = -Eigen::MatrixXd(K_ib);
  linalg::SparseMatrixd K_ii, M_ii;
  auto factor = options.factorization_maker ? options.factorization_maker() : linalg::make_factorization(options.factorization);
  if (ni > 0) {
    K_ii = extract_block(K_ff, cb.interior, ipos, cb.interior, true);
    M_ii = extract_block(M_ff, cb.interior, ipos, cb.interior, true);
    factor->factorize(K_ii);  // FactorizationError names the interior column: mapped by the caller
    factor->solve_in_place(Psi_i);
    cb.stats.interior_factorization = factor->stats();
  }
  if (options.interior_loads.cols() > 0) {
    SEFLEX_DEMAND(options.interior_loads.rows() == n, "Craig-Bampton: interior_loads must have one row per f-dof");
    cb.static_responses = Eigen::MatrixXd::Zero(n, options.interior_loads.cols());
    if (ni > 0) {
      Eigen::MatrixXd Y(ni, options.interior_loads.cols());
      for (Eigen::Index r = 0; r < ni; ++r) Y.row(r) = options.interior_loads.row(cb.interior[static_cast<std::size_t>(r)]);
      factor->solve_in_place(Y);
      for (Eigen::Index r = 0; r < ni; ++r) cb.static_responses.row(cb.interior[static_cast<std::size_t>(r)]) = Y.row(r);
      cb.stats.interior_factorization = factor->stats();  // the loads' columns counted, as the partitioned path does
    }
  }
  cb.Psi = Eigen::MatrixXd::Zero(n, nb);
  for (Eigen::Index k = 0; k < nb; ++k) cb.Psi(boundary[static_cast<std::size_t>(k)], k) = 1.0;
  for (Eigen::Index r = 0; r < ni; ++r) cb.Psi.row(cb.interior[static_cast<std::size_t>(r)]) = Psi_i.row(r);

  // Fixed-interface modes of (K_ii, M_ii): the lowest `modes` + extra, or all up to fmax + extra.
  Eigen::MatrixXd X(ni, 0);
  Eigen::VectorXd lambda(0);
  Eigen::Index kept = 0;
  const std::optional<double> lambda_max =
      options.fmax_hz ? std::optional<double>(std::pow(2.0 * 3.14159265358979323846 * *options.fmax_hz, 2))
                      : std::nullopt;
  const Eigen::Index finite = ni > 0 ? linalg::detail::mass_rank_bound(M_ii) : 0;
  const Eigen::Index want = options.modes ? std::min<Eigen::Index>(*options.modes + options.extra_modes, finite) : 0;
  bool done = ni == 0 || (options.modes && want == 0);
  if (!done && ni >= options.block_lanczos_min_size) {
    linalg::detail::BlockLanczosOptions bo;
    if (options.modes)
      bo.count = want;
    else
      bo.lambda_max = lambda_max;
    bo.extra = options.extra_modes;
    if (auto r = linalg::detail::block_lanczos_lowest(*factor, M_ii, bo)) {
      cb.stats.block_solves = r->block_solves;
      cb.stats.krylov_basis = r->basis_size;
      X = std::move(r->vectors);
      lambda = std::move(r->eigenvalues);
      done = true;
    }
  }
  factor.reset();
  if (!done) {  // small interiors (dense), or more modes than a block Krylov basis holds: restarted Lanczos
    linalg::EigenOptions eo;
    eo.backend = options.backend;
    eo.factorization = options.factorization;
    eo.external = options.external;
    auto solve = [&](std::optional<int> count, std::optional<double> limit) {
      eo.count = count;
      eo.lambda_max = limit;
      linalg::EigenSolution s = linalg::solve_eigenproblem(K_ii, M_ii, eo);
      cb.stats.eigen = s.stats;
      ++cb.stats.eigen_solutions;
      return s;
    };
    linalg::EigenSolution sol;
    if (options.modes) {
      sol = solve(static_cast<int>(want), std::nullopt);
    } else {
      sol = solve(std::nullopt, lambda_max);
      const Eigen::Index below = sol.eigenvalues.size();
      if (options.extra_modes > 0 && below < finite)  // the modes just above the limit: a count run
        sol = solve(static_cast<int>(std::min<Eigen::Index>(below + options.extra_modes, finite)), std::nullopt);
    }
    X = std::move(sol.vectors);
    lambda = std::move(sol.eigenvalues);
  }
  if (options.modes) {
    kept = std::min<Eigen::Index>(*options.modes, lambda.size());
  } else {
    while (kept < lambda.size() && lambda(kept) <= *lambda_max) ++kept;
  }
  const Eigen::Index m = kept;
  cb.eigenvalues = lambda.head(m);
  cb.neglected_eigenvalues = lambda.tail(lambda.size() - m);
  cb.Phi = Eigen::MatrixXd::Zero(n, m);
  if (m > 0)  // X may be empty when no mode is kept (--modes 0): no row of it may be taken then
    for (Eigen::Index r = 0; r < ni; ++r) cb.Phi.row(cb.interior[static_cast<std::size_t>(r)]) = X.row(r).head(m);

  // Reduced matrices.
  const Eigen::Index nr = nb + m;
  cb.K = Eigen::MatrixXd::Zero(nr, nr);
  cb.M = Eigen::MatrixXd::Zero(nr, nr);
  Eigen::MatrixXd Kbb = K_bb + Eigen::MatrixXd(K_ib.transpose() * Psi_i);  // Schur complement Psi^T K Psi
  cb.K.topLeftCorner(nb, nb) = 0.5 * (Kbb + Kbb.transpose());
  cb.K.diagonal().tail(m) = cb.eigenvalues;
  const Eigen::MatrixXd MPsi = M_ff * cb.Psi;
  Eigen::MatrixXd Mbb = cb.Psi.transpose() * MPsi;
  cb.M.topLeftCorner(nb, nb) = 0.5 * (Mbb + Mbb.transpose());
  if (m > 0) {
    cb.M.bottomLeftCorner(m, nb) = cb.Phi.transpose() * MPsi;
    cb.M.topRightCorner(nb, m) = cb.M.bottomLeftCorner(m, nb).transpose();
    cb.M.bottomRightCorner(m, m).setIdentity();
  }
  return cb;
}

Eigen::VectorXd small_pencil_eigenvalues(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, int count) {
  SEFLEX_DEMAND(K.rows() == K.cols() && M.rows() == M.cols() && K.rows() == M.rows(), "pencil: sizes differ");
  if (K.rows() == 0 || count <= 0) return Eigen::VectorXd(0);
  // M = [R Z] diag(mu_r, ~0) [R Z]^T. The massless directions Z carry infinite eigenvalues; the finite
  // ones are those of the pencil condensed onto R: (K_rr - K_rz K_zz^-1 K_zr, diag(mu_r)). Working
  // from M (not a shift of K) keeps rigid-body modes at 0 to round-off of ||K|| / ||M|| and every
  // elastic eigenvalue to working precision, whatever the spread of the spectrum.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> me(0.5 * (M + M.transpose()));
  SEFLEX_DEMAND(me.info() == Eigen::Success, "pencil: eigendecomposition of M failed");
  const double mu_max = me.eigenvalues().cwiseAbs().maxCoeff();
  SEFLEX_DEMAND(mu_max > 0, "pencil: M is zero");
  Eigen::Index nz = 0;
  while (nz < M.rows() && me.eigenvalues()(nz) <= kMasslessFraction * mu_max) ++nz;
  const Eigen::MatrixXd Z = me.eigenvectors().leftCols(nz), R = me.eigenvectors().rightCols(M.rows() - nz);
  const Eigen::MatrixXd Ks = 0.5 * (K + K.transpose());
  Eigen::MatrixXd Kc = R.transpose() * Ks * R;
  if (nz > 0) {
    const Eigen::LLT<Eigen::MatrixXd> zz(Z.transpose() * Ks * Z);
    SEFLEX_DEMAND(zz.info() == Eigen::Success, "pencil: a massless direction has no stiffness (a mechanism)");
    const Eigen::MatrixXd Krz = R.transpose() * Ks * Z;
    Kc -= Krz * zz.solve(Krz.transpose());
  }
  const Eigen::VectorXd scale = me.eigenvalues().tail(M.rows() - nz).cwiseSqrt().cwiseInverse();
  Eigen::MatrixXd A = scale.asDiagonal() * Kc * scale.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ae(0.5 * (A + A.transpose()), Eigen::EigenvaluesOnly);
  SEFLEX_DEMAND(ae.info() == Eigen::Success, "pencil: eigensolution failed");
  return ae.eigenvalues().head(std::min<Eigen::Index>(count, ae.eigenvalues().size()));
}

}  // namespace seflex::reduction
