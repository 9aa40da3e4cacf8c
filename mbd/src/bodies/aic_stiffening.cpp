// Geometric stiffening of an AIC superelement (docs/geometric-stiffening.md): the differential
// stiffness of the body's current stress state, from se::StiffeningInvariants, added to the elastic
// force and its tangent, at a cost of two products with the n x r n basis of the stacked invariants
// (AicElement::G_basis, r <= 12 + 6N).
//
// The stress of the inertia loads is taken at the current load factors lambda (a frozen load); the
// stress of the interface deformation comes from a potential, the energy of that stress on the
// nonlinear (Green) strain, with its quartic term condensed onto the interface coordinates:
//   V_G = 1/2 xi^T (sum_c lambda_c G_c) xi + xi_b . b + 1/2 b . s,
//   b_j = 1/2 xi^T G_j xi (j < 6N: the foreshortening load),  s = Kbb^+ b (the interface shortening),
//   f_G = (sum_c lambda_c G_c + sum_j (xi_j + s_j) G_j) xi + [b; 0]
//   df_G = sum_c mu_c G_c + Gb E^T + E Gb^T + Gb Kbb^+ Gb^T,  Gb = [G_j xi]_j,  mu = [lambda; xi_b + s]
// (lambda held fixed). 1/2 xi_b Kbb xi_b + xi_b . b + 1/2 b . s = 1/2 (xi_b + s)^T Kbb (xi_b + s): the
// axial energy of a bar with the bending's foreshortening, exact for a uniform axial strain, and
// bounded below (the cubic term alone is not: a beam whose ends are interfaces buckles at
// deflections of a fraction of its thickness, and a force that is not a gradient, the stress frozen
// at the current xi_b, is circulatory and fed a chain's axial vibration).
#include <Eigen/Dense>

#include "bodies/aic_inertia_detail.hpp"
#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/bodies/aic_element.hpp"
#include "seflex/superelement/symmetric_basis.hpp"

namespace seflex::mbd {

using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

void stiffening_load_factors(const AicElement& e, const AicKinematics& kin, const Eigen::Ref<const VectorXd>& v,
                             const Eigen::Ref<const VectorXd>& a, StiffeningLoads& lambda, AicWorkspace& ws) {
  to_body(e, kin.frame.R_WB, v, ws.sw);
  to_body(e, kin.frame.R_WB, a, ws.sab);
  const Vector3d Om = kin.Zx.middleRows<3>(3) * ws.sw;
  apply_transfer(e, kin, ws.sw, ws.sxid);
  detail::interface_velocity_accelerations(e, kin.xi, Om, ws.sxid, ws.sc);
  ws.sab -= ws.sc;
  lambda.head<6>().noalias() = kin.Zx * ws.sab;
  detail::centrifugal_load_factors(Om, lambda);
}

namespace detail {

namespace {

// U_i xi for the r basis matrices (the G_c are combinations of them, AicElement::G_basis): one
// product with the stacked basis, kept while xi and the element stay the same.
void basis_products(const AicElement& e, const VectorXd& xi, AicWorkspace& ws) {
  if (ws.Uxi_of == e.G_basis_t_V.data() && ws.Uxi_at.size() == xi.size() && ws.Uxi_at == xi) return;
  ws.eta_f.noalias() = e.V_f.transpose() * xi;  // xi = V_f V_f^T xi (the frame condition)
  ws.Uxi.noalias() = e.G_basis_t_V * ws.eta_f;
  ws.Uxi_at = xi;
  ws.Uxi_of = e.G_basis_t_V.data();
  ws.Gxi_formed = false;
}

}  // namespace

Eigen::Map<const MatrixXd> stiffening_inertia_products(const AicElement& e, AicWorkspace& ws) {
  const Eigen::Index n = e.n, r = e.G_coef.rows();
  if (!ws.Gxi_formed) {  // [G_c xi]_{c<12} = [U_i xi]_i W(:, c<12)
    ws.Gxi.resize(n * 12);
    if (r > 0)
      Eigen::Map<MatrixXd>(ws.Gxi.data(), n, 12).noalias() = Eigen::Map<const MatrixXd>(ws.Uxi.data(), n, r) * e.G_coef.leftCols<12>();
    else
      ws.Gxi.setZero();
    ws.Gxi_formed = true;
  }
  return Eigen::Map<const MatrixXd>(ws.Gxi.data(), n, 12);
}

double add_stress_stiffening(const AicElement& e, const VectorXd& xi, const StiffeningLoads& lambda, VectorXd& g, AicWorkspace& ws) {
  const Eigen::Index n = e.n, nb = 6 * e.N, k = 12 + nb, r = e.G_coef.rows();
  basis_products(e, xi, ws);
  ws.mu.resize(k);
  ws.mu.head<12>() = lambda;
  if (r == 0) {  // every G_c is zero
    ws.fb.setZero(nb);
    ws.fs.setZero(nb);
    ws.mu.tail(nb) = xi.head(nb);
    ws.Wmu.resize(0);
    return 0.0;
  }
  // Every term through the r products U_i xi: xi^T G_c xi = (W^T [xi^T U_i xi]_i)_c and
  // sum_c mu_c G_c xi = [U_i xi]_i (W mu); [G_c xi]_c itself only for the tangents.
  const Eigen::Map<const MatrixXd> Y(ws.Uxi.data(), n, r);
  const MatrixXd& W = e.G_coef;
  ws.yx.noalias() = Y.transpose() * xi;                        // xi^T U_i xi
  ws.fb.noalias() = 0.5 * W.rightCols(nb).transpose() * ws.yx;  // b_j = 1/2 xi^T G_j xi
  ws.fs.noalias() = e.Kbb_pinv * ws.fb;                         // s = Kbb^+ b
  ws.mu.tail(nb) = xi.head(nb) + ws.fs;
  ws.Wmu.noalias() = W * ws.mu;
  g.noalias() += Y * ws.Wmu;
  g.head(nb) += ws.fb;
  // 1/2 xi^T (sum lambda_c G_c) xi + xi_b . b + 1/2 b . s
  StiffeningLoads xGx;  // xi^T G_c xi, c < 12 (fixed size: no allocation)
  xGx.noalias() = W.leftCols<12>().transpose() * ws.yx;
  return 0.5 * lambda.dot(xGx) + xi.head(nb).dot(ws.fb) + 0.5 * ws.fb.dot(ws.fs);
}

void add_stress_stiffening_hessian(const AicElement& e, AicWorkspace& ws, MatrixXd& H) {
  const Eigen::Index n = e.n, nb = 6 * e.N, r = e.G_coef.rows();
  if (r == 0) return;
  // H += sum_c mu_c G_c + Gb E^T + E Gb^T + Gb Kbb^+ Gb^T, Gb = [G_j xi]_j (n x 6N), E the interface
  // rows. sum_c mu_c G_c = sum_i U_i (W mu)_i: the blocks of G_basis are contiguous, one product.
  Eigen::Map<VectorXd>(H.data(), n * n).noalias() += Eigen::Map<const MatrixXd>(e.G_basis.data(), n * n, r) * ws.Wmu;
  // With Y = [U_i xi]_i, Gb = Y W_b and Gb Kbb^+ Gb^T = Y P Y^T (P = W_b Kbb^+ W_b^T, r x r): the rest
  // is Y Q + (Y Q)^T with Q = 1/2 P Y^T + W_b E^T.
  const Eigen::Map<const MatrixXd> Y(ws.Uxi.data(), n, r);
  ws.Qr.noalias() = 0.5 * e.G_foreshortening * Y.transpose();
  ws.Qr.leftCols(nb) += e.G_coef.rightCols(nb);
  ws.YQ.noalias() = Y * ws.Qr;
  H += ws.YQ;
  H += ws.YQ.transpose();
}

void add_stiffening_mass_tangent(const AicElement& e, const AicKinematics& kin, AicWorkspace& ws, MatrixXd& Mt,
                                 MatrixAxes axes) {
  const Eigen::Index nb = 6 * e.N;
  const Eigen::Map<const MatrixXd> Gx = stiffening_inertia_products(e, ws);
  // d f_local / d a_b = [G_c xi]_{c<6} Zx (lambda_0..5 = Zx (a_b - c)); f_w = Tx^T f_local, with
  // Tx^T A = A - Zx^T Phi_rig^T A_b (Tx = I - [Phi_rig; 0] Zx); then to world as the mass matrix.
  ws.nn.noalias() = Gx.leftCols<6>() * kin.Zx;
  ws.sixn.noalias() = kin.Phi_rig.transpose() * ws.nn.topRows(nb);
  ws.nn.noalias() -= kin.Zx.transpose() * ws.sixn;
  if (axes == MatrixAxes::World) rotate_to_world(e, kin.frame.R_WB, ws.nn);
  Mt += ws.nn;
}

void centrifugal_load_factors(const Vector3d& Om, StiffeningLoads& lambda) {
  const Eigen::Matrix3d W = so3::skew(Om) * so3::skew(Om);
  lambda.tail<6>() = se::sym_components(W);
}

}  // namespace detail

void elastic_force_stiffened(const AicElement& e, const AicKinematics& kin, TangentModel tangent,
                             const StiffeningLoads& lambda, VectorXd& f, MatrixXd* Kt, AicWorkspace& ws, double* energy,
                             MatrixAxes axes) {
  SEFLEX_DEMAND(e.has_stiffening(), "superelement " + e.name + " has no geometric-stiffness invariants");
  const VectorXd& xi = kin.xi;
  ws.g.noalias() = e.K * xi;
  const double eK = 0.5 * xi.dot(ws.g);
  const double eG = detail::add_stress_stiffening(e, xi, lambda, ws.g, ws);
  if (energy != nullptr) *energy = eK + eG;
  if (Kt == nullptr) {
    detail::elastic_force_of_local(e, kin, tangent, e.K, f, nullptr, ws);
    return;
  }
  // H = K + the Hessian of V_G.
  MatrixXd& H = ws.Keff;
  H = e.K;
  detail::add_stress_stiffening_hessian(e, ws, H);
  detail::elastic_force_of_local(e, kin, tangent, H, f, Kt, ws, axes);
}

}  // namespace seflex::mbd
