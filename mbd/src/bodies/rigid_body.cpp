// Assembly contribution of one rigid body, as a wrench at its anchor node (moment about the node):
//   c = vector anchor -> centre of mass, I = inertia about the centre of mass (world axes)
//   F_t = m (a + alpha x c + w x (w x c) - g),   F_r = I alpha + w x I w + c x F_t
// with the mass matrix [[m, -m c~], [m c~, I - m c~ c~]], the gyroscopic derivative and the
// derivative with respect to the anchor's spatial rotation (c and I turn with the body).
#include "assembly/assembly_detail.hpp"
#include "bodies/rigid_inertia.hpp"
#include "seflex/common/so3.hpp"

namespace seflex::mbd::detail {

using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using so3::skew;

void assemble_rigid(const Model& model, Data& data, const AssemblyOptions& opt, int bi) {
  const RigidBody& b = model.rigid_bodies[static_cast<std::size_t>(bi)];
  RigidBodyData& rd = data.rigid[static_cast<std::size_t>(bi)];
  NodeKinematics& A = data.nodes[static_cast<std::size_t>(b.anchor.value)];
  const Matrix3d R_WB = A.R * b.R_NB;
  const Vector3d c = A.R * b.p_NBo_N + R_WB * b.p_BoCm_B;
  const Matrix3d I = R_WB * b.I_Cm_B * R_WB.transpose();
  const double m = b.mass;
  const Vector3d g = opt.load_factor * model.gravity;
  const Vector3d& w = A.w;
  const Vector3d& al = A.alpha;
  const RigidWrench rw = rigid_wrench(m, c, I, A.v, w, A.a - g, al);
  const Vector6d& F = rw.F;
  A.wrench += F;
  rd.f = F;
  rd.p_WCm = A.p + c;
  rd.kinetic = opt.dynamics ? rw.kinetic : 0.0;

  const int ci = data.clique_of_rigid[static_cast<std::size_t>(bi)];
  const auto& cdofs = data.pattern.dofs[static_cast<std::size_t>(ci)];
  const int nc = static_cast<int>(cdofs.size());
  if (nc == 0) return;
  auto off_of = [&]() -> const std::vector<int>& { return data.pattern.offsets[static_cast<std::size_t>(ci)]; };
  auto& J = rd.J;  // the anchor's Jacobian, body scratch (no allocation after the first call)
  J.resize(6, nc);
  for (int k = 0; k < nc; ++k) J.col(k) = A.J[static_cast<std::size_t>(k)];
  // Residual scale: magnitudes of the inertia and gravity parts before they cancel (|J^T F| alone
  // vanishes with the residual itself for a body on a single hinge, leaving no relative scale).
  Vector6d F_mag;
  const Vector3d Ft_mag = (m * (A.a + al.cross(c) + w.cross(w.cross(c)))).cwiseAbs() + (m * g).cwiseAbs();
  F_mag.head<3>() = Ft_mag;
  F_mag.tail<3>() = (I * al).cwiseAbs() + w.cross(I * w).cwiseAbs() + Vector3d::Constant(c.norm() * Ft_mag.norm());
  for (int k = 0; k < nc; ++k) data.scale[cdofs[static_cast<std::size_t>(k)]] += J.col(k).cwiseAbs().dot(F_mag);
  // vals += J^T X6 Y (X6 6 x 6, Y 6 x nc) through the body's scratch.
  auto scatter_JtXY = [&](std::vector<double>& vals, const Eigen::Matrix<double, 6, 6>& X6, const Eigen::Matrix<double, 6, Eigen::Dynamic>& Y) {
    rd.XY.noalias() = X6 * Y;
    rd.JtXY.noalias() = J.transpose() * rd.XY;
    scatter(vals, off_of(), rd.JtXY);
  };
  if (!opt.matrices) return;
  const Matrix3d cx = skew(c), wx = skew(w), ax = skew(al);
  Eigen::Matrix<double, 6, 6> K6 = Eigen::Matrix<double, 6, 6>::Zero();
  const Matrix3d dFt = -m * (ax + wx * wx) * cx;
  K6.block<3, 3>(0, 3) = dFt;
  K6.block<3, 3>(3, 3) = -skew(I * al) + I * ax + wx * (-skew(I * w) + I * wx) + skew(F.head<3>()) * cx + cx * dFt;
  scatter_JtXY(data.K, K6, J);
  if (!opt.dynamics) return;
  const Eigen::Matrix<double, 6, 6>& M6 = rw.M6;
  scatter_JtXY(data.M, M6, J);
  Eigen::Matrix<double, 6, 6> C6 = Eigen::Matrix<double, 6, 6>::Zero();
  const Matrix3d dFt_dw = m * (-skew(w.cross(c)) - wx * cx);
  C6.block<3, 3>(0, 3) = dFt_dw;
  C6.block<3, 3>(3, 3) = wx * I - skew(I * w) + cx * dFt_dw;
  auto& G = rd.G;  // convective terms of the node tree
  G.resize(6, nc);
  for (int k = 0; k < nc; ++k) G.col(k) = A.G[static_cast<std::size_t>(k)];
  scatter_JtXY(data.C, C6, J);
  scatter_JtXY(data.C, M6, G);
}

}  // namespace seflex::mbd::detail
