// The full inertia of an AIC flexible body by sums over the FE nodes (formulation 2.4, extended to
// internal modes as 2.5 through the body-local maps Zx, Tx). This was the production path before the
// inertia invariants; it stays as the reference the invariant evaluation is tested against.
//   FE node accelerations in B:  Xdd = N (a_b - c) + c_FE,   N = Psi Tx + Phi_rig^FE(U) Zx
//   f_w = N^T (M_FE Xdd + gyro),  gyro_i = omega_i x J_i omega_i (rotary inertia of FE node i)
#include <Eigen/Dense>

#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/bodies/aic_element.hpp"
#include "bodies/aic_inertia_detail.hpp"

namespace seflex::mbd {

using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using so3::skew;

namespace {

void full_nodal(const AicElement& e, const AicKinematics& kin, const VectorXd& w, const VectorXd& ab, bool want,
                bool elastic_gyro, MatrixXd& Mw, MatrixXd& Cw, MatrixXd& Kw, VectorXd& fw, double& kinetic) {
  const int n = e.n;
  const auto nfe = static_cast<int>(e.X.cols());
  const MatrixXd Zr = kin.Zx.middleRows<3>(3);
  const Vector3d Om = Zr * w;
  const MatrixXd Tx = transfer_matrix(e, kin);
  const VectorXd xid = Tx * w;
  const VectorXd U = e.Psi * kin.xi;
  const VectorXd Ud = e.Psi * xid;
  const MatrixXd PT = e.Psi * Tx;  // 6nfe x n
  MatrixXd Nm = PT;
  for (int i = 0; i < nfe; ++i) {
    const Vector3d pi = e.X.col(i) + U.segment<3>(6 * i);
    Nm.middleRows<3>(6 * i) += kin.Zx.topRows<3>() - skew(pi) * Zr;
    Nm.middleRows<3>(6 * i + 3) += Zr;
  }
  // Quadratic-velocity accelerations at the interfaces (c) and at the FE nodes (c_FE).
  VectorXd c;
  detail::interface_velocity_accelerations(e, kin.xi, Om, xid, c);
  VectorXd cfe(6 * nfe), gyro = VectorXd::Zero(6 * nfe);
  for (int i = 0; i < nfe; ++i) {
    const Vector3d pi = e.X.col(i) + U.segment<3>(6 * i);
    cfe.segment<3>(6 * i) = Om.cross(Om.cross(pi)) + 2.0 * Om.cross(Ud.segment<3>(6 * i));
    cfe.segment<3>(6 * i + 3) = Om.cross(Ud.segment<3>(6 * i + 3));
    const Vector3d udr = Ud.segment<3>(6 * i + 3), wi = Om + udr;
    gyro.segment<3>(6 * i + 3) = wi.cross(e.J_node[i] * wi);
    if (!elastic_gyro) gyro.segment<3>(6 * i + 3) -= udr.cross(e.J_node[i] * udr);
  }
  const MatrixXd MN = e.M_fe * Nm;  // 6nfe x n
  const VectorXd Xdd = Nm * (ab - c) + cfe;
  fw.noalias() = MN.transpose() * Xdd;
  fw.noalias() += Nm.transpose() * gyro;
  const VectorXd Xd = Nm * w;
  kinetic = 0.5 * Xd.dot(e.M_fe * Xd);
  if (!want) return;
  Mw.noalias() = Nm.transpose() * MN;
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
    if (!elastic_gyro) Dg.middleRows<3>(6 * i + 3) -= (skew(udr) * J - skew(J * udr)) * PT.middleRows<3>(6 * i + 3);
  }
  Cw.noalias() = MN.transpose() * Dfe + Nm.transpose() * Dg;
  Cw -= detail::times_velocity_accelerations_tangent(e, kin, Om, xid, Mw);
  Kw = (Mw * detail::stacked_skew(e, ab) - detail::stacked_skew(e, fw)) * kin.ZxL.middleRows<3>(3);
}

}  // namespace

void inertia_force_nodal(const AicElement& e, const AicKinematics& kin, const Eigen::Ref<const VectorXd>& v,
                         const Eigen::Ref<const VectorXd>& a, bool want_matrices, bool elastic_gyro, InertiaResult& out) {
  SEFLEX_DEMAND(e.has_fe_data, "the nodal inertia needs the FE recovery matrix and FE mass of superelement " + e.name);
  AicWorkspace ws;
  detail::inertia_in_world(e, kin, v, a, want_matrices ? InertiaMatrices::All : InertiaMatrices::None, out, ws, MatrixAxes::World,
                           [&](const VectorXd& w, const VectorXd& ab, InertiaMatrices want, MatrixXd& Mw, MatrixXd& Cw,
                               MatrixXd& Kw, VectorXd& fw, double& kinetic) {
                             full_nodal(e, kin, w, ab, want != InertiaMatrices::None, elastic_gyro, Mw, Cw, Kw, fw, kinetic);
                           });
}

}  // namespace seflex::mbd
