#pragma once
// Pieces of the AIC inertia shared by the invariant evaluation (aic_inertia.cpp) and the nodal
// reference (aic_inertia_nodal.cpp): interface-level terms that never touch the FE mesh.
#include <Eigen/Core>

#include "seflex/common/so3.hpp"
#include "seflex/mbd/aic_element.hpp"

namespace seflex::mbd::detail {

/// n x 3: the skew matrices of the 2N 3-vectors of y stacked (zero on the modal rows).
inline Eigen::MatrixXd stacked_skew(const AicElement& e, const Eigen::VectorXd& y) {
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(e.n, 3);
  for (int i = 0; i < 2 * e.N; ++i) S.middleRows<3>(3 * i) = so3::skew(y.segment<3>(3 * i));
  return S;
}

/// Quadratic-velocity accelerations of the interface nodes (formulation 2.4 item 2), body axes:
/// c_j = [Om x (Om x s_j) + 2 Om x u_dot_j;  Om x theta_dot_j], s_j = x_j + u_j; zero on eta.
inline void interface_velocity_accelerations(const AicElement& e, const Eigen::VectorXd& xi, const Eigen::Vector3d& Om,
                                             const Eigen::VectorXd& xid, Eigen::VectorXd& c) {
  c.setZero(e.n);
  for (int j = 0; j < e.N; ++j) {
    const Eigen::Vector3d s = e.x[static_cast<std::size_t>(j)] + xi.segment<3>(6 * j);
    c.segment<3>(6 * j) = Om.cross(Om.cross(s)) + 2.0 * Om.cross(xid.segment<3>(6 * j));
    c.segment<3>(6 * j + 3) = Om.cross(xid.segment<3>(6 * j + 3));
  }
}

/// A * dc/dw for an n-column matrix A, with Om = Zr w and xid = Tx w (formulation 2.4 item 2):
/// dc/dw = DcOm Zr + DcD Tx, DcD block-diagonal (2 Om~ on translations, Om~ on rotations), so the
/// product costs O(rows n) plus the rank-6 form of Tx = I - [Phi_rig; 0] Zx.
inline Eigen::MatrixXd times_velocity_accelerations_tangent(const AicElement& e, const AicKinematics& kin,
                                                            const Eigen::Vector3d& Om, const Eigen::VectorXd& xid,
                                                            const Eigen::MatrixXd& A) {
  using so3::skew;
  const Eigen::Matrix3d W = skew(Om);
  Eigen::MatrixXd AOm = Eigen::MatrixXd::Zero(A.rows(), 3);  // A DcOm
  Eigen::MatrixXd AD = Eigen::MatrixXd::Zero(A.rows(), e.n);  // A DcD
  for (int j = 0; j < e.N; ++j) {
    const Eigen::Vector3d s = e.x[static_cast<std::size_t>(j)] + kin.xi.segment<3>(6 * j);
    const Eigen::Vector3d ud = xid.segment<3>(6 * j), thd = xid.segment<3>(6 * j + 3);
    AOm.noalias() += A.middleCols<3>(6 * j) * (-skew(Om.cross(s)) - W * skew(s) - 2.0 * skew(ud));
    AOm.noalias() -= A.middleCols<3>(6 * j + 3) * skew(thd);
    AD.middleCols<3>(6 * j).noalias() = 2.0 * A.middleCols<3>(6 * j) * W;
    AD.middleCols<3>(6 * j + 3).noalias() = A.middleCols<3>(6 * j + 3) * W;
  }
  Eigen::MatrixXd out = AOm * kin.Zx.middleRows<3>(3);
  out += AD;
  out.noalias() -= (AD.leftCols(6 * e.N) * kin.Phi_rig) * kin.Zx;
  return out;
}

/// Evaluate an inertia model in body axes and rotate the result to world components:
/// body(w, ab, want, Mw, Cw, Kw, fw, kinetic) with w, ab the body-axis velocities and accelerations.
template <class BodyInertia>
void inertia_in_world(const AicElement& e, const AicKinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& v,
                      const Eigen::Ref<const Eigen::VectorXd>& a, bool want_matrices, InertiaResult& out,
                      BodyInertia&& body) {
  const Eigen::Matrix3d& R = kin.frame.R_WB;
  const Eigen::VectorXd w = to_body(e, R, v);
  const Eigen::VectorXd ab = to_body(e, R, a);
  Eigen::VectorXd fw(e.n);
  Eigen::MatrixXd Mw, Cw, Kw;
  body(w, ab, want_matrices, Mw, Cw, Kw, fw, out.kinetic);
  out.f = to_world(e, R, fw);
  if (!want_matrices) return;
  out.Mt = to_world_matrix(e, R, Mw);
  out.Ct = to_world_matrix(e, R, Cw);
  out.Kt = to_world_matrix(e, R, Kw);
}

}  // namespace seflex::mbd::detail
