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
// The tangents K and C (want_tangents): ffrf_body_tangents.cpp.
#include <Eigen/Dense>

#include "ffrf/ffrf_body_tangents.hpp"
#include "ffrf/ffrf_detail.hpp"
#include "bodies/aic_inertia_detail.hpp"
#include "bodies/rigid_inertia.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/superelement/symmetric_basis.hpp"

namespace seflex::mbd::detail {

using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using so3::skew;

namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

/// Body-axis inertia force w.fw and mass w.Mw (if want) from the FE node sums.
void flexible_nodal(const FfrfBody& b, const AicElement& e, bool want, bool tangents, bool elastic_gyro, Scratch& w, double& kinetic) {
  const int k = b.k, nb = 6 + k;
  const auto nfe = static_cast<int>(e.X.cols());
  const VectorXd& z = w.z;
  const VectorXd& v = w.v;
  const Vector3d Om = v.segment<3>(3);
  const auto zd = v.tail(k);
  w.U.noalias() = b.PV * z;
  w.Ud.noalias() = b.PV * zd;
  const VectorXd &U = w.U, &Ud = w.Ud;
  MatrixXd& N = w.N;
  N.setZero(6 * nfe, nb);
  w.cfe.resize(6 * nfe);
  w.gyro.setZero(6 * nfe);
  VectorXd &cfe = w.cfe, &gyro = w.gyro;
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
  w.Xd.noalias() = N * v;
  w.Xdd.noalias() = N * w.ab;
  w.Xdd += cfe;
  w.MXdd.noalias() = e.M_fe * w.Xdd;  // M_fe Xdd + gyro
  w.MXdd += gyro;
  w.fw.noalias() = N.transpose() * w.MXdd;
  w.MXd.noalias() = e.M_fe * w.Xd;
  kinetic = 0.5 * w.Xd.dot(w.MXd);
  if (!want) return;
  w.MN.noalias() = e.M_fe * N;
  w.Mw.noalias() = N.transpose() * w.MN;
  if (tangents) nodal_inertia_tangents(b, e, elastic_gyro, w);
}

/// The same from the inertia invariants.
void flexible_invariants(const FfrfBody& b, const AicElement& e, bool want, bool tangents, Scratch& w, double& kinetic,
                         AicWorkspace& ws) {
  const int k = b.k;
  const VectorXd& v = w.v;
  const VectorXd& ab = w.ab;
  VectorXd& fw = w.fw;
  const Vector3d Om = v.segment<3>(3);
  ws.xid.noalias() = b.V * v.tail(k);
  detail::InertiaProjections pr;
  detail::inertia_projections(e, w.xi, ws.xid, Om, ws, pr);
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
  const auto zd = v.tail(k);
  w.t6.noalias() = EmPV * zd;
  w.tk.noalias() = b.VMppV * zd;
  kinetic = 0.5 * vf.dot(pr.EmE * vf) + vf.dot(w.t6) + 0.5 * zd.dot(w.tk);
  if (!want) return;
  MatrixXd& Mw = w.Mw;
  Mw.resize(6 + k, 6 + k);
  Mw.topLeftCorner<6, 6>() = pr.EmE;
  Mw.topRightCorner(6, k) = EmPV;
  Mw.bottomLeftCorner(k, 6) = EmPV.transpose();
  Mw.bottomRightCorner(k, k) = b.VMppV;
  if (tangents) invariant_inertia_tangents(b, e, pr, w, ws);
}

/// The body's force and (if want) mass from its body-axis velocities out.scratch.v, accelerations
/// out.scratch.ab and modal coordinates out.scratch.z.
void flexible(const FfrfSystem& sys, const FfrfBody& b, const AicElement& e, const Matrix3d& R, bool want, bool tangents,
              BodyForce& out) {
  const int k = b.k, nb = 6 + k;
  Scratch& w = out.scratch;
  const VectorXd& z = w.z;
  const auto zd = w.v.tail(k);
  w.xi.noalias() = b.V * z;
  if (b.nodal)
    flexible_nodal(b, e, want, tangents, sys.options.elastic_gyro, w, out.kinetic);
  else
    flexible_invariants(b, e, want, tangents, w, out.kinetic, out.ws);
  const VectorXd& fw = w.fw;
  MatrixXd& Mw = w.Mw;
  out.f.resize(nb);
  out.f.head<3>() = R * fw.head<3>();
  out.f.segment<3>(3) = R * fw.segment<3>(3);
  out.f.tail(k) = fw.tail(k) + b.omega2.cwiseProduct(z + b.stiffness_damping * zd);
  out.elastic = 0.5 * z.dot(b.omega2.cwiseProduct(z));
  if (b.stiffening) {  // + V^T K_G xi, K_G from the frame's accelerations and spin and the interface deformation
    StiffeningLoads lambda;
    lambda.head<6>() = w.ab.head<6>();
    detail::centrifugal_load_factors(w.v.segment<3>(3), lambda);
    w.g.setZero(e.n);
    out.elastic += detail::add_stress_stiffening(e, w.xi, lambda, w.g, out.ws);
    out.f.tail(k).noalias() += b.V.transpose() * w.g;
    // The first six load factors are the frame's body-axis accelerations: d f_z / d ab_frame = V^T [G_c xi]_{c<6}.
    if (want) Mw.bottomLeftCorner(k, 6).noalias() += b.V.transpose() * detail::stiffening_inertia_products(e, out.ws).leftCols<6>();
    if (tangents) {
      // d f_z / d Om through the centrifugal load factors lambda_6.. = sym(Om~ Om~); d f_z / d z: the
      // Hessian of the stiffening potential at fixed lambda.
      const Matrix3d W = skew(w.v.segment<3>(3));
      Eigen::Matrix<double, 6, 3> dsW;
      for (int a = 0; a < 3; ++a) {
        const Matrix3d Ea = skew(Vector3d::Unit(a));
        dsW.col(a) = se::sym_components(Matrix3d(Ea * W + W * Ea));
      }
      w.n3.noalias() = detail::stiffening_inertia_products(e, out.ws).middleCols<6>(6) * dsW;
      w.Cw.block(6, 3, k, 3).noalias() += b.V.transpose() * w.n3;
      w.nn.setZero(e.n, e.n);
      add_stress_stiffening_hessian(e, out.ws, w.nn);
      w.nk.noalias() = w.nn * b.V;
      w.Kz.bottomRows(k).noalias() += b.V.transpose() * w.nk;
    }
  }
  if (tangents) {  // modal stiffness and damping
    w.Kz.bottomRows(k).diagonal() += b.omega2;
    w.Cw.bottomRightCorner(k, k).diagonal() += b.stiffness_damping * b.omega2;
  }
  if (!want) return;
  MatrixXd& Rh = w.Rh;
  Rh.setIdentity(nb, nb);
  Rh.block<3, 3>(0, 0) = R;
  Rh.block<3, 3>(3, 3) = R;
  w.RhMw.noalias() = Rh * Mw;
  out.M.noalias() = w.RhMw * Rh.transpose();
  if (tangents) tangents_to_world(R, k, w, out);
}

}  // namespace

void body_force(const FfrfSystem& sys, const FfrfState& s, int bi, bool want_mass, BodyForce& out, bool want_tangents) {
  const FfrfBody& b = sys.bodies[static_cast<std::size_t>(bi)];
  const Model& model = *sys.model;
  const Matrix3d& R = s.R_WB[static_cast<std::size_t>(bi)];
  const int nb = 6 + b.k;
  const auto vW = s.v.segment(b.coord, nb);
  const auto aW = s.vdot.segment(b.coord, nb);
  if (!b.flexible) {
    const Vector3d c = R * b.p_BoCm_B;
    const Matrix3d I = R * b.I_Cm_B * R.transpose();
    const RigidWrench rw = rigid_wrench(b.mass, c, I, vW.head<3>(), vW.segment<3>(3), aW.head<3>() - model.gravity, aW.segment<3>(3));
    out.f = rw.F;
    out.kinetic = rw.kinetic;
    out.elastic = 0.0;
    if (want_mass) out.M = rw.M6;
    if (!want_tangents) return;
    // Tangents from the wrench in body axes (the same wrench rotated: rigid_wrench is frame-covariant).
    Scratch& w = out.scratch;
    w.v.resize(6);
    w.ab.resize(6);
    w.v << R.transpose() * vW.head<3>(), R.transpose() * vW.segment<3>(3);
    w.ab << R.transpose() * (aW.head<3>() - model.gravity), R.transpose() * aW.segment<3>(3);
    const RigidWrench rb = rigid_wrench(b.mass, b.p_BoCm_B, b.I_Cm_B, w.v.head<3>(), w.v.tail<3>(), w.ab.head<3>(), w.ab.tail<3>());
    w.fw = rb.F;
    w.Mw = rb.M6;
    rigid_tangents(b.mass, b.p_BoCm_B, b.I_Cm_B, w.v.tail<3>(), w);
    tangents_to_world(R, 0, w, out);
    return;
  }
  const AicElement& e = model.superelement(model.flexible_bodies[static_cast<std::size_t>(b.model_index)].se);
  Scratch& w = out.scratch;
  w.v.resize(nb);
  w.ab.resize(nb);
  w.v << R.transpose() * vW.head<3>(), R.transpose() * vW.segment<3>(3), vW.tail(b.k);
  w.ab << R.transpose() * (aW.head<3>() - model.gravity), R.transpose() * aW.segment<3>(3), aW.tail(b.k);
  w.z = s.z.segment(b.z_offset, b.k);
  flexible(sys, b, e, R, want_mass || want_tangents, want_tangents, out);
}

}  // namespace seflex::mbd::detail
