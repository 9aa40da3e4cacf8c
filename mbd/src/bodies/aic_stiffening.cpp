// Geometric stiffening of an AIC superelement (docs/geometric-stiffening.md): the differential
// stiffness of the body's current stress state, from se::StiffeningInvariants, added to the elastic
// force and its tangent, at a cost of two products with the n x (12 + 6N) n stacked invariants.
//
//   K_G(lambda, xi) = sum_c lambda_c G_c + sum_{j < 6N} xi_j G_j      (stress of the inertia loads and
//                                                                       of the interface deformation)
//   f_G   = K_G xi
//   df_G  = K_G + [G_j xi]_j e_j^T   (the stress's variation with the interface coordinates; lambda fixed)
//
// The stress is taken at the current loads, not derived from a potential: the cubic energy
// 1/2 sum_j xi_j xi^T G_j xi would add the axial force of the bending (1/2 [xi^T G_j xi]_j), but without
// the quartic term of the Green strain it is unbounded below (a beam whose ends are interface nodes
// buckles at deflections of a fraction of its thickness; docs/geometric-stiffening.md).
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

void add_stress_stiffening(const AicElement& e, const VectorXd& xi, const StiffeningLoads& lambda, VectorXd& g, AicWorkspace& ws) {
  const Eigen::Index n = e.n, nb = 6 * e.N, k = 12 + nb;
  // G_c xi for every case (the G_c are symmetric): one product with the stacked invariants.
  ws.Gxi.noalias() = e.G_stack.transpose() * xi;
  const Eigen::Map<const MatrixXd> Gx(ws.Gxi.data(), n, k);  // column c: G_c xi
  ws.mu.resize(k);
  ws.mu.head<12>() = lambda;
  ws.mu.tail(nb) = xi.head(nb);
  g.noalias() += Gx * ws.mu;
}

void centrifugal_load_factors(const Vector3d& Om, StiffeningLoads& lambda) {
  const Eigen::Matrix3d W = so3::skew(Om) * so3::skew(Om);
  lambda.tail<6>() = se::sym_components(W);
}

}  // namespace detail

void elastic_force_stiffened(const AicElement& e, const AicKinematics& kin, TangentModel tangent,
                             const StiffeningLoads& lambda, VectorXd& f, MatrixXd* Kt, AicWorkspace& ws, double* energy) {
  SEFLEX_DEMAND(e.has_stiffening(), "superelement " + e.name + " has no geometric-stiffness invariants");
  const Eigen::Index n = e.n, nb = 6 * e.N, k = 12 + nb;
  const VectorXd& xi = kin.xi;
  ws.g.noalias() = e.K * xi;
  detail::add_stress_stiffening(e, xi, lambda, ws.g, ws);  // + K_G xi
  const Eigen::Map<const MatrixXd> Gx(ws.Gxi.data(), n, k);  // column c: G_c xi
  if (energy != nullptr) *energy = 0.5 * xi.dot(ws.g);
  if (Kt == nullptr) {
    detail::elastic_force_of_local(e, kin, tangent, e.K, f, nullptr, ws);
    return;
  }
  // vec(K_G) = [vec G_0 ... vec G_k-1] mu: the blocks of G_stack are contiguous, one product.
  MatrixXd& H = ws.Keff;
  H = e.K;
  Eigen::Map<VectorXd>(H.data(), n * n).noalias() += Eigen::Map<const MatrixXd>(e.G_stack.data(), n * n, k) * ws.mu;
  H.leftCols(nb) += Gx.rightCols(nb);
  detail::elastic_force_of_local(e, kin, tangent, H, f, Kt, ws);
}

}  // namespace seflex::mbd
