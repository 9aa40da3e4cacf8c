// FFRF-LM body kernels. Flexible: the floating-frame inertia of the FE model (the same nodal mass
// model as the AIC full inertia, formulation 2.4). With body-axis velocities
// w = [R^T dp/dt; R^T omega; dz/dt] and accelerations ab = [R^T (d2p/dt2 - g); R^T domega/dt; d2z/dt2],
// local elastic coordinates xi = V z (the superelement's CB coordinates), FE displacements U = P xi:
//   FE node velocities in B:  Xd = N(z) w,  N_i = [[I, -(X_i + U_i)~, P_t,i V], [0, I, P_r,i V]]
//   accelerations:            Xdd = N ab + c,  c_t,i = Om x (Om x p_i) + 2 Om x Ud_t,i,  c_r,i = Om x Ud_r,i
//   force (body axes):        f_w = N^T (M_fe Xdd + gyro),  gyro_i = w_i x J_i w_i,  w_i = Om + Ud_r,i
//   mass:                     M_w = N^T M_fe N
// By default from the inertia invariants (docs/inertia-invariants.md), N = [E(xi), P V]:
//   M_w = [[E^T M E, E^T M P V], [V^T P^T M E, V^T Mpp V]],  f_w = M_w ab + [E^T y; V^T P^T y],
// y = M c + gyro, the projections of detail::inertia_projections: a cost set by n, never the mesh
// (the gyroscopic moment quadratic in the elastic rotation rates is the one term left out, as in
// AIC). FfrfOptions::inertia chooses per body: the FE node sums are cheaper for small meshes and are the
// reference of the tests.
// Then rotated to world (frame rows) and the modal stiffness diag(omega^2) z (+ beta diag(omega^2)
// dz/dt) added, with the stress stiffening V^T K_G(lambda, xi) xi when the body has it
// (docs/geometric-stiffening.md; lambda = [a_o - g; alpha; Om~ Om~] of the frame, which FFRF-LM has
// as coordinates). Rigid: the rigid-body wrench about the frame origin (rigid_inertia.hpp).
#include <Eigen/Dense>

#include "ffrf/ffrf_detail.hpp"
#include "bodies/aic_inertia_detail.hpp"
#include "bodies/rigid_inertia.hpp"
#include "seflex/common/so3.hpp"

namespace seflex::mbd::detail {

using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using so3::skew;

namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

/// Body-axis inertia force fw and mass Mw (if want) from the FE node sums.
void flexible_nodal(const FfrfBody& b, const AicElement& e, const VectorXd& z, const VectorXd& v, const VectorXd& ab, bool want,
                    bool elastic_gyro, VectorXd& fw, MatrixXd& Mw, double& kinetic) {
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
    const Vector3d ud = Ud.segment<3>(6 * i + 3), wi = Om + ud;
    const Matrix3d& J = e.J_node[static_cast<std::size_t>(i)];
    gyro.segment<3>(6 * i + 3) = wi.cross(J * wi);
    if (!elastic_gyro) gyro.segment<3>(6 * i + 3) -= ud.cross(J * ud);
  }
  if (k > 0) N.rightCols(k) = b.PV;
  const VectorXd Xd = N * v;
  const VectorXd Xdd = N * ab + cfe;
  fw = N.transpose() * (e.M_fe * Xdd + gyro);
  kinetic = 0.5 * Xd.dot(e.M_fe * Xd);
  if (want) Mw = N.transpose() * (e.M_fe * N);
}

/// The same from the inertia invariants.
void flexible_invariants(const FfrfBody& b, const AicElement& e, const VectorXd& xi, const VectorXd& v, const VectorXd& ab,
                         bool want, VectorXd& fw, MatrixXd& Mw, double& kinetic, AicWorkspace& ws) {
  const int k = b.k;
  const Vector3d Om = v.segment<3>(3);
  ws.xid.noalias() = b.V * v.tail(k);
  detail::InertiaProjections pr;
  detail::inertia_projections(e, xi, ws.xid, Om, ws, pr);
  ws.sixn.noalias() = ws.PmE.transpose() * b.V;  // E^T M P V (6 x k)
  const auto& EmPV = ws.sixn;
  const Vector6d af = ab.head<6>(), vf = v.head<6>();
  fw.resize(6 + k);
  fw.head<6>().noalias() = pr.EmE * af;
  fw.head<6>().noalias() += EmPV * ab.tail(k);
  fw.head<6>() += pr.em;
  fw.tail(k).noalias() = EmPV.transpose() * af;
  fw.tail(k).noalias() += b.VMppV * ab.tail(k);
  fw.tail(k).noalias() += b.V.transpose() * ws.pm;
  const VectorXd zd = v.tail(k);
  kinetic = 0.5 * vf.dot(pr.EmE * vf) + vf.dot(EmPV * zd) + 0.5 * zd.dot(b.VMppV * zd);
  if (!want) return;
  Mw.resize(6 + k, 6 + k);
  Mw.topLeftCorner<6, 6>() = pr.EmE;
  Mw.topRightCorner(6, k) = EmPV;
  Mw.bottomLeftCorner(k, 6) = EmPV.transpose();
  Mw.bottomRightCorner(k, k) = b.VMppV;
}

void flexible(const FfrfSystem& sys, const FfrfBody& b, const AicElement& e, const Matrix3d& R, const VectorXd& z, const VectorXd& v,
              const VectorXd& ab, bool want, BodyForce& out) {
  const int k = b.k, nb = 6 + k;
  const VectorXd zd = v.tail(k);
  VectorXd fw;
  MatrixXd Mw;
  const VectorXd xi = b.V * z;
  if (b.nodal)
    flexible_nodal(b, e, z, v, ab, want, sys.options.elastic_gyro, fw, Mw, out.kinetic);
  else
    flexible_invariants(b, e, xi, v, ab, want, fw, Mw, out.kinetic, out.ws);
  out.f.resize(nb);
  out.f.head<3>() = R * fw.head<3>();
  out.f.segment<3>(3) = R * fw.segment<3>(3);
  out.f.tail(k) = fw.tail(k) + b.omega2.cwiseProduct(z + b.stiffness_damping * zd);
  out.elastic = 0.5 * z.dot(b.omega2.cwiseProduct(z));
  if (b.stiffening) {  // + V^T K_G xi, K_G from the frame's accelerations and spin and the interface deformation
    StiffeningLoads lambda;
    lambda.head<6>() = ab.head<6>();
    detail::centrifugal_load_factors(v.segment<3>(3), lambda);
    VectorXd g = VectorXd::Zero(e.n);
    out.elastic += detail::add_stress_stiffening(e, xi, lambda, g, out.ws);
    out.f.tail(k).noalias() += b.V.transpose() * g;
    // The first six load factors are the frame's body-axis accelerations: d f_z / d ab_frame = V^T [G_c xi]_{c<6}.
    if (want) Mw.bottomLeftCorner(k, 6).noalias() += b.V.transpose() * Eigen::Map<const MatrixXd>(out.ws.Gxi.data(), e.n, 6);
  }
  if (!want) return;
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
  flexible(sys, b, e, R, s.z.segment(b.z_offset, b.k), v, ab, want_mass, out);
}

}  // namespace seflex::mbd::detail
