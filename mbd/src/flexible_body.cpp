// Assembly contribution of one flexible (AIC) body: gather interface poses and motions from its
// nodes, run the kernel (frame recovery, elastic force and tangent, inertia, damping) and map the
// node-space results through the node Jacobians onto the body's dof clique.
#include <limits>

#include "assembly_detail.hpp"

namespace seflex::mbd::detail {

using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

void assemble_flexible(const Model& model, const State& s, Data& data, const AssemblyOptions& opt, int bi) {
  const FlexibleBody& body = model.flexible_bodies[static_cast<std::size_t>(bi)];
  const AicElement& e = model.superelement(body.se);
  FlexibleBodyData& fd = data.flex[static_cast<std::size_t>(bi)];
  const int N = e.N, n = e.n, m = e.m;
  std::vector<Eigen::Matrix3d> R_WI(static_cast<std::size_t>(N));
  std::vector<Vector3d> p_WI(static_cast<std::size_t>(N));
  VectorXd v(n), a(n);
  const Vector3d g = opt.load_factor * model.gravity;
  for (int j = 0; j < N; ++j) {
    const NodeKinematics& nk = data.nodes[static_cast<std::size_t>(body.nodes[static_cast<std::size_t>(j)].value)];
    R_WI[static_cast<std::size_t>(j)] = nk.R * body.R_NI[static_cast<std::size_t>(j)];
    p_WI[static_cast<std::size_t>(j)] = nk.p;
    v.segment<3>(6 * j) = nk.v;
    v.segment<3>(6 * j + 3) = nk.w;
    a.segment<3>(6 * j) = nk.a - g;
    a.segment<3>(6 * j + 3) = nk.alpha;
  }
  const VectorXd eta = m > 0 ? VectorXd(s.eta.segment(body.eta_offset, m)) : VectorXd();
  if (m > 0) {
    if (opt.dynamics) {
      v.tail(m) = s.v.segment(body.eta_dof, m);
      a.tail(m) = s.vdot.segment(body.eta_dof, m);
    } else {
      v.tail(m).setZero();
      a.tail(m).setZero();
    }
  }
  recover_frame(e, R_WI, p_WI, eta, body.options.recovery, s.frames[static_cast<std::size_t>(bi)], fd.kin);
  MatrixXd Kl;
  elastic_force(e, fd.kin, body.options.tangent, fd.f_el, opt.matrices ? &Kl : nullptr);
  fd.elastic = 0.5 * fd.kin.xi.dot(e.K * fd.kin.xi);

  InertiaResult in;
  const bool need_inertia = opt.dynamics || g.squaredNorm() > 0.0;
  if (need_inertia) {
    inertia_force(e, fd.kin, body.options.inertia, v, a, opt.matrices, in);
    fd.f_in = in.f;
    fd.kinetic = opt.dynamics ? in.kinetic : 0.0;
  } else {
    fd.f_in = VectorXd::Zero(n);
    fd.kinetic = 0.0;
  }
  MatrixXd Cd;
  const bool damped = opt.dynamics && (body.options.stiffness_damping > 0.0 || body.options.modal_damping > 0.0);
  if (damped) {
    MatrixXd D = body.options.stiffness_damping * e.K;
    for (int k = 0; k < m; ++k) D(6 * N + k, 6 * N + k) += 2.0 * body.options.modal_damping * e.omega_modes[k] * e.M(6 * N + k, 6 * N + k);
    const MatrixXd Dw = fd.kin.Tx.transpose() * D * fd.kin.Tx;
    fd.f_damp = to_world(e, fd.kin.frame.R_WB, Dw * to_body(e, fd.kin.frame.R_WB, v));
    if (opt.matrices) Cd = to_world_matrix(e, fd.kin.frame.R_WB, Dw);
  } else {
    fd.f_damp = VectorXd::Zero(n);
  }
  const VectorXd f = fd.f_el + fd.f_in + fd.f_damp;
  for (int j = 0; j < N; ++j)
    data.nodes[static_cast<std::size_t>(body.nodes[static_cast<std::size_t>(j)].value)].wrench += f.segment<6>(6 * j);
  for (int k = 0; k < m; ++k) data.residual[body.eta_dof + k] += f[6 * N + k];

  // Node-space -> clique map.
  const int ci = data.clique_of_flex[static_cast<std::size_t>(bi)];
  const auto& cdofs = data.pattern.dofs[static_cast<std::size_t>(ci)];
  const int nc = static_cast<int>(cdofs.size());
  ElementMap map;
  const auto& pos = data.flex_node_pos[static_cast<std::size_t>(bi)];
  for (int j = 0; j < N; ++j) {
    const auto k = static_cast<std::size_t>(body.nodes[static_cast<std::size_t>(j)].value);
    map.J.push_back(&data.nodes[k].J);
    map.pos.push_back(&pos[static_cast<std::size_t>(j)]);
    map.identity.push_back(model.nodes[k].kind == NodeKind::Free);
  }
  map.extra = &data.flex_eta_pos[static_cast<std::size_t>(bi)];
  VectorXd sc = VectorXd::Zero(nc);
  add_mapped_abs(sc, map, fd.f_el);
  add_mapped_abs(sc, map, fd.f_in);
  if (damped) add_mapped_abs(sc, map, fd.f_damp);
  // Round-off level of the elastic force: stiffness x (eps x absolute position).
  double pmax = e.length;
  for (const auto& pj : p_WI) pmax = std::max(pmax, pj.norm());
  const double fl = 16.0 * std::numeric_limits<double>::epsilon() * e.K_abs_max * pmax;
  for (int c = 0; c < nc; ++c) {
    data.scale[cdofs[static_cast<std::size_t>(c)]] += sc[c];
    data.floor[cdofs[static_cast<std::size_t>(c)]] += fl;
  }
  if (!opt.matrices) return;
  const auto& off = data.pattern.offsets[static_cast<std::size_t>(ci)];
  if (need_inertia) Kl += in.Kt;
  scatter_mapped(data.K, off, nc, map, Kl);
  if (opt.dynamics) {
    scatter_mapped(data.M, off, nc, map, in.Mt);
    if (damped) in.Ct += Cd;
    scatter_mapped(data.C, off, nc, map, in.Ct);
    // Convective terms of the node tree: C += J^T M0 G.
    std::vector<const std::vector<Vector6d>*> G;
    for (int j = 0; j < N; ++j) G.push_back(&data.nodes[static_cast<std::size_t>(body.nodes[static_cast<std::size_t>(j)].value)].G);
    ElementMap gmap;
    if (convective_map(map, G, gmap)) scatter_mapped(data.C, off, nc, map, in.Mt, &gmap);
  }
}

}  // namespace seflex::mbd::detail
