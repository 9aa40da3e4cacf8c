#pragma once
// Pieces of the AIC inertia shared by the invariant evaluation (aic_inertia.cpp) and the nodal
// reference (aic_inertia_nodal.cpp): interface-level terms that never touch the FE mesh.
#include <Eigen/Core>

#include "seflex/common/so3.hpp"
#include "seflex/mbd/bodies/aic_element.hpp"

namespace seflex::mbd::detail {

/// n x 3: the skew matrices of the 2N 3-vectors of y stacked (zero on the modal rows).
inline void stacked_skew(const AicElement& e, const Eigen::VectorXd& y, Eigen::MatrixXd& S) {
  S.setZero(e.n, 3);
  for (int i = 0; i < 2 * e.N; ++i) S.middleRows<3>(3 * i) = so3::skew(y.segment<3>(3 * i));
}
inline Eigen::MatrixXd stacked_skew(const AicElement& e, const Eigen::VectorXd& y) {
  Eigen::MatrixXd S;
  stacked_skew(e, y, S);
  return S;
}

/// Elastic force f (world) and, when Kt != nullptr, its tangent, of a local elastic force g(xi) the
/// caller left in ws.g, with derivative H = dg/dxi (n x n), at kin.xi: f_w = Tx^T g (formulation 2.2, 3).
/// elastic_force uses g = K xi; elastic_force_stiffened adds the stress stiffening K_G xi.
void elastic_force_of_local(const AicElement& e, const AicKinematics& kin, TangentModel tangent,
                                const Eigen::MatrixXd& H, Eigen::VectorXd& f, Eigen::MatrixXd* Kt, AicWorkspace& ws,
                                MatrixAxes axes = MatrixAxes::World);

/// The FE-level projections of the full inertia at local coordinates xi, local elastic velocities
/// xid and angular velocity Om (body axes), from the inertia invariants (docs/inertia-invariants.md):
/// with P the recovery basis, E = E0 + E1(P xi) the FE rigid modes about the frame origin at the
/// deformed positions and y = M c_FE + gyro the FE load of the velocity-dependent accelerations,
///   ws.PmE = P^T M E (n x 6),  EmE = E^T M E,  ws.pm = P^T y (n),  em = E^T y (6),
/// plus the pieces the gyroscopic tangent reuses (centrifugal maps CL*, Coriolis and gyroscopic
/// columns G*, Om Om^T). Cost O(n^2), never the mesh. Used by the AIC full inertia and by FFRF-LM.
struct InertiaProjections {
  Eigen::Matrix<double, 6, 6> EmE, CLe;
  Eigen::Matrix<double, 3, 6> CLh;
  Eigen::Matrix<double, 6, 3> GPe;
  Eigen::Matrix3d GVe, GPh;
  Eigen::Matrix<double, 9, 1> OO;
  Eigen::Matrix<double, 6, 1> em;
};
/// The mass pairing at xi from the contracted xi-stack X (StackedInvariantRows HP, HE0, HE1):
/// ws.PmE = P^T M E (n x 6) and EmE = E^T M E.
void mass_pairing(const AicElement& e, const Eigen::VectorXd& xi, const double* X, AicWorkspace& ws,
                  Eigen::Matrix<double, 6, 6>& EmE);
/// out = N^T M N v = Mpp v + Q Z v + Z^T (Q^T v + S Z v), with ws.Q and S of the mass operators.
void mass_times(const AicElement& e, const AicKinematics& kin, const Eigen::Matrix<double, 6, 6>& S, const AicWorkspace& ws,
                const Eigen::VectorXd& v, Eigen::VectorXd& out);
void inertia_projections(const AicElement& e, const Eigen::VectorXd& xi, const Eigen::VectorXd& xid,
                         const Eigen::Vector3d& Om, AicWorkspace& ws, InertiaProjections& pr);
/// The derivatives of the velocity-dependent projections pm = P^T y, em = E^T y w.r.t. Om (ws.DOp, n x 3;
/// DOe, 6 x 3) and w.r.t. xi_dot (ws.Ap, n x n; ws.Ae, 6 x n), at fixed xi, after inertia_projections at the
/// same state (reads its pr and ws.CLp, GPp, GVp, HGPxi). Used by the AIC full inertia's C_w and by FFRF-LM.
void velocity_load_tangents(const AicElement& e, const Eigen::Vector3d& Om, AicWorkspace& ws, const InertiaProjections& pr,
                            Eigen::Matrix<double, 6, 3>& DOe);

/// g += the stress-stiffening force of the 12 inertia load cases scaled by lambda and of the interface
/// deformation xi_b with its foreshortening (aic_stiffening.cpp, docs/geometric-stiffening.md); returns
/// its potential V_G. Leaves U_i xi in ws.Uxi, [lambda; xi_b + s] in ws.mu and W mu in ws.Wmu, b and s
/// in ws.fb, ws.fs. Used by the AIC body and by FFRF-LM.
double add_stress_stiffening(const AicElement& e, const Eigen::VectorXd& xi, const StiffeningLoads& lambda, Eigen::VectorXd& g,
                           AicWorkspace& ws);
/// [G_c xi]_{c<12} (n x 12, the inertia cases), after add_stress_stiffening at the same state: formed
/// from ws.Uxi at the first call (the mass and gyroscopic tangents need it, the force does not), kept
/// in ws.Gxi.
Eigen::Map<const Eigen::MatrixXd> stiffening_inertia_products(const AicElement& e, AicWorkspace& ws);
/// H (n x n) += the Hessian of V_G in xi at fixed lambda (sum_c mu_c G_c + Gb E^T + E Gb^T + Gb Kbb^+ Gb^T),
/// after add_stress_stiffening at the same state (reads ws.Uxi and ws.Wmu). Used by the AIC body
/// and by FFRF-LM.
void add_stress_stiffening_hessian(const AicElement& e, AicWorkspace& ws, Eigen::MatrixXd& H);
/// Mt (world, or body axes with MatrixAxes::Body) += d f / d a of the stiffening force through its first six load factors, the frame's
/// accelerations (a rank-6, unsymmetric term; after add_stress_stiffening at the same state, whose
/// case products it reads). The load factors' velocity dependence (Om, c) stays out of C.
void add_stiffening_mass_tangent(const AicElement& e, const AicKinematics& kin, AicWorkspace& ws, Eigen::MatrixXd& Mt,
                                 MatrixAxes axes = MatrixAxes::World);
/// The last six load factors: the symmetric components of Om~ Om~ (body axes).
void centrifugal_load_factors(const Eigen::Vector3d& Om, StiffeningLoads& lambda);

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

/// The parts of A * dc/dw (formulation 2.4 item 2) that do not pass through Tx's rank-6 term, with
/// Om = Zr w and xid = Tx w: dc/dw = DcOm Zr + DcD Tx, DcD block-diagonal (2 Om~ on the translations,
/// Om~ on the rotations, zero on eta). AOm = A DcOm (rows x 3); out -= A DcD, block by block.
inline void velocity_acceleration_blocks(const AicElement& e, const AicKinematics& kin, const Eigen::Vector3d& Om,
                                         const Eigen::VectorXd& xid, const Eigen::MatrixXd& A, Eigen::MatrixXd& AOm,
                                         Eigen::MatrixXd& out) {
  using so3::skew;
  const Eigen::Matrix3d W = skew(Om);
  AOm.setZero(A.rows(), 3);
  for (int j = 0; j < e.N; ++j) {
    const Eigen::Vector3d s = e.x[static_cast<std::size_t>(j)] + kin.xi.segment<3>(6 * j);
    const Eigen::Vector3d ud = xid.segment<3>(6 * j), thd = xid.segment<3>(6 * j + 3);
    const Eigen::Matrix3d Bt = -skew(Om.cross(s)) - W * skew(s) - 2.0 * skew(ud);
    AOm.noalias() += A.middleCols<3>(6 * j) * Bt;
    AOm.noalias() -= A.middleCols<3>(6 * j + 3) * skew(thd);
    out.middleCols<3>(6 * j).noalias() -= 2.0 * A.middleCols<3>(6 * j) * W;
    out.middleCols<3>(6 * j + 3).noalias() -= A.middleCols<3>(6 * j + 3) * W;
  }
}

/// out -= A * dc/dw for an n-column matrix A: velocity_acceleration_blocks plus the rank-6 form of
/// Tx = I - [Phi_rig; 0] Zx, term by term (the nodal reference's form; the invariant path gathers the
/// products, aic_inertia.cpp velocity_tangent). O(rows n). Scratch in ws.
inline void subtract_times_velocity_accelerations_tangent(const AicElement& e, const AicKinematics& kin,
                                                          const Eigen::Vector3d& Om, const Eigen::VectorXd& xid,
                                                          const Eigen::MatrixXd& A, AicWorkspace& ws, Eigen::MatrixXd& out) {
  Eigen::MatrixXd& mAD = ws.AD;  // -A DcD
  mAD.setZero(A.rows(), e.n);
  velocity_acceleration_blocks(e, kin, Om, xid, A, ws.AOm, mAD);
  out.noalias() -= ws.AOm * kin.Zx.middleRows<3>(3);
  out += mAD;
  ws.ADPhi.noalias() = mAD.leftCols(6 * e.N) * kin.Phi_rig;
  out.noalias() -= ws.ADPhi * kin.Zx;
}

/// A * dc/dw as a new matrix (the nodal reference).
inline Eigen::MatrixXd times_velocity_accelerations_tangent(const AicElement& e, const AicKinematics& kin,
                                                            const Eigen::Vector3d& Om, const Eigen::VectorXd& xid,
                                                            const Eigen::MatrixXd& A) {
  AicWorkspace ws;
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(A.rows(), e.n);
  subtract_times_velocity_accelerations_tangent(e, kin, Om, xid, A, ws, out);
  return -out;
}

/// Evaluate an inertia model in body axes and rotate the result to world components:
/// body(w, ab, want, Mw, Cw, Kw, fw, kinetic) with w, ab the body-axis velocities and accelerations.
/// Mw, Cw, Kw are out.Mt, out.Ct, out.Kt, rotated in place afterwards (Ct only when formed) unless
/// axes is Body; vectors live in ws.
template <class BodyInertia>
void inertia_in_world(const AicElement& e, const AicKinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& v,
                      const Eigen::Ref<const Eigen::VectorXd>& a, InertiaMatrices want_matrices, InertiaResult& out,
                      AicWorkspace& ws, MatrixAxes axes, BodyInertia&& body) {
  const Eigen::Matrix3d& R = kin.frame.R_WB;
  to_body(e, R, v, ws.w);
  to_body(e, R, a, ws.ab);
  ws.fi.resize(e.n);
  body(ws.w, ws.ab, want_matrices, out.Mt, out.Ct, out.Kt, ws.fi, out.kinetic);
  out.has_Ct = want_matrices == InertiaMatrices::All;
  to_world(e, R, ws.fi, out.f);
  if (want_matrices == InertiaMatrices::None || axes == MatrixAxes::Body) return;
  rotate_to_world(e, R, out.Mt);
  if (want_matrices == InertiaMatrices::All) rotate_to_world(e, R, out.Ct);
  rotate_to_world(e, R, out.Kt);
}

}  // namespace seflex::mbd::detail
