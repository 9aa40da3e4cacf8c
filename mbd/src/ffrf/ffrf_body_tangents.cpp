// Analytic tangents of the FFRF-LM body forces (ffrf_body.cpp has the equations of the force): the
// body-axis velocity tangent Cw = d f_w / d w and modal configuration tangent Kz = d f_w / d z of the
// inertia, by the FE node sums or from the inertia invariants, then the world tangents of
//   f = [R f_w,t; R f_w,r; f_w,z + elastic],  w = blkdiag(R, R, I)^T v,  ab = blkdiag(R, R, I)^T (a - g):
//   C = Rh Cw Rh^T
//   K(:, p) = 0,  K(:, z) = Rh Kz,
//   K(:, pi) = Rh (Cw S(w) + Mw S(ab)) R^T - [(R f_w,t)~; (R f_w,r)~; 0],  S(x) = [x_t~; x_r~; 0]
// for the rotation increment R <- exp(dpi~) R (perturb), since d(R^T x) = (R^T x)~ R^T dpi and
// d(R y) = -(R y)~ dpi. Mw and Cw include the stress stiffening's dependence on its load factors (the
// frame's accelerations and spin), Kz the Hessian of its potential, the modal stiffness and damping
// (ffrf_body.cpp). The velocity tangent of the invariant inertia is the AIC's
// (detail::velocity_load_tangents); its z derivative contracts the same stacked invariants
// (AicElement::inv_by_xi, StackedInvariantRows) with the modes, FfrfBody::AV = inv_by_xi V, once per body.
#include <Eigen/Dense>

#include "ffrf/ffrf_body_tangents.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/superelement/symmetric_basis.hpp"

namespace seflex::mbd::detail {

using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using so3::skew;
using Vector9d = Eigen::Matrix<double, 9, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Matrix36d = Eigen::Matrix<double, 3, 6>;
using Map3n = Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic>>;
using Map9n = Eigen::Map<const Eigen::Matrix<double, 9, Eigen::Dynamic>>;

void nodal_inertia_tangents(const FfrfBody& b, const AicElement& e, bool elastic_gyro, Scratch& w) {
  const int k = b.k, nb = 6 + k;
  const auto nfe = static_cast<int>(e.X.cols());
  const Vector3d Om = w.v.segment<3>(3);
  const Matrix3d W = skew(Om);
  const Matrix3d A2 = skew(w.ab.segment<3>(3)) + W * W;
  // D = d c_FE / d w (Coriolis and centrifugal accelerations of the FE nodes), Dz = d (N ab + c_FE) / d z
  // (only the translations: the arm p_i = X_i + U_i); the arm's rotation rows of N: d N^T y / d z = -y_t~ PV_t.
  MatrixXd& D = w.D;
  MatrixXd& Dz = w.Dz;
  MatrixXd& Kz = w.Kz;
  D.setZero(6 * nfe, nb);
  Dz.setZero(6 * nfe, k);
  Kz.setZero(nb, k);
  for (int i = 0; i < nfe; ++i) {
    const Vector3d p = e.X.col(i) + w.U.segment<3>(6 * i);
    D.block<3, 3>(6 * i, 3) = -skew(Om.cross(p)) - W * skew(p) - 2.0 * skew(w.Ud.segment<3>(6 * i));
    D.block<3, 3>(6 * i + 3, 3) = -skew(w.Ud.segment<3>(6 * i + 3));
    if (k == 0) continue;
    const auto PVt = b.PV.middleRows<3>(6 * i);
    D.block(6 * i, 6, 3, k).noalias() = 2.0 * W * PVt;
    D.block(6 * i + 3, 6, 3, k).noalias() = W * b.PV.middleRows<3>(6 * i + 3);
    Dz.middleRows<3>(6 * i).noalias() = A2 * PVt;
    Kz.middleRows<3>(3).noalias() -= skew(w.MXdd.segment<3>(6 * i)) * PVt;
  }
  w.MD.noalias() = e.M_fe * D;
  for (int i = 0; i < nfe; ++i) {  // + d gyro / d w, gyro_i = w_i x J_i w_i (less the elastic part)
    const Vector3d ud = w.Ud.segment<3>(6 * i + 3), wi = Om + ud;
    const Matrix3d& J = e.J_node[static_cast<std::size_t>(i)];
    Matrix3d G = skew(wi) * J - skew(J * wi);
    w.MD.block<3, 3>(6 * i + 3, 3) += G;
    if (k == 0) continue;
    if (!elastic_gyro) G -= skew(ud) * J - skew(J * ud);
    w.MD.block(6 * i + 3, 6, 3, k).noalias() += G * b.PV.middleRows<3>(6 * i + 3);
  }
  w.Cw.noalias() = w.N.transpose() * w.MD;
  if (k == 0) return;
  w.MDz.noalias() = e.M_fe * Dz;
  Kz.noalias() += w.N.transpose() * w.MDz;
}

void invariant_inertia_tangents(const FfrfBody& b, const AicElement& e, const InertiaProjections& pr, Scratch& w,
                                AicWorkspace& ws) {
  const int k = b.k, nb = 6 + k;
  const Eigen::Index n = e.n;
  const Vector3d Om = w.v.segment<3>(3);
  const VectorXd& xi = w.xi;
  const VectorXd& xid = ws.xid;
  // Cw: d/dOm and d/dxi_dot (xi_dot = V z_dot) of em and pm, the AIC's.
  Eigen::Matrix<double, 6, 3> DOe;
  velocity_load_tangents(e, Om, ws, pr, DOe);
  MatrixXd& Cw = w.Cw;
  Cw.setZero(nb, nb);
  Cw.block<6, 3>(0, 3) = DOe;
  if (k == 0) return;
  Cw.block(6, 3, k, 3).noalias() = b.V.transpose() * ws.DOp;
  w.nk.noalias() = ws.Ap * b.V;
  Cw.bottomRightCorner(k, k).noalias() = b.V.transpose() * w.nk;
  Cw.topRightCorner(6, k).noalias() = ws.Ae * b.V;
  // Kz: f_w = [EmE af + PmE^T V azd + em; V^T (PmE af + pm)] differentiated along xi = V e_j; every
  // invariant enters linearly through X = inv_by_xi xi (dX = AV e_j) or bilinearly through X and xi.
  const StackedInvariantRows r(n);
  const double* X = ws.t.data();
  const Eigen::Matrix<double, 6, 1> af = w.ab.head<6>();
  w.Va.noalias() = b.V * w.ab.tail(k);
  const Eigen::Matrix<double, 6, 1> sW = se::sym_components(Matrix3d(skew(Om) * skew(Om)));
  MatrixXd& E1V = w.nk2;  // 9 x k: the HE1 map at X times the modes
  E1V.noalias() = Map9n(X + r.HE1, 9, n) * b.V;
  MatrixXd& LV = w.Dz;  // 3 x k: sum_s sW_s (HLP_s map at X) times the modes
  LV.setZero(3, k);
  for (int s = 0; s < 6; ++s) LV.noalias() += sW[s] * (Map3n(X + r.HLP + 3 * n * s, 3, n) * b.V);
  MatrixXd& Kz = w.Kz;
  Kz.setZero(nb, k);
  MatrixXd& Up = w.nk;  // n x k: d (PmE af + pm) / d z_j
  for (int j = 0; j < k; ++j) {
    const double* dX = b.AV.col(j).data();
    const Map3n Hd(dX + r.HP, 3, n);  // d PmE = [0, Hd^T]
    const Eigen::Map<const Matrix36d> B(dX + r.HE0);
    Matrix6d dE = Matrix6d::Zero();
    dE.bottomRows<3>() += B;
    dE.rightCols<3>() += B.transpose();
    Vector9d q = E1V.col(j);
    q.noalias() += Map9n(dX + r.HE1, 9, n) * xi;
    dE.bottomRightCorner<3, 3>() += Eigen::Map<const Matrix3d>(q.data());
    Eigen::Matrix<double, 6, 1> f6;
    f6.noalias() = dE * af;
    f6.tail<3>().noalias() += Hd * w.Va;
    f6.noalias() += Eigen::Map<const Matrix6d>(dX + r.E0LP) * sW;  // d CLe
    Vector3d h = LV.col(j);                                        // d CLh, d GPh
    h.noalias() += Eigen::Map<const Matrix36d>(dX + r.HLX) * sW;
    for (int s = 0; s < 6; ++s) h.noalias() += sW[s] * (Map3n(dX + r.HLP + 3 * n * s, 3, n) * xi);
    for (int a = 0; a < 3; ++a) h.noalias() += Om[a] * (Map3n(dX + r.HGP + 3 * n * a, 3, n) * xid);
    f6.tail<3>() += h;
    Kz.col(j).head<6>() = f6;
    Up.col(j).noalias() = Hd.transpose() * af.tail<3>();
    Up.col(j).noalias() += Eigen::Map<const MatrixXd>(dX + r.LP, n, 6) * sW;  // d CLp
  }
  Kz.bottomRows(k).noalias() = b.V.transpose() * Up;
}

void rigid_tangents(double m, const Vector3d& c, const Matrix3d& I, const Vector3d& Om, Scratch& w) {
  const Matrix3d dFt = m * (-skew(Om.cross(c)) - skew(Om) * skew(c));
  w.Cw.setZero(6, 6);
  w.Cw.block<3, 3>(0, 3) = dFt;
  w.Cw.block<3, 3>(3, 3) = skew(Om) * I - skew(I * Om) + skew(c) * dFt;
  w.Kz.resize(6, 0);
}

void tangents_to_world(const Matrix3d& R, int k, Scratch& w, BodyForce& out) {
  const int nb = 6 + k;
  MatrixXd& Rh = w.Rh;
  Rh.setIdentity(nb, nb);
  Rh.block<3, 3>(0, 0) = R;
  Rh.block<3, 3>(3, 3) = R;
  w.RhC.noalias() = Rh * w.Cw;
  out.C.noalias() = w.RhC * Rh.transpose();
  MatrixXd& S = w.Snb;  // Cw S(w) + Mw S(ab)
  S.noalias() = w.Cw.leftCols<3>() * skew(w.v.head<3>());
  S.noalias() += w.Cw.middleCols<3>(3) * skew(w.v.segment<3>(3));
  S.noalias() += w.Mw.leftCols<3>() * skew(w.ab.head<3>());
  S.noalias() += w.Mw.middleCols<3>(3) * skew(w.ab.segment<3>(3));
  w.RhC.leftCols<3>().noalias() = Rh * S;
  out.K.setZero(nb, nb);
  out.K.middleCols<3>(3).noalias() = w.RhC.leftCols<3>() * R.transpose();
  out.K.block<3, 3>(0, 3) -= skew(R * w.fw.head<3>());
  out.K.block<3, 3>(3, 3) -= skew(R * w.fw.segment<3>(3));
  if (k > 0) out.K.rightCols(k).noalias() = Rh * w.Kz;
}

}  // namespace seflex::mbd::detail
