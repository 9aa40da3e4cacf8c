// FFRF-LM body kernels. Flexible: the FE-node form of the floating-frame inertia (the same nodal
// mass model as the AIC full inertia, formulation 2.4): with body-axis velocities
// w = [R^T dp/dt; R^T omega; dz/dt] and accelerations ab = [R^T (d2p/dt2 - g); R^T domega/dt; d2z/dt2],
//   FE node velocities in B:  Xd = N(z) w,  N_i = [[I, -(X_i + U_i)~, PV_t,i], [0, I, PV_r,i]],  U = PV z
//   accelerations:            Xdd = N ab + c,  c_t,i = Om x (Om x p_i) + 2 Om x Ud_t,i,  c_r,i = Om x Ud_r,i
//   force (body axes):        f_w = N^T (M_fe Xdd + gyro),  gyro_i = w_i x J_i w_i,  w_i = Om + Ud_r,i
//   mass:                     M_w = N^T M_fe N   (the inertia invariants, summed at the current z)
// then rotated to world (frame rows) and the modal stiffness diag(omega^2) z (+ beta diag(omega^2) dz/dt)
// added. Rigid: the rigid-body wrench about the frame origin (rigid_inertia.hpp).
#include <Eigen/Dense>

#include "ffrf/ffrf_detail.hpp"
#include "bodies/rigid_inertia.hpp"
#include "seflex/common/so3.hpp"

namespace seflex::mbd::detail {

using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using so3::skew;

namespace {

void flexible(const FfrfBody& b, const AicElement& e, const Matrix3d& R, const VectorXd& z, const VectorXd& v,
              const VectorXd& ab, bool want, BodyForce& out) {
  const int k = b.k, nb = 6 + k;
  const auto nfe = static_cast<int>(e.X.cols());
  const Vector3d Om = v.segment<3>(3);
  const VectorXd zd = v.tail(k);
  const VectorXd U = b.PV * z, Ud = b.PV * zd;
  MatrixXd N = MatrixXd::Zero(6 * nfe, nb);
  VectorXd cfe(6 * nfe), gyro = VectorXd::Zero(6 * nfe);
  for (int i = 0; i < nfe; ++i) {
    const Vector3d pi = e.X.col(i) + U.segment<3>(6 * i);
    N.block<3, 3>(6 * i, 0).setIdentity();
    N.block<3, 3>(6 * i, 3) = -skew(pi);
    N.block<3, 3>(6 * i + 3, 3).setIdentity();
    cfe.segment<3>(6 * i) = Om.cross(Om.cross(pi)) + 2.0 * Om.cross(Ud.segment<3>(6 * i));
    cfe.segment<3>(6 * i + 3) = Om.cross(Ud.segment<3>(6 * i + 3));
    const Vector3d wi = Om + Ud.segment<3>(6 * i + 3);
    gyro.segment<3>(6 * i + 3) = wi.cross(e.J_node[static_cast<std::size_t>(i)] * wi);
  }
  if (k > 0) N.rightCols(k) = b.PV;
  const VectorXd Xd = N * v;
  const VectorXd Xdd = N * ab + cfe;
  const VectorXd fw = N.transpose() * (e.M_fe * Xdd + gyro);
  out.kinetic = 0.5 * Xd.dot(e.M_fe * Xd);
  out.f.resize(nb);
  out.f.head<3>() = R * fw.head<3>();
  out.f.segment<3>(3) = R * fw.segment<3>(3);
  out.f.tail(k) = fw.tail(k) + b.omega2.cwiseProduct(z + b.stiffness_damping * zd);
  out.elastic = 0.5 * z.dot(b.omega2.cwiseProduct(z));
  if (!want) return;
  const MatrixXd Mw = N.transpose() * (e.M_fe * N);
  MatrixXd Rh = MatrixXd::Identity(nb, nb);
  Rh.block<3, 3>(0, 0) = R;
  Rh.block<3, 3>(3, 3) = R;
  out.M = Rh * Mw * Rh.transpose();
}

}  // namespace

void body_force(const FfrfSystem& sys, const FfrfState& s, int bi, bool want_mass, BodyForce& out) {
  const FfrfBody& b = sys.bodies[static_cast<std::size_t>(bi)];
  const Model& model = *sys.model;
  const Matrix3d& R = s.R_WB[static_cast<std::size_t>(bi)];
  const int nb = 6 + b.k;
  const VectorXd vW = s.v.segment(b.coord, nb), aW = s.vdot.segment(b.coord, nb);
  if (!b.flexible) {
    const Vector3d c = R * b.p_BoCm_B;
    const Matrix3d I = R * b.I_Cm_B * R.transpose();
    const RigidWrench rw = rigid_wrench(b.mass, c, I, vW.head<3>(), vW.segment<3>(3), aW.head<3>() - model.gravity, aW.segment<3>(3));
    out.f = rw.F;
    out.kinetic = rw.kinetic;
    out.elastic = 0.0;
    if (want_mass) out.M = rw.M6;
    return;
  }
  const AicElement& e = model.superelement(model.flexible_bodies[static_cast<std::size_t>(b.model_index)].se);
  VectorXd v(nb), ab(nb);
  v << R.transpose() * vW.head<3>(), R.transpose() * vW.segment<3>(3), vW.tail(b.k);
  ab << R.transpose() * (aW.head<3>() - model.gravity), R.transpose() * aW.segment<3>(3), aW.tail(b.k);
  flexible(b, e, R, s.z.segment(b.z_offset, b.k), v, ab, want_mass, out);
}

}  // namespace seflex::mbd::detail
