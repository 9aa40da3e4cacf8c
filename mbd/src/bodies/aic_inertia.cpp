// Inertia of an AIC flexible body: the simplified mass Rhat M Rhat^T (formulation 2.3) and the full
// inertia with quadratic-velocity terms (2.4, 2.5) evaluated from the inertia invariants
// (docs/inertia-invariants.md), at a cost set by the reduced size n, never by the FE mesh.
//
// With N = P T + E(xi) Z (T = Tx, Z = Zx, E = E0 + E1(P xi) the FE rigid modes at the deformed
// positions), every FE-level quantity enters through two projections of an FE "load" y:
// pm = P^T y (n) and em = E^T y (6), and N^T y = T^T pm + Z^T em. The invariants give, for the mass
// pairing, PmE = P^T M E (n x 6) and EmE = E^T M E (6 x 6) at the current xi; for the field of the
// velocity-dependent accelerations c_FE (centrifugal L(W)(X + P xi), Coriolis G(Om)(P xi_dot)) and
// the nodal gyroscopic moments, pm and em as linear maps of W = Om~ Om~ (6 symmetric components)
// and Om. Then
//   f_w = N^T M N (a_b - c) + N^T (M c_FE + gyro),   M_w = N^T M N,
//   C_w = d/dw [N^T (M c_FE + gyro)] - M_w dc/dw,     K_w = rotation of the inertia force with B.
#include <Eigen/Dense>

#include "bodies/aic_inertia_detail.hpp"
#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/bodies/aic_element.hpp"
#include "seflex/superelement/symmetric_basis.hpp"

namespace seflex::mbd {

using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using so3::skew;
using se::sym_components;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix36d = Eigen::Matrix<double, 3, 6>;
using Vector9d = Eigen::Matrix<double, 9, 1>;

namespace detail {

void mass_pairing(const AicElement& e, const VectorXd& xi, const double* X, AicWorkspace& ws, Matrix6d& EmE) {
  const se::InertiaInvariants& I = e.inv;
  const Eigen::Index n = e.n;
  const StackedInvariantRows r(n);
  using Map3n = Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic>>;
  MatrixXd& PmE = ws.PmE;
  PmE = I.PmE0;
  PmE.rightCols<3>() += Map3n(X + r.HP, 3, n).transpose();
  EmE = I.E0mE0;
  const Eigen::Map<const Matrix36d> B(X + r.HE0);
  EmE.bottomRows<3>() += B;
  EmE.rightCols<3>() += B.transpose();
  Vector9d q;
  q.noalias() = Eigen::Map<const Eigen::Matrix<double, 9, Eigen::Dynamic>>(X + r.HE1, 9, n) * xi;
  EmE.bottomRightCorner<3, 3>() += Eigen::Map<const Matrix3d>(q.data());
}

void inertia_projections(const AicElement& e, const VectorXd& xi, const VectorXd& xid, const Vector3d& Om, AicWorkspace& ws,
                         InertiaProjections& pr) {
  const se::InertiaInvariants& I = e.inv;
  const Eigen::Index n = e.n;
  // Every contraction with xi and with xi_dot: two products with the stacked invariants
  // (StackedInvariantRows), read in place below.
  const StackedInvariantRows r(n);
  // (n - 6 columns: xi and xid satisfy the frame condition, AicElement::V_f.)
  ws.eta_f.noalias() = e.V_f.transpose() * xi;
  ws.t.noalias() = e.inv_by_xi * ws.eta_f;
  ws.eta_f.noalias() = e.V_f.transpose() * xid;
  ws.q.noalias() = e.inv_by_xid * ws.eta_f;
  const double* X = ws.t.data();
  const double* Y = ws.q.data();
  using Map3n = Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic>>;
  using MapN = Eigen::Map<const MatrixXd>;

  mass_pairing(e, xi, X, ws, pr.EmE);
  // Centrifugal field: pm = CLp s(W), em = CLe s(W) + [0; CLh s(W)].
  MatrixXd& CLp = ws.CLp;
  CLp = I.PmLX;
  CLp += MapN(X + r.LP, n, 6);
  Matrix6d& CLe = pr.CLe;
  CLe = I.E0mLX;
  CLe += Eigen::Map<const Matrix6d>(X + r.E0LP);
  Matrix36d& CLh = pr.CLh;
  CLh = Eigen::Map<const Matrix36d>(X + r.HLX);
  for (int s = 0; s < 6; ++s) CLh.col(s).noalias() += Map3n(X + r.HLP + 3 * n * s, 3, n) * xi;
  // Coriolis field and gyroscopic moments, linear in Om at fixed xi_dot: columns a.
  MatrixXd& GPp = ws.GPp;
  MatrixXd& GVp = ws.GVp;
  GPp = MapN(Y + r.PmGP, n, 3);
  GVp = MapN(Y + r.PgOV, n, 3);
  pr.GPe = Eigen::Map<const Eigen::Matrix<double, 6, 3>>(Y + r.E0mGP);
  pr.GVe = Eigen::Map<const Matrix3d>(Y + r.EgOV);
  for (int a = 0; a < 3; ++a) {
    ws.HGPxi[a] = Map3n(X + r.HGP + 3 * n * a, 3, n);
    pr.GPh.col(a).noalias() = ws.HGPxi[a] * xid;
  }
  Vector9d& OO = pr.OO;
  for (int b = 0; b < 3; ++b)
    for (int a = 0; a < 3; ++a) OO[a + 3 * b] = Om[a] * Om[b];
  const Matrix3d Wc = skew(Om) * skew(Om);
  const Vector6d sW = sym_components(Wc);
  VectorXd& pm = ws.pm;
  pm.noalias() = CLp * sW;
  pm.noalias() += GPp * Om;
  pm.noalias() += I.PgOO * OO;
  pm.noalias() += GVp * Om;
  Vector6d& em = pr.em;
  em.noalias() = CLe * sW;
  em.noalias() += pr.GPe * Om;
  em.tail<3>().noalias() += CLh * sW;
  em.tail<3>().noalias() += pr.GPh * Om;
  em.tail<3>().noalias() += I.EgOO * OO;
  em.tail<3>().noalias() += pr.GVe * Om;

}

void velocity_load_tangents(const AicElement& e, const Vector3d& Om, AicWorkspace& ws, const InertiaProjections& pr,
                            Eigen::Matrix<double, 6, 3>& DOe) {
  const se::InertiaInvariants& I = e.inv;
  const Eigen::Index n = e.n;
  const MatrixXd& CLp = ws.CLp;
  const Matrix6d& CLe = pr.CLe;
  const Matrix36d& CLh = pr.CLh;
  const MatrixXd& GPp = ws.GPp;
  const MatrixXd& GVp = ws.GVp;
  const Eigen::Matrix<double, 6, 3>& GPe = pr.GPe;
  const Matrix3d& GVe = pr.GVe;
  const Matrix3d& GPh = pr.GPh;
  // d/dOm_a of the velocity-dependent loads (n x 3 and 6 x 3), then d/dxi_dot (n x n and 6 x n).
  MatrixXd& DOp = ws.DOp;
  DOp.resize(n, 3);
  for (int a = 0; a < 3; ++a) {
    const Matrix3d Ea = skew(Vector3d::Unit(a));
    const Vector6d sWa = sym_components(Ea * skew(Om) + skew(Om) * Ea);
    Vector9d dOO = Vector9d::Zero();
    for (int b = 0; b < 3; ++b) {
      dOO[a + 3 * b] += Om[b];
      dOO[b + 3 * a] += Om[b];
    }
    DOp.col(a).noalias() = CLp * sWa;
    DOp.col(a) += GPp.col(a) + GVp.col(a);
    DOp.col(a).noalias() += I.PgOO * dOO;
    DOe.col(a).noalias() = CLe * sWa;
    DOe.col(a) += GPe.col(a);
    DOe.col(a).tail<3>().noalias() += CLh * sWa;
    DOe.col(a).tail<3>().noalias() += I.EgOO * dOO;
    DOe.col(a).tail<3>() += GPh.col(a) + GVe.col(a);
  }
  MatrixXd& Ap = ws.Ap;
  Ap = Om[0] * e.inv_GPV[0];
  for (int a = 1; a < 3; ++a) Ap += Om[a] * e.inv_GPV[a];
  MatrixXd& Ae = ws.Ae;
  Ae = Om[0] * I.E0mGP[0];
  for (int a = 1; a < 3; ++a) Ae += Om[a] * I.E0mGP[a];
  for (int a = 0; a < 3; ++a) Ae.bottomRows<3>() += Om[a] * (ws.HGPxi[a] + I.EgOV[a]);
}

void mass_times(const AicElement& e, const AicKinematics& kin, const Matrix6d& S, const AicWorkspace& ws, const VectorXd& v,
                VectorXd& out) {
  const MatrixXd& Z = kin.Zx;
  const MatrixXd& Q = ws.Q;
  Vector6d z, y;
  z.noalias() = Z * v;
  y.noalias() = Q.transpose() * v;
  y.noalias() += S * z;
  out.noalias() = e.inv.Mpp * v;
  out.noalias() += Q * z;
  out.noalias() += Z.transpose() * y;
}

}  // namespace detail

namespace {

/// Kw = (Mw Ab~ - Fw~) ZxL_r: the rotation of the inertia force with the frame (Ab~, Fw~: stacked
/// skew matrices of the body-axis accelerations and forces).
void configuration_tangent(const AicElement& e, const AicKinematics& kin, const MatrixXd& Mw, const VectorXd& ab,
                           const VectorXd& fw, AicWorkspace& ws, MatrixXd& Kw) {
  detail::stacked_skew(e, ab, ws.S3);
  ws.n3.noalias() = Mw * ws.S3;
  detail::stacked_skew(e, fw, ws.S3);
  ws.n3 -= ws.S3;
  Kw.noalias() = ws.n3 * kin.ZxL.middleRows<3>(3);
}

/// 1/2 w^T M w with the constant body-axis mass of the simplified inertia (formulation 2.3).
double simplified_kinetic(const AicElement& e, const VectorXd& w, AicWorkspace& ws) {
  ws.v2.noalias() = e.M * w;
  return 0.5 * w.dot(ws.v2);
}

void simplified(const AicElement& e, const AicKinematics& kin, const VectorXd& w, const VectorXd& ab, InertiaMatrices want,
                MatrixXd& Mw, MatrixXd& Cw, MatrixXd& Kw, VectorXd& fw, double& kinetic, AicWorkspace& ws) {
  fw.noalias() = e.M * ab;
  kinetic = simplified_kinetic(e, w, ws);
  if (want == InertiaMatrices::None) return;
  Mw = e.M;
  if (want == InertiaMatrices::All) Cw.setZero(e.n, e.n);
  configuration_tangent(e, kin, Mw, ab, fw, ws, Kw);
}

/// N = P T + E Z = P + D Z with D = E - P R6, R6 = [Phi_rig; 0] (T = I - R6 Z has rank-6 defect):
/// N^T M N = Mpp + Q Z + Z^T Q^T + Z^T S Z, Q = P^T M D (ws.Q), S = D^T M D (returned), from the
/// mass pairing (ws.PmE, EmE); ws.MR = Mpp R6.
Matrix6d mass_operators(const AicElement& e, const AicKinematics& kin, const Matrix6d& EmE, AicWorkspace& ws) {
  const auto nb = 6 * e.N;
  const auto& Phi = kin.Phi_rig;
  const MatrixXd& PmE = ws.PmE;
  MatrixXd& MR = ws.MR;
  MR.noalias() = e.inv.Mpp.leftCols(nb) * Phi;
  ws.Q = PmE - MR;
  Matrix6d PhiPmE, PhiMR;
  PhiPmE.noalias() = Phi.transpose() * PmE.topRows(nb);
  PhiMR.noalias() = Phi.transpose() * MR.topRows(nb);
  return EmE - PhiPmE - PhiPmE.transpose() + PhiMR;
}

/// C_w = d/dw [N^T (M c_FE + gyro)] - M_w dc/dw (formulation 2.4) with the products by Zx gathered.
/// Term by term (b: the 6N interface rows or columns, Zr = rows 3-5 of Z, A = M_w):
///   Xp = Ap + DOp Zr - (Ap_b Phi) Z,  Xe = Ae + DOe Zr - (Ae_b Phi) Z - Phi^T Xp_b   (dpm/dw, dem/dw),
///   A dc/dw = A DcOm Zr + A DcD Tx = AOm Zr + AD - (AD_b Phi) Z
///   (detail::subtract_times_velocity_accelerations_tangent, the nodal reference's form), and
///   C_w = Xp + Z^T Xe - A dc/dw. Gathered: with B = Ap - AD and P6 = Phi^T Ap_b,
///   C_w = B + L Z + Z^T Xe,  L = [0 | DOp - AOm] - B_b Phi,
///   Xe = Ae - P6 + E Z,  E = [0 | DOe - Phi^T DOp_b] - Ae_b Phi + P6_b Phi:
/// two n x 6 x n products where the terms take five (and no n x n AD, Xp apart from B).
void velocity_tangent(const AicElement& e, const AicKinematics& kin, const Vector3d& Om, const VectorXd& xid,
                      const MatrixXd& A, const Eigen::Matrix<double, 6, 3>& DOe, AicWorkspace& ws, MatrixXd& Cw) {
  const Eigen::Index nb = 6 * e.N;
  const auto& Phi = kin.Phi_rig;
  const MatrixXd& Z = kin.Zx;
  const MatrixXd& Ap = ws.Ap;
  const MatrixXd& Ae = ws.Ae;
  const MatrixXd& DOp = ws.DOp;
  // B = Ap - A DcD, AOm = A DcOm.
  MatrixXd& B = ws.Xp;
  B = Ap;
  detail::velocity_acceleration_blocks(e, kin, Om, xid, A, ws.AOm, B);
  const MatrixXd& AOm = ws.AOm;
  MatrixXd& P6 = ws.sixn;
  P6.noalias() = Phi.transpose() * Ap.topRows(nb);
  MatrixXd& L = ws.ADPhi;
  L.noalias() = B.leftCols(nb) * Phi;
  L = -L;
  L.rightCols<3>() += DOp - AOm;
  Matrix6d E;
  E.noalias() = P6.leftCols(nb) * Phi;
  E.noalias() -= Ae.leftCols(nb) * Phi;
  E.rightCols<3>() += DOe;
  E.rightCols<3>().noalias() -= Phi.transpose() * DOp.topRows(nb);
  MatrixXd& Xe = ws.Xe;
  Xe = Ae - P6;
  Xe.noalias() += E * Z;
  Cw = B;
  Cw.noalias() += L * Z;
  Cw.noalias() += Z.transpose() * Xe;
}

void full(const AicElement& e, const AicKinematics& kin, const VectorXd& w, const VectorXd& ab, InertiaMatrices want,
          MatrixXd& Mw, MatrixXd& Cw, MatrixXd& Kw, VectorXd& fw, double& kinetic, AicWorkspace& ws) {
  const se::InertiaInvariants& I = e.inv;
  const MatrixXd& Z = kin.Zx;
  const VectorXd& xi = kin.xi;
  const auto nb = 6 * e.N;
  const auto& Phi = kin.Phi_rig;  // the non-zero rows of R6 = [Phi_rig; 0]
  Vector3d Om;
  Om.noalias() = Z.middleRows<3>(3) * w;
  VectorXd& xid = ws.xid;  // Tx w = w - R6 (Zx w)
  xid = w;
  Vector6d Zw;
  Zw.noalias() = Z * w;
  xid.head(nb).noalias() -= Phi * Zw;

  detail::InertiaProjections pr;
  detail::inertia_projections(e, xi, xid, Om, ws, pr);
  const Matrix6d& EmE = pr.EmE;
  const VectorXd& pm = ws.pm;
  const Vector6d& em = pr.em;

  const Matrix6d S = mass_operators(e, kin, EmE, ws);
  const MatrixXd& Q = ws.Q;
  auto project = [&](const VectorXd& p, const Vector6d& q, VectorXd& out) {  // N^T y from P^T y, E^T y
    Vector6d r = q;
    r.noalias() -= Phi.transpose() * p.head(nb);
    out = p;
    out.noalias() += Z.transpose() * r;
  };
  auto mass_times = [&](const VectorXd& v, VectorXd& out) { detail::mass_times(e, kin, S, ws, v, out); };
  VectorXd& c = ws.c;
  detail::interface_velocity_accelerations(e, xi, Om, xid, c);
  ws.v1 = ab - c;
  mass_times(ws.v1, fw);
  project(pm, em, ws.v2);
  fw += ws.v2;
  mass_times(w, ws.v2);
  kinetic = 0.5 * w.dot(ws.v2);
  if (want == InertiaMatrices::None) return;

  MatrixXd& QZ = ws.nn;
  QZ.noalias() = Q * Z;
  Mw = I.Mpp + QZ + QZ.transpose();
  ws.sixn.noalias() = S * Z;
  Mw.noalias() += Z.transpose() * ws.sixn;
  if (want == InertiaMatrices::NoVelocityTangent) {
    configuration_tangent(e, kin, Mw, ab, fw, ws, Kw);
    return;
  }
  Eigen::Matrix<double, 6, 3> DOe;
  detail::velocity_load_tangents(e, Om, ws, pr, DOe);
  velocity_tangent(e, kin, Om, xid, Mw, DOe, ws, Cw);
  configuration_tangent(e, kin, Mw, ab, fw, ws, Kw);
}

}  // namespace

double kinetic_energy(const AicElement& e, const AicKinematics& kin, InertiaModel model, const Eigen::Ref<const VectorXd>& v,
                      AicWorkspace& ws) {
  to_body(e, kin.frame.R_WB, v, ws.w);
  if (model == InertiaModel::Simplified) return simplified_kinetic(e, ws.w, ws);
  SEFLEX_DEMAND(e.inv.present(), "full inertia needs the inertia invariants of superelement " + e.name);
  // Only the mass pairing's rows of the xi-stack (HP, HE0, HE1: the first 12 n + 18).
  const StackedInvariantRows r(e.n);
  ws.eta_f.noalias() = e.V_f.transpose() * kin.xi;
  ws.t.resize(r.by_xi);
  ws.t.head(r.LP).noalias() = e.inv_by_xi.topRows(r.LP) * ws.eta_f;
  Matrix6d EmE;
  detail::mass_pairing(e, kin.xi, ws.t.data(), ws, EmE);
  const Matrix6d S = mass_operators(e, kin, EmE, ws);
  detail::mass_times(e, kin, S, ws, ws.w, ws.v2);
  return 0.5 * ws.w.dot(ws.v2);
}

void inertia_force(const AicElement& e, const AicKinematics& kin, InertiaModel model, const Eigen::Ref<const VectorXd>& v,
                   const Eigen::Ref<const VectorXd>& a, bool want_matrices, InertiaResult& out) {
  AicWorkspace ws;
  inertia_force(e, kin, model, v, a, want_matrices, out, ws);
}

void inertia_force(const AicElement& e, const AicKinematics& kin, InertiaModel model, const Eigen::Ref<const VectorXd>& v,
                   const Eigen::Ref<const VectorXd>& a, bool want_matrices, InertiaResult& out, AicWorkspace& ws) {
  inertia_force(e, kin, model, v, a, want_matrices ? InertiaMatrices::All : InertiaMatrices::None, out, ws);
}

void inertia_force(const AicElement& e, const AicKinematics& kin, InertiaModel model, const Eigen::Ref<const VectorXd>& v,
                   const Eigen::Ref<const VectorXd>& a, InertiaMatrices want_matrices, InertiaResult& out,
                   AicWorkspace& ws, MatrixAxes axes) {
  if (model == InertiaModel::Full) {
    SEFLEX_DEMAND(e.inv.present(), "full inertia needs the inertia invariants of superelement " + e.name);
  }
  detail::inertia_in_world(e, kin, v, a, want_matrices, out, ws, axes,
                           [&](const VectorXd& w, const VectorXd& ab, InertiaMatrices want, MatrixXd& Mw, MatrixXd& Cw,
                               MatrixXd& Kw, VectorXd& fw, double& kinetic) {
                             if (model == InertiaModel::Full)
                               full(e, kin, w, ab, want, Mw, Cw, Kw, fw, kinetic, ws);
                             else
                               simplified(e, kin, w, ab, want, Mw, Cw, Kw, fw, kinetic, ws);
                           });
}

}  // namespace seflex::mbd
