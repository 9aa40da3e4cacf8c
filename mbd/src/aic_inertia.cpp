// Inertia of an AIC flexible body: the simplified mass Rhat M Rhat^T (formulation 2.3) and the full
// nodal inertia with quadratic-velocity terms (2.4), extended to internal modes (2.5) through the
// body-local maps Zx, Tx:
//   FE node accelerations in B:  Xdd = N (a_b - c) + c_FE,   N = Psi Tx + Phi_rig^FE(U) Zx
//   f_w = N^T (M_FE Xdd + gyro),  gyro_i = omega_i x J_i omega_i (rotary inertia of FE node i)
#include <Eigen/Dense>

#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/aic_element.hpp"

namespace seflex::mbd {

using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using so3::skew;

namespace {

MatrixXd stacked_skew(const AicElement& e, const VectorXd& y) {
  MatrixXd S = MatrixXd::Zero(e.n, 3);
  for (int i = 0; i < 2 * e.N; ++i) S.middleRows<3>(3 * i) = skew(y.segment<3>(3 * i));
  return S;
}

void simplified(const AicElement& e, const AicKinematics& kin, const VectorXd& w, const VectorXd& ab, bool want,
                MatrixXd& Mw, MatrixXd& Cw, MatrixXd& Kw, VectorXd& fw, double& kinetic) {
  fw.noalias() = e.M * ab;
  kinetic = 0.5 * w.dot(e.M * w);
  if (!want) return;
  Mw = e.M;
  Cw = MatrixXd::Zero(e.n, e.n);
  Kw = (e.M * stacked_skew(e, ab) - stacked_skew(e, fw)) * kin.ZxL.middleRows<3>(3);
}

void full(const AicElement& e, const AicKinematics& kin, const VectorXd& w, const VectorXd& ab, bool want,
          MatrixXd& Mw, MatrixXd& Cw, MatrixXd& Kw, VectorXd& fw, double& kinetic) {
  const int N = e.N, n = e.n;
  const auto nfe = static_cast<int>(e.X.cols());
  const MatrixXd Zr = kin.Zx.middleRows<3>(3);
  const Vector3d Om = Zr * w;
  const VectorXd xid = kin.Tx * w;
  const VectorXd U = e.Psi * kin.xi;
  const VectorXd Ud = e.Psi * xid;
  const MatrixXd PT = e.Psi * kin.Tx;  // 6nfe x n
  MatrixXd Nm = PT;
  for (int i = 0; i < nfe; ++i) {
    const Vector3d pi = e.X.col(i) + U.segment<3>(6 * i);
    Nm.middleRows<3>(6 * i) += kin.Zx.topRows<3>() - skew(pi) * Zr;
    Nm.middleRows<3>(6 * i + 3) += Zr;
  }
  // Quadratic-velocity accelerations at the interfaces (c) and at the FE nodes (c_FE).
  VectorXd c = VectorXd::Zero(n);
  for (int j = 0; j < N; ++j) {
    const Vector3d s = e.x[j] + kin.xi.segment<3>(6 * j);
    c.segment<3>(6 * j) = Om.cross(Om.cross(s)) + 2.0 * Om.cross(xid.segment<3>(6 * j));
    c.segment<3>(6 * j + 3) = Om.cross(xid.segment<3>(6 * j + 3));
  }
  VectorXd cfe(6 * nfe), gyro = VectorXd::Zero(6 * nfe);
  for (int i = 0; i < nfe; ++i) {
    const Vector3d pi = e.X.col(i) + U.segment<3>(6 * i);
    cfe.segment<3>(6 * i) = Om.cross(Om.cross(pi)) + 2.0 * Om.cross(Ud.segment<3>(6 * i));
    cfe.segment<3>(6 * i + 3) = Om.cross(Ud.segment<3>(6 * i + 3));
    const Vector3d wi = Om + Ud.segment<3>(6 * i + 3);
    gyro.segment<3>(6 * i + 3) = wi.cross(e.J_node[i] * wi);
  }
  const MatrixXd MN = e.M_fe * Nm;  // 6nfe x n
  const VectorXd Xdd = Nm * (ab - c) + cfe;
  fw.noalias() = MN.transpose() * Xdd;
  fw.noalias() += Nm.transpose() * gyro;
  const VectorXd Xd = Nm * w;
  kinetic = 0.5 * Xd.dot(e.M_fe * Xd);
  if (!want) return;
  Mw.noalias() = Nm.transpose() * MN;
  // d c / d w
  MatrixXd DcOm = MatrixXd::Zero(n, 3), DcD = MatrixXd::Zero(n, n);
  for (int j = 0; j < N; ++j) {
    const Vector3d s = e.x[j] + kin.xi.segment<3>(6 * j);
    const Vector3d ud = xid.segment<3>(6 * j), thd = xid.segment<3>(6 * j + 3);
    DcOm.middleRows<3>(6 * j) = -skew(Om.cross(s)) - skew(Om) * skew(s) - 2.0 * skew(ud);
    DcOm.middleRows<3>(6 * j + 3) = -skew(thd);
    DcD.block<3, 3>(6 * j, 6 * j) = 2.0 * skew(Om);
    DcD.block<3, 3>(6 * j + 3, 6 * j + 3) = skew(Om);
  }
  const MatrixXd Dc = DcOm * Zr + DcD * kin.Tx;
  MatrixXd Dfe(6 * nfe, n);  // d(M cfe + gyro)/dw before the N^T projection: first d cfe/dw, gyro separately
  MatrixXd Dg = MatrixXd::Zero(6 * nfe, n);
  for (int i = 0; i < nfe; ++i) {
    const Vector3d pi = e.X.col(i) + U.segment<3>(6 * i);
    const Vector3d udt = Ud.segment<3>(6 * i), udr = Ud.segment<3>(6 * i + 3);
    Dfe.middleRows<3>(6 * i) = (-skew(Om.cross(pi)) - skew(Om) * skew(pi) - 2.0 * skew(udt)) * Zr +
                               2.0 * skew(Om) * PT.middleRows<3>(6 * i);
    Dfe.middleRows<3>(6 * i + 3) = -skew(udr) * Zr + skew(Om) * PT.middleRows<3>(6 * i + 3);
    const Vector3d wi = Om + udr;
    const Matrix3d& J = e.J_node[i];
    Dg.middleRows<3>(6 * i + 3) = (skew(wi) * J - skew(J * wi)) * (Zr + PT.middleRows<3>(6 * i + 3));
  }
  Cw.noalias() = MN.transpose() * Dfe + Nm.transpose() * Dg;
  Cw.noalias() -= Mw * Dc;
  Kw = (Mw * stacked_skew(e, ab) - stacked_skew(e, fw)) * kin.ZxL.middleRows<3>(3);
}

}  // namespace

void inertia_force(const AicElement& e, const AicKinematics& kin, InertiaModel model, const Eigen::Ref<const VectorXd>& v,
                   const Eigen::Ref<const VectorXd>& a, bool want_matrices, InertiaResult& out) {
  const Matrix3d& R = kin.frame.R_WB;
  const VectorXd w = to_body(e, R, v);
  const VectorXd ab = to_body(e, R, a);
  VectorXd fw(e.n);
  MatrixXd Mw, Cw, Kw;
  if (model == InertiaModel::Full) {
    SEFLEX_DEMAND(e.has_fe_data, "full inertia needs the FE recovery matrix and FE mass of superelement " + e.name);
    full(e, kin, w, ab, want_matrices, Mw, Cw, Kw, fw, out.kinetic);
  } else {
    simplified(e, kin, w, ab, want_matrices, Mw, Cw, Kw, fw, out.kinetic);
  }
  out.f = to_world(e, R, fw);
  if (!want_matrices) return;
  out.Mt = to_world_matrix(e, R, Mw);
  out.Ct = to_world_matrix(e, R, Cw);
  out.Kt = to_world_matrix(e, R, Kw);
}

}  // namespace seflex::mbd
