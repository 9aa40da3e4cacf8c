// The AIC superelement kernel: validation/precomputation, frame recovery, local coordinates,
// Z/T, elastic force and tangent. Formulas: formulation.md sections 1.4-1.6, 2.2, 2.5, 3.
#include "seflex/mbd/bodies/aic_element.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <sstream>

#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "bodies/aic_inertia_detail.hpp"

namespace seflex::mbd {

using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using so3::skew;

namespace {

void rigid_modes_at(const std::vector<Vector3d>& x, const VectorXd* xi, MatrixXd& P) {
  const int N = static_cast<int>(x.size());
  P.setZero(6 * N, 6);
  for (int j = 0; j < N; ++j) {
    Vector3d s = x[j];
    if (xi) s += xi->segment<3>(6 * j);
    P.block<3, 3>(6 * j, 0).setIdentity();
    P.block<3, 3>(6 * j, 3) = -skew(s);
    P.block<3, 3>(6 * j + 3, 3).setIdentity();
  }
}

MatrixXd rigid_modes_at(const std::vector<Vector3d>& x, const VectorXd* xi) {
  MatrixXd P;
  rigid_modes_at(x, xi, P);
  return P;
}

std::string who(const std::string& name) { return "superelement '" + name + "'"; }

// The invariants in the stacked layout of StackedInvariantRows (one GEMV each per evaluation).
void stack_invariants(AicElement& e) {
  const se::InertiaInvariants& I = e.inv;
  const Eigen::Index n = e.n;
  const StackedInvariantRows r(n);
  MatrixXd& A = e.inv_by_xi;
  A.resize(r.by_xi, n);
  A.middleRows(r.HP, 3 * n) = I.HP;
  A.middleRows(r.HE0, 18) = I.HE0;
  A.middleRows(r.HE1, 9 * n) = I.HE1;
  for (int s = 0; s < 6; ++s) {
    A.middleRows(r.LP + s * n, n) = I.PmLP[s];
    A.middleRows(r.E0LP + 6 * s, 6) = I.E0mLP[s];
    A.middleRows(r.HLP + 3 * n * s, 3 * n) = I.HLP[s];
  }
  A.middleRows(r.HLX, 18) = I.HLX;
  MatrixXd& B = e.inv_by_xid;
  B.resize(r.by_xid, n);
  for (int a = 0; a < 3; ++a) {
    A.middleRows(r.HGP + 3 * n * a, 3 * n) = I.HGP[a];
    B.middleRows(r.PmGP + n * a, n) = I.PmGP[a];
    B.middleRows(r.E0mGP + 6 * a, 6) = I.E0mGP[a];
    B.middleRows(r.PgOV + n * a, n) = I.PgOV[a];
    B.middleRows(r.EgOV + 3 * a, 3) = I.EgOV[a];
    e.inv_GPV[a] = I.PmGP[a] + I.PgOV[a];
  }
  A = A * e.V_f;  // (n - 6) columns: the contractions see xi = V_f (V_f^T xi) only
  B = B * e.V_f;
}

/// Orthonormal basis of the null space of the 6 x n frame-node rows (rank 6: Phi_fb Phi_rig0 = I).
MatrixXd frame_condition_null_space(const MatrixXd& Phi_f) {
  const Eigen::HouseholderQR<MatrixXd> qr(Phi_f.transpose());
  const MatrixXd Q = qr.householderQ();
  return Q.rightCols(Phi_f.cols() - 6);
}

// The basis U and coefficients W of the stiffening invariants, G_c = sum_i U_i W(i, c)
// (docs/geometric-stiffening.md, "The rank of the invariants"). The SVD is taken of the stack with
// each group of cases, the 12 inertia loads and the 6N interface displacements, scaled by its largest
// |G_c|: the groups' units differ (per m/s^2 and per m; 1e7 apart on the demo's panel). Singular values
// below kRankTolerance of the largest are round-off of combinations that stress nothing (the rigid
// motions of the interfaces, a bar's bending, a flat plate's bending); dropping them moves no G_c by
// more than kRankTolerance sqrt(k) of the largest |G_c| of its group.
void stiffening_basis(AicElement& e, const MatrixXd& G_stack) {
  constexpr double kRankTolerance = 1e-12;
  const Eigen::Index k = G_stack.cols();
  const VectorXd norms = G_stack.colwise().norm().transpose();
  VectorXd scale(k);
  scale.head(12).setConstant(norms.head(12).maxCoeff());
  scale.tail(k - 12).setConstant(norms.tail(k - 12).maxCoeff());
  for (Eigen::Index c = 0; c < k; ++c)
    if (scale[c] == 0.0) scale[c] = 1.0;  // a group of zero matrices
  const MatrixXd scaled = G_stack * scale.cwiseInverse().asDiagonal();
  const Eigen::JacobiSVD<MatrixXd> svd(scaled, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const VectorXd& sv = svd.singularValues();
  Eigen::Index r = 0;
  while (r < sv.size() && sv[r] > kRankTolerance * sv[0]) ++r;
  e.G_basis.resize(e.n, r * e.n);
  for (Eigen::Index i = 0; i < r; ++i) {  // symmetric to the last bit, as the G_c are
    const Eigen::Map<const MatrixXd> U(svd.matrixU().col(i).data(), e.n, e.n);
    e.G_basis.middleCols(i * e.n, e.n) = 0.5 * (U + U.transpose());
  }
  e.G_coef = sv.head(r).asDiagonal() * svd.matrixV().leftCols(r).transpose() * scale.asDiagonal();
  e.G_basis_t_V = e.G_basis.transpose() * e.V_f;
}

}  // namespace

AicElement make_aic_element(const se::Superelement& s) {
  const std::string name = s.name.empty() ? std::string("(unnamed)") : s.name;
  const auto problems = se::check_consistency(s, 1e-8);
  if (!problems.empty()) {
    std::string msg = who(name) + " cannot be used as a flexible body:";
    for (const auto& p : problems) msg += " " + p + ";";
    throw InputError(msg);
  }
  AicElement e;
  e.name = name;
  e.N = s.num_interfaces();
  e.m = s.num_modes;
  e.n = s.size();
  e.Phi_f = s.Phi_f;
  e.K = 0.5 * (s.K + s.K.transpose());
  e.M = 0.5 * (s.M + s.M.transpose());
  e.K_abs_max = e.K.cwiseAbs().maxCoeff();
  double len = 1e-3;
  for (const auto& itf : s.interfaces) {
    e.x.push_back(itf.p_BoN_B);
    e.C.push_back(itf.R_BN);
    len = std::max(len, itf.p_BoN_B.norm());
    if ((itf.R_BN.transpose() * itf.R_BN - Matrix3d::Identity()).norm() > 1e-8 || itf.R_BN.determinant() < 0)
      throw InputError(who(name) + ": interface " + std::to_string(itf.id) + ": nodal triad R_BN is not a rotation matrix");
  }
  e.length = len;

  // Rigid-body reproduction by the frame-node rows: Phi_fb Phi_rig0 = I (formulation 1.3).
  const MatrixXd P0 = rigid_modes_at(e.x, nullptr);
  const MatrixXd A0 = e.Phi_f.leftCols(6 * e.N) * P0;
  const double err = (A0 - Eigen::Matrix<double, 6, 6>::Identity()).cwiseAbs().maxCoeff();
  if (!(err < 1e-6)) {
    std::ostringstream os;
    os << who(name) << ": the frame-node rows Phi_f do not reproduce rigid motion (|Phi_f Phi_rig0 - I| = " << err
       << ", expected < 1e-6); the AIC formulation needs the raw (not orthonormalised) constraint modes of a free-free "
          "model and a frame node that is not an interface node";
    throw InputError(os.str());
  }

  e.V_f = frame_condition_null_space(e.Phi_f);

  // Mass properties implied by M (exactly those of the FE model for a consistent reduction).
  const MatrixXd Mr = P0.transpose() * e.M.topLeftCorner(6 * e.N, 6 * e.N) * P0;
  e.mass = Mr(0, 0);
  if (!(e.mass > 0.0)) throw InputError(who(name) + ": the reduced mass matrix carries no mass (rigid-body mass " + std::to_string(e.mass) + ")");
  const Matrix3d mc = 0.5 * (Mr.block<3, 3>(3, 0) - Mr.block<3, 3>(0, 3));  // m c~
  e.p_BoCm_B = so3::vee(mc) / e.mass;
  const Matrix3d cx = skew(e.p_BoCm_B);
  e.I_Cm_B = Mr.block<3, 3>(3, 3) + e.mass * cx * cx;

  // Full-inertia data.
  const auto nfe = static_cast<Eigen::Index>(s.fe_node_ids.size());
  e.has_fe_data = nfe > 0 && s.recovery.rows() == 6 * nfe && s.recovery.cols() == e.n && s.M_fe.rows() == 6 * nfe &&
                  s.p_BoI_B.cols() == nfe;
  if (e.has_fe_data) {
    e.Psi = s.recovery;
    e.M_fe = s.M_fe;
    e.X = s.p_BoI_B;
    e.J_node.assign(nfe, Matrix3d::Zero());
    for (int c = 0; c < e.M_fe.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(e.M_fe, c); it; ++it) {
        const auto r = it.row();
        if (r / 6 == c / 6 && r % 6 >= 3 && c % 6 >= 3) e.J_node[c / 6](r % 6 - 3, c % 6 - 3) = it.value();
      }
  }
  if (s.invariants.present()) {
    if (s.invariants.n != e.n || s.invariants.Mpp.rows() != e.n || s.invariants.mode_max_translation.size() != e.m)
      throw InputError(who(name) + ": its inertia invariants are for " + std::to_string(s.invariants.n) +
                       " reduced coordinates, the superelement has " + std::to_string(e.n));
    e.inv = s.invariants;
  } else if (e.has_fe_data) {
    e.inv = se::compute_inertia_invariants(s);
  }
  if (e.inv.present()) stack_invariants(e);
  if (s.stiffening.present()) {
    const auto& st = s.stiffening;
    const auto nb = static_cast<std::size_t>(6 * e.N);
    if (st.n != e.n || st.interface.size() != nb)
      throw InputError(who(name) + ": its geometric-stiffness invariants are for " + std::to_string(st.n) +
                       " reduced coordinates and " + std::to_string(st.interface.size()) +
                       " interface dofs, the superelement has " + std::to_string(e.n) + " and " + std::to_string(nb));
    const auto k = static_cast<Eigen::Index>(12 + nb);
    MatrixXd G_stack(e.n * e.n, k);  // column c: vec G_c
    for (std::size_t c = 0; c < 12 + nb; ++c) {
      const MatrixXd& G = c < 12 ? st.inertia[c] : st.interface[c - 12];
      if (G.rows() != e.n || G.cols() != e.n)
        throw InputError(who(name) + ": a geometric-stiffness invariant is " + std::to_string(G.rows()) + "x" +
                         std::to_string(G.cols()) + ", expected " + std::to_string(e.n) + " square");
      Eigen::Map<MatrixXd>(G_stack.col(static_cast<Eigen::Index>(c)).data(), e.n, e.n) = 0.5 * (G + G.transpose());
    }
    stiffening_basis(e, G_stack);
    e.stiffening = true;
    // Pseudo-inverse of K_bb: its 6 rigid-motion eigenvalues are round-off against the largest.
    const auto nbi = static_cast<Eigen::Index>(nb);
    const MatrixXd Kbb = 0.5 * (e.K.topLeftCorner(nbi, nbi) + e.K.topLeftCorner(nbi, nbi).transpose());
    Eigen::SelfAdjointEigenSolver<MatrixXd> es(Kbb);
    const VectorXd& lam = es.eigenvalues();
    const double floor = 1e-9 * lam.cwiseAbs().maxCoeff();
    VectorXd inv = VectorXd::Zero(nbi);
    for (Eigen::Index i = 0; i < nbi; ++i)
      if (lam[i] > floor) inv[i] = 1.0 / lam[i];
    e.Kbb_pinv = es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose();
    e.G_foreshortening = e.G_coef.rightCols(nbi) * e.Kbb_pinv * e.G_coef.rightCols(nbi).transpose();
  }
  e.eta_amplitude = VectorXd::Ones(e.m);
  e.omega_modes = VectorXd::Zero(e.m);
  for (int k = 0; k < e.m; ++k) {
    const int c = 6 * e.N + k;
    const double mkk = e.M(c, c);
    e.omega_modes[k] = mkk > 0 ? std::sqrt(std::max(0.0, e.K(c, c) / mkk)) : 0.0;
    double amp = 0.0;
    if (e.inv.present()) {
      amp = e.inv.mode_max_translation[k];
    } else {
      amp = 1.0 / std::sqrt(e.mass);
    }
    e.eta_amplitude[k] = amp;
  }
  return e;
}

MatrixXd rigid_modes(const AicElement& e, const Eigen::Ref<const VectorXd>& xi) {
  const VectorXd x = xi;
  return rigid_modes_at(e.x, &x);
}

FloatingFrame frame_guess(const AicElement& e, const Matrix3d& R_WI0, const Vector3d& p_WI0) {
  FloatingFrame f;
  f.R_WB = R_WI0 * e.C[0].transpose();
  f.p_WBo = p_WI0 - f.R_WB * e.x[0];
  return f;
}

namespace {

void local_coordinates(const AicElement& e, const std::vector<Matrix3d>& R_WI, const std::vector<Vector3d>& p_WI,
                       const Matrix3d& R, const Vector3d& p, VectorXd& xi) {
  for (int j = 0; j < e.N; ++j) {
    xi.segment<3>(6 * j) = R.transpose() * (p_WI[j] - p) - e.x[j];
    xi.segment<3>(6 * j + 3) = so3::log(R.transpose() * R_WI[j] * e.C[j].transpose());
  }
}

/// X := A^-1 X for a 6 x 6 A (X: 6 x 1 or 6 x 6), Gauss-Jordan with partial pivoting in fixed-size
/// loops: Eigen's inverse() and partialPivLu() of a 6 x 6 run its general LU and triangular solves,
/// 26 % of the frame recovery and 4 % of a Radau IIA-5 run of sync-3d (perf, 2026-12-07); the
/// inverse here takes 260 against 630 ns (-O3 -march=x86-64-v3, the 2-core Xeon host). A singular A
/// gives non-finite entries, as Eigen's.
template <int Cols>
void gauss_jordan6(Eigen::Matrix<double, 6, 6> A, Eigen::Matrix<double, 6, Cols>& X) {
  for (int k = 0; k < 6; ++k) {
    int p = k;
    for (int i = k + 1; i < 6; ++i)
      if (std::abs(A(i, k)) > std::abs(A(p, k))) p = i;
    if (p != k) {
      A.row(k).swap(A.row(p));
      X.row(k).swap(X.row(p));
    }
    const double d = 1.0 / A(k, k);
    A.row(k) *= d;
    X.row(k) *= d;
    for (int i = 0; i < 6; ++i)
      if (i != k) {
        const double f = A(i, k);
        A.row(i) -= f * A.row(k);
        X.row(i) -= f * X.row(k);
      }
  }
}

}  // namespace

void recover_frame(const AicElement& e, const std::vector<Matrix3d>& R_WI, const std::vector<Vector3d>& p_WI,
                   const Eigen::Ref<const VectorXd>& eta, FrameRecovery method, const FloatingFrame& warm_start,
                   AicKinematics& kin) {
  SEFLEX_DEMAND(static_cast<int>(R_WI.size()) == e.N && static_cast<int>(p_WI.size()) == e.N, "interface count");
  SEFLEX_DEMAND(eta.size() == e.m, "modal coordinate count");
  const int N = e.N, nb = 6 * N;
  Matrix3d R = warm_start.R_WB;
  Vector3d p = warm_start.p_WBo;
  double scale = e.length;
  for (const auto& pj : p_WI) scale = std::max(scale, pj.norm());
  kin.xi.resize(e.n);
  if (e.m > 0) kin.xi.tail(e.m) = eta;
  const auto Phi_fb = e.Phi_f.leftCols(nb);
  const double tol = 1e-9;
  // Newton converges quadratically: after a correction of size d_k (previous d_{k-1}) the next would be
  // about K d_k^2, K = d_k / d_{k-1}^2, so the iterate is within d_k^3 / d_{k-1}^2 of the frame; stop
  // when that is below a thousandth of the tolerance (saves the confirming iteration: 3 -> 2 on the demo).
  double d_prev = 0.0;
  auto small = [&](double d) {
    const bool done = d <= tol || (d_prev > 0.0 && d <= 1e-3 && d * d * d <= 1e-3 * tol * d_prev * d_prev);
    d_prev = d;
    return done;
  };
  bool converged = false;
  int it = 0;
  for (; it < 30 && !converged; ++it) {
    if (method == FrameRecovery::Newton6) {
      local_coordinates(e, R_WI, p_WI, R, p, kin.xi);
      Eigen::Matrix<double, 6, 1> g;
      g.noalias() = e.Phi_f * kin.xi;
      Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
      for (int j = 0; j < N; ++j) {
        Eigen::Matrix<double, 6, 6> B = Eigen::Matrix<double, 6, 6>::Zero();
        B.topLeftCorner<3, 3>().setIdentity();
        B.topRightCorner<3, 3>() = -skew(e.x[j] + kin.xi.segment<3>(6 * j));
        B.bottomRightCorner<3, 3>() = so3::jl_inv(kin.xi.segment<3>(6 * j + 3));
        A.noalias() += Phi_fb.middleCols<6>(6 * j) * B;
      }
      Eigen::Matrix<double, 6, 1> d = g;
      gauss_jordan6(A, d);
      if (!d.allFinite()) break;
      p += R * d.head<3>();
      R = R * so3::exp(d.tail<3>());
      converged = small(d.head<3>().norm() / scale + d.tail<3>().norm());
    } else {
      Vector3d g = Vector3d::Zero();
      Matrix3d J = Matrix3d::Zero();
      for (int j = 0; j < N; ++j) {
        const auto A = Phi_fb.middleCols<6>(6 * j);
        const Vector3d b = R.transpose() * p_WI[j];
        const Vector3d th = so3::log(R.transpose() * R_WI[j] * e.C[j].transpose());
        g += A.block<3, 3>(3, 0) * (b - e.x[j]) + A.block<3, 3>(3, 3) * th;
        J += A.block<3, 3>(3, 3) * so3::jl_inv(th) - A.block<3, 3>(3, 0) * skew(b);
      }
      if (e.m > 0) g.noalias() += e.Phi_f.block(3, nb, 3, e.m) * eta;
      const Vector3d d = J.partialPivLu().solve(g);
      if (!d.allFinite()) break;
      R = R * so3::exp(d);
      converged = small(d.norm());
      if (converged || it == 29) {
        Vector3d t = Vector3d::Zero();
        for (int j = 0; j < N; ++j) {
          const auto A = Phi_fb.middleCols<6>(6 * j);
          const Vector3d b = R.transpose() * p_WI[j];
          const Vector3d th = so3::log(R.transpose() * R_WI[j] * e.C[j].transpose());
          t += A.block<3, 3>(0, 0) * (b - e.x[j]) + A.block<3, 3>(0, 3) * th;
        }
        if (e.m > 0) t.noalias() += e.Phi_f.block(0, nb, 3, e.m) * eta;
        p = R * t;
      }
    }
  }
  if (!converged) {
    std::ostringstream os;
    os << "floating-frame recovery of body with superelement '" << e.name << "' did not converge in " << it
       << " iterations (the interface poses are far from a small-strain state of the body)";
    throw ConvergenceError(os.str());
  }
  R = so3::orthonormalize(R);
  kin.frame.R_WB = R;
  kin.frame.p_WBo = p;
  kin.iterations = it;
  local_coordinates(e, R_WI, p_WI, R, p, kin.xi);
  rigid_modes_at(e.x, &kin.xi, kin.Phi_rig);
  // 6-row products with fixed sizes (no general matrix-product kernel for these small shapes).
  using Matrix6d = Eigen::Matrix<double, 6, 6>;
  using Matrix6X = Eigen::Matrix<double, 6, Eigen::Dynamic>;
  const Eigen::Map<const Matrix6X> Pf(e.Phi_f.data(), 6, e.n);
  kin.Lambda.resize(N);
  Matrix6d A0 = Matrix6d::Zero(), AL = Matrix6d::Zero();
  for (int j = 0; j < N; ++j) {
    kin.Lambda[j] = so3::jl_inv(kin.xi.segment<3>(6 * j + 3));
    const Matrix6d Pj = kin.Phi_rig.middleRows<6>(6 * j);
    A0.noalias() += Pf.middleCols<6>(6 * j).lazyProduct(Pj);
    // [Phi_fb Lambda]: the rotation columns of interface j times Lambda_j.
    AL.noalias() += Pf.middleCols<3>(6 * j).lazyProduct(Pj.topRows<3>());
    AL.noalias() += (Pf.middleCols<3>(6 * j + 3) * kin.Lambda[j]).lazyProduct(Pj.bottomRows<3>());
  }
  Matrix6d A0_inv = Matrix6d::Identity(), AL_inv = Matrix6d::Identity();
  gauss_jordan6(A0, A0_inv);
  gauss_jordan6(AL, AL_inv);
  kin.Zx.resize(6, e.n);
  kin.ZxL.resize(6, e.n);
  Eigen::Map<Matrix6X> Zx(kin.Zx.data(), 6, e.n), ZxL(kin.ZxL.data(), 6, e.n);
  Zx.noalias() = A0_inv.lazyProduct(Pf);
  // ZxL = AL^-1 [Phi_fb Lambda, Phi_fn]: the columns of Pf, rotation blocks times Lambda.
  ZxL.noalias() = AL_inv.lazyProduct(Pf);
  for (int j = 0; j < N; ++j) {
    const Eigen::Matrix<double, 6, 3> B = AL_inv * Pf.middleCols<3>(6 * j + 3);
    ZxL.middleCols<3>(6 * j + 3).noalias() = B * kin.Lambda[j];
  }
}

void apply_transfer(const AicElement& e, const AicKinematics& kin, const Eigen::Ref<const VectorXd>& x, VectorXd& y) {
  Eigen::Matrix<double, 6, 1> z;
  z.noalias() = kin.Zx * x;
  y = x;
  y.head(6 * e.N).noalias() -= kin.Phi_rig * z;
}

void apply_transfer_transpose(const AicElement& e, const AicKinematics& kin, const Eigen::Ref<const VectorXd>& x,
                              VectorXd& y) {
  Eigen::Matrix<double, 6, 1> z;
  z.noalias() = kin.Phi_rig.transpose() * x.head(6 * e.N);
  y = x;
  y.noalias() -= kin.Zx.transpose() * z;
}

MatrixXd transfer_matrix(const AicElement& e, const AicKinematics& kin) {
  MatrixXd T = MatrixXd::Identity(e.n, e.n);
  T.topRows(6 * e.N).noalias() -= kin.Phi_rig * kin.Zx;
  return T;
}

void to_body(const AicElement& e, const Matrix3d& R_WB, const Eigen::Ref<const VectorXd>& x, VectorXd& y) {
  y = x;
  for (int i = 0; i < 2 * e.N; ++i) y.segment<3>(3 * i) = R_WB.transpose() * x.segment<3>(3 * i);
}

void to_world(const AicElement& e, const Matrix3d& R_WB, const Eigen::Ref<const VectorXd>& x, VectorXd& y) {
  y = x;
  for (int i = 0; i < 2 * e.N; ++i) y.segment<3>(3 * i) = R_WB * x.segment<3>(3 * i);
}

VectorXd to_body(const AicElement& e, const Matrix3d& R_WB, const Eigen::Ref<const VectorXd>& x) {
  VectorXd y;
  to_body(e, R_WB, x, y);
  return y;
}

VectorXd to_world(const AicElement& e, const Matrix3d& R_WB, const Eigen::Ref<const VectorXd>& x) {
  VectorXd y;
  to_world(e, R_WB, x, y);
  return y;
}

void rotate_to_world(const AicElement& e, const Matrix3d& R_WB, MatrixXd& B) {
  // B <- R B R^T on the 2N interface 3-blocks of rows and columns, in place (no temporaries): columns
  // first (rows are contiguous in column-major storage: unit-stride loops), then the row blocks of
  // every column.
  const int nr = 2 * e.N;
  const Eigen::Index rows = B.rows(), cols = B.cols();
  const Matrix3d& R = R_WB;
  for (int i = 0; i < nr && 3 * i + 2 < cols; ++i) {
    double* c0 = B.col(3 * i).data();
    double* c1 = B.col(3 * i + 1).data();
    double* c2 = B.col(3 * i + 2).data();
    for (Eigen::Index r = 0; r < rows; ++r) {  // [c0 c1 c2](r) <- [c0 c1 c2](r) R^T
      const double a = c0[r], b = c1[r], c = c2[r];
      c0[r] = a * R(0, 0) + b * R(0, 1) + c * R(0, 2);
      c1[r] = a * R(1, 0) + b * R(1, 1) + c * R(1, 2);
      c2[r] = a * R(2, 0) + b * R(2, 1) + c * R(2, 2);
    }
  }
  for (Eigen::Index c = 0; c < cols; ++c) {
    double* col = B.col(c).data();
    for (int i = 0; i < nr && 3 * i + 2 < rows; ++i) {  // rows 3i..3i+2 <- R rows
      double* x = col + 3 * i;
      const double a = x[0], b = x[1], d = x[2];
      x[0] = R(0, 0) * a + R(0, 1) * b + R(0, 2) * d;
      x[1] = R(1, 0) * a + R(1, 1) * b + R(1, 2) * d;
      x[2] = R(2, 0) * a + R(2, 1) * b + R(2, 2) * d;
    }
  }
}

MatrixXd to_world_matrix(const AicElement& e, const Matrix3d& R_WB, const MatrixXd& A) {
  MatrixXd B = A;
  rotate_to_world(e, R_WB, B);
  return B;
}

void elastic_force(const AicElement& e, const AicKinematics& kin, TangentModel tangent, VectorXd& f, MatrixXd* Kt) {
  AicWorkspace ws;
  elastic_force(e, kin, tangent, f, Kt, ws);
}

void elastic_force(const AicElement& e, const AicKinematics& kin, TangentModel tangent, VectorXd& f, MatrixXd* Kt,
                   AicWorkspace& ws, MatrixAxes axes) {
  ws.g.noalias() = e.K * kin.xi;
  detail::elastic_force_of_local(e, kin, tangent, e.K, f, Kt, ws, axes);
}

namespace detail {

void elastic_force_of_local(const AicElement& e, const AicKinematics& kin, TangentModel tangent, const MatrixXd& H,
                                VectorXd& f, MatrixXd* Kt, AicWorkspace& ws, MatrixAxes axes) {
  // Tx = I - R6 Zx with R6 = [Phi_rig; 0] (rank-6 defect): every product with Tx is O(n^2).
  const int N = e.N, nb = 6 * N;
  const MatrixXd& Phi = kin.Phi_rig;
  const VectorXd& g = ws.g;
  VectorXd& fw = ws.fw;
  fw = g;  // Tx^T g
  Eigen::Matrix<double, 6, 1> Pg;
  Pg.noalias() = Phi.transpose() * g.head(nb);
  fw.noalias() -= kin.Zx.transpose() * Pg;
  to_world(e, kin.frame.R_WB, fw, f);
  if (!Kt) return;
  const bool exact = tangent == TangentModel::Exact;
  const MatrixXd& ZxL = exact ? kin.ZxL : kin.Zx;
  // Kw = Tx^T KL TxL + Zx_r^T GT - F~ E_r ZxL with KL = H Lambda_x (formed in Kw, body axes):
  //   material part Tx^T KL TxL = KL - n6 ZxL - Zx^T PK,  n6 = KL_b Phi,  PK = Phi^T (KL - n6 ZxL)_b;
  //   geometric part from the variation of T: Zx^T E_r^T GT, GT = G TxL, G = [f_u1~, 0, f_u2~, 0, ...];
  //   from the rotation of the forces with R_WB: -F~ E_r ZxL (F~: the stacked skew matrices of fw).
  // The products by ZxL and by Zx^T gathered: Kw = KL + L ZxL + Zx^T R with L = -n6 - [0 | F~] and
  // R = -(Phi^T KL_b - (Phi^T n6_b) ZxL) + [0; GT_0] (GT_0 = G's own blocks - (G Phi) ZxL).
  MatrixXd& Kw = *Kt;
  Kw = H;
  if (exact)
    for (int j = 0; j < N; ++j) Kw.middleCols<3>(6 * j + 3).noalias() = H.middleCols<3>(6 * j + 3) * kin.Lambda[j];
  MatrixXd& L = ws.n6;
  L.noalias() = Kw.leftCols(nb) * Phi;  // n6
  Eigen::Matrix<double, 6, 6> Pn6;
  Pn6.noalias() = Phi.transpose() * L.topRows(nb);
  MatrixXd& R = ws.PK;
  R.noalias() = Phi.transpose() * Kw.topRows(nb);
  R.noalias() -= Pn6 * ZxL;
  R = -R;
  Eigen::Matrix<double, 3, 6> GPhi = Eigen::Matrix<double, 3, 6>::Zero();
  for (int j = 0; j < N; ++j) {
    const Matrix3d F = skew(fw.segment<3>(6 * j));
    R.block<3, 3>(3, 6 * j) += F;
    GPhi.noalias() += F * Phi.middleRows<3>(6 * j);
  }
  R.middleRows<3>(3).noalias() -= GPhi * ZxL;
  detail::stacked_skew(e, fw, ws.S3);
  L = -L;
  L.rightCols<3>() -= ws.S3;
  Kw.noalias() += L * ZxL;
  Kw.noalias() += kin.Zx.transpose() * R;
  if (axes == MatrixAxes::World) rotate_to_world(e, kin.frame.R_WB, Kw);
}

}  // namespace detail

Vector3d deformed_com(const AicElement& e, const Eigen::Ref<const VectorXd>& xi) {
  Vector3d s = Vector3d::Zero();  // sum over interfaces of the translation rows of M xi
  for (int j = 0; j < e.N; ++j) s.noalias() += e.M.middleRows<3>(6 * j) * xi;
  return e.p_BoCm_B + s / e.mass;
}

}  // namespace seflex::mbd
