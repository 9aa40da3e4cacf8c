// Analytic tangents of the FFRF-LM joints and node loads (docs/ffrf.md "Joint and node-load
// tangents"). For a pose with Jacobian J = [J_p; J_r] (world translation and spatial rotation per
// unit coordinate) and a world wrench w = [F; M] held fixed, H(w) = d(J^T w)/dq, with rotation
// increments R <- exp(dpi~) R, so d(R x) = -(R x)~ dpi and d(R^T y) = (R^T y)~ R^T dpi:
// - interface of body B (columns [p; pi; z], s = X_BN.p + V_t z, theta = V_r z, J_l = jl(theta)):
//     rows pi: (R s) x F + M        -> H(pi, pi) = F~ (R s)~,  H(pi, z) = -F~ R V_t
//     rows z:  V_t^T R^T F + V_r^T J_l^T R^T M
//                                   -> H(z, pi) = V_t^T (R^T F)~ R^T + V_r^T J_l^T (R^T M)~ R^T,
//                                      H(z, z) = V_r^T d(J_l^T u)/dtheta V_r,  u = R^T M
// - node through its parent P (d = R_P p_PN, hinge column [0; R_P a]): J^T w = J_P^T [F; M + d x F]
//   on the parent's columns and (R_P a) . M on the hinge's, so
//     H = H_P([F; M + d x F]) + J_P,r^T F~ d~ J_P,r, hinge row ((R_P a) x M)^T J_P,r, hinge column 0.
// A constraint's G^T lambda is J_A^T w - J_B^T w with w = [lambda_f; m], m = R_B J_l^-1(g_r)^T lambda_m,
// and g_r = log(R_B^T R_A) moves by dg_r = G_r dq, so
//     d(G^T lambda)/dq = H_A(w) - H_B(w) + (J_A,r - J_B,r)^T (R_B d(J_l^-T lambda_m)/dg_r G_r - m~ J_B,r).
// A node load's -J^T F adds, for a follower (F = R f), J_p^T F_t~ J_r + J_r^T F_r~ J_r.
#include "ffrf/ffrf_joint_tangents.hpp"

#include <Eigen/Dense>

#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"

namespace seflex::mbd::detail {

using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using so3::skew;

namespace {

/// Polynomial sum_i c[i] x^i (Horner).
template <std::size_t N>
double poly(const double (&c)[N], double x) {
  double r = c[N - 1];
  for (std::size_t i = N - 1; i-- > 0;) r = r * x + c[i];
  return r;
}

/// Below t^2 = 0.1 the coefficients and their derivatives (f'(t)/t) are Taylor series in t^2 up to t^10
/// (remainder < 1e-17 relative); above it the closed forms lose at most ~300 eps to cancellation.
constexpr double kSeries = 0.1;

/// a = (1 - cos t)/t^2, b = (t - sin t)/t^3 (J_l = I + a S + b S^2) and a'(t)/t, b'(t)/t.
void jl_coefficients(double t2, double& a, double& b, double& da, double& db) {
  if (t2 < kSeries) {
    static constexpr double ca[] = {1.0 / 2, -1.0 / 24, 1.0 / 720, -1.0 / 40320, 1.0 / 3628800, -1.0 / 479001600};
    static constexpr double cb[] = {1.0 / 6, -1.0 / 120, 1.0 / 5040, -1.0 / 362880, 1.0 / 39916800, -1.0 / 6227020800};
    static constexpr double cda[] = {-1.0 / 12,    1.0 / 180,       -1.0 / 6720,
                                     1.0 / 453600, -1.0 / 47900160, 1.0 / 7264857600};
    static constexpr double cdb[] = {-1.0 / 60,     1.0 / 1260,       -1.0 / 60480,
                                     1.0 / 4989600, -1.0 / 622702080, 1.0 / 108972864000};
    a = poly(ca, t2);
    b = poly(cb, t2);
    da = poly(cda, t2);
    db = poly(cdb, t2);
    return;
  }
  const double t = std::sqrt(t2), s = std::sin(t), h = std::sin(0.5 * t);
  const double omc = 2.0 * h * h;  // 1 - cos t without cancellation
  a = omc / t2;
  b = (t - s) / (t2 * t);
  da = s / (t2 * t) - 2.0 * omc / (t2 * t2);
  db = omc / (t2 * t2) - 3.0 * (t - s) / (t2 * t2 * t);
}

/// c = 1/t^2 - (1 + cos t)/(2 t sin t) (J_l^-1 = I - S/2 + c S^2) and c'(t)/t.
void jl_inv_coefficients(double t2, double& c, double& dc) {
  if (t2 < kSeries) {
    static constexpr double cc[] = {1.0 / 12,      1.0 / 720,      1.0 / 30240,
                                    1.0 / 1209600, 1.0 / 47900160, 691.0 / 1307674368000};
    static constexpr double cdc[] = {1.0 / 360,     1.0 / 7560,           1.0 / 201600,
                                     1.0 / 5987520, 691.0 / 130767436800, 1.0 / 6227020800};
    c = poly(cc, t2);
    dc = poly(cdc, t2);
    return;
  }
  const double t = std::sqrt(t2), h = std::sin(0.5 * t), cot = std::cos(0.5 * t) / h;  // (1 + cos t)/sin t = cot(t/2)
  c = 1.0 / t2 - cot / (2.0 * t);
  dc = -2.0 / (t2 * t2) + 1.0 / (4.0 * t2 * h * h) + cot / (2.0 * t2 * t);
}

/// d(theta x (theta x u))/dtheta.
Matrix3d double_cross_tangent(const Vector3d& th, const Vector3d& u) {
  return th * u.transpose() + th.dot(u) * Matrix3d::Identity() - 2.0 * u * th.transpose();
}

/// H grown (never shrunk) to at least n x n, its leading n x n block zeroed.
void zero_leading(MatrixXd& H, Eigen::Index n) {
  if (H.rows() < n || H.cols() < n) H.resize(std::max(n, H.rows()), std::max(n, H.cols()));
  H.topLeftCorner(n, n).setZero();
}

}  // namespace

Matrix3d jl_transpose_tangent(const Vector3d& th, const Vector3d& u) {
  double a, b, da, db;
  jl_coefficients(th.squaredNorm(), a, b, da, db);
  // J_l^T u = u - a th x u + b th x (th x u)
  const Vector3d y1 = th.cross(u), y2 = th.cross(y1);
  return a * skew(u) - da * y1 * th.transpose() + b * double_cross_tangent(th, u) + db * y2 * th.transpose();
}

Matrix3d jl_inv_transpose_tangent(const Vector3d& th, const Vector3d& u) {
  double c, dc;
  jl_inv_coefficients(th.squaredNorm(), c, dc);
  // J_l^-T u = u + th x u / 2 + c th x (th x u)
  const Vector3d y2 = th.cross(th.cross(u));
  return -0.5 * skew(u) + c * double_cross_tangent(th, u) + dc * y2 * th.transpose();
}

void interface_tangent(const FfrfSystem& sys, const FfrfState& s, int bi, int j, const Vector6d& w, PoseJ& P,
                       MatrixXd& H) {
  interface_pose(sys, s, bi, j, P);
  const FfrfBody& b = sys.bodies[static_cast<std::size_t>(bi)];
  const Matrix3d& R = s.R_WB[static_cast<std::size_t>(bi)];
  const Vector3d F = w.head<3>(), M = w.tail<3>();
  zero_leading(H, P.size());
  Vector3d s_j = b.X_BN[static_cast<std::size_t>(j)].p;
  const bool modal = b.flexible && b.k > 0;
  const auto Vj = b.V.middleRows(modal ? 6 * j : 0, modal ? 6 : 0);
  if (modal) s_j.noalias() += Vj.topRows(3) * s.z.segment(b.z_offset, b.k);
  H.block<3, 3>(3, 3) = skew(F) * skew(R * s_j);
  if (!modal) return;
  const int k = b.k;
  const auto Vt = Vj.topRows(3), Vr = Vj.bottomRows(3);
  const Vector3d th = Vr * s.z.segment(b.z_offset, k);
  const Vector3d u = R.transpose() * M;
  const Matrix3d A = -skew(F) * R;
  H.block(3, 6, 3, k).noalias() = A * Vt;
  const Matrix3d Bt = skew(R.transpose() * F) * R.transpose();
  const Matrix3d Br = so3::jl(th).transpose() * skew(u) * R.transpose();
  H.block(6, 3, k, 3).noalias() = Vt.transpose() * Bt;
  H.block(6, 3, k, 3).noalias() += Vr.transpose() * Br;
  const Matrix3d Z = jl_transpose_tangent(th, u);
  for (int c = 0; c < k; ++c) {
    const Vector3d zc = Z * Vr.col(c);
    H.col(6 + c).segment(6, k).noalias() = Vr.transpose() * zc;
  }
}

void node_tangent(const FfrfSystem& sys, const FfrfState& s, int k, bool chain, const Vector6d& w, PoseJ& P,
                  MatrixXd& H) {
  const Node& n = sys.model->nodes[static_cast<std::size_t>(k)];
  const FfrfNodeSource& src = sys.node_source[static_cast<std::size_t>(k)];
  if (n.kind == NodeKind::Fixed) {
    node_pose(sys, s, k, chain, P);
    zero_leading(H, 0);
    return;
  }
  if (!chain && src.kind == FfrfNodeSource::Kind::Body) {
    interface_tangent(sys, s, src.body, src.interface, w, P, H);
    return;
  }
  SEFLEX_DEMAND(n.kind == NodeKind::Attached, "node pose through a parent of a node that has none");
  const int parent = n.parent.value;
  node_pose(sys, s, parent, false, P);  // R_P, for the wrench at the parent
  const Matrix3d R_P = P.R;
  const Vector3d d = R_P * n.p_PN_P;
  const Vector3d F = w.head<3>(), M = w.tail<3>();
  Vector6d wP;
  wP << F, M + d.cross(F);
  node_tangent(sys, s, parent, false, wP, P, H);
  const Eigen::Index np = P.size();
  const Matrix3d FD = skew(F) * skew(d);
  for (Eigen::Index c = 0; c < np; ++c) {
    const Vector3d t = FD * P.J.col(c).tail<3>();
    H.col(c).head(np).noalias() += P.J.leftCols(np).bottomRows<3>().transpose() * t;
  }
  if (n.hinge.valid()) {
    if (H.rows() < np + 1 || H.cols() < np + 1)
      H.conservativeResize(std::max(np + 1, H.rows()), std::max(np + 1, H.cols()));
    const Vector3d a = R_P * sys.model->hinges[static_cast<std::size_t>(n.hinge.value)].axis_P;
    H.row(np).head(np).noalias() = a.cross(M).transpose() * P.J.leftCols(np).bottomRows<3>();
    H.col(np).head(np + 1).setZero();
  }
  attach_to_parent(sys, s, k, P);
}

void constraint_tangent(const FfrfSystem& sys, const FfrfState& s, const FfrfConstraint& con, const ConstraintEval& ce,
                        const Vector6d& lam, JointTangentScratch& w) {
  const PoseJ& A = ce.A;
  const PoseJ& B = ce.B;
  const Eigen::Index n = ce.size(), na = A.size(), nB = B.size();
  const Vector3d th = ce.g.tail<3>(), lm = lam.tail<3>();
  const Vector3d m = B.R * (so3::jl_inv(th).transpose() * lm);
  Vector6d wc;
  wc << lam.head<3>(), m;
  interface_tangent(sys, s, con.body, con.interface, wc, w.P, w.HA);
  node_tangent(sys, s, con.node.value, con.chain, wc, w.P, w.HB);
  zero_leading(w.K, n);
  auto K = w.K.topLeftCorner(n, n);
  K.topLeftCorner(na, na) = w.HA.topLeftCorner(na, na);
  if (w.Dr.cols() < n) w.Dr.resize(3, n);
  if (w.JBr.cols() < n) w.JBr.resize(3, n);
  auto Dr = w.Dr.leftCols(n);
  auto T = w.JBr.leftCols(n);
  Dr.setZero();
  T.setZero();
  Dr.leftCols(na) = A.J.leftCols(na).bottomRows<3>();
  for (Eigen::Index i = 0; i < nB; ++i) {
    const Eigen::Index ai = ce.b_at[static_cast<std::size_t>(i)];
    for (Eigen::Index j = 0; j < nB; ++j) K(ai, ce.b_at[static_cast<std::size_t>(j)]) -= w.HB(i, j);
    Dr.col(ai) -= B.J.col(i).tail<3>();
    T.col(ai) = B.J.col(i).tail<3>();
  }
  // T = R_B Y G_r - m~ J_B,r: dm/dq
  const Matrix3d RY = B.R * jl_inv_transpose_tangent(th, lm), Sm = skew(m);
  for (Eigen::Index c = 0; c < n; ++c) {
    const Vector3d t = RY * ce.G.col(c).tail<3>() - Sm * T.col(c);
    T.col(c) = t;
  }
  K.noalias() += Dr.transpose() * T;
}

void load_tangent(const FfrfSystem& sys, const FfrfState& s, const NodeLoad& load, const PoseJ& P, const Vector6d& F,
                  JointTangentScratch& w) {
  node_tangent(sys, s, load.node.value, false, F, w.P, w.HA);
  const Eigen::Index n = P.size();
  zero_leading(w.K, n);
  auto K = w.K.topLeftCorner(n, n);
  K = -w.HA.topLeftCorner(n, n);
  if (!load.follower) return;
  const Matrix3d Sf = skew(F.head<3>()), Sm = skew(F.tail<3>());
  for (Eigen::Index c = 0; c < n; ++c) {
    const Vector3d jr = P.J.col(c).tail<3>();
    const Vector3d tf = Sf * jr, tm = Sm * jr;
    K.col(c).noalias() += P.J.leftCols(n).topRows<3>().transpose() * tf;
    K.col(c).noalias() += P.J.leftCols(n).bottomRows<3>().transpose() * tm;
  }
}

}  // namespace seflex::mbd::detail
