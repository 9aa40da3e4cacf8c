// Assembly contribution of one flexible (AIC) body: gather interface poses and motions from its
// nodes, run the kernel (frame recovery, elastic force and tangent, inertia, damping) and map the
// node-space results through the node Jacobians onto the body's dof clique. Every intermediate
// lives in the body's scratch (FlexibleBodyData::scratch): no allocation after the first call.
#include <limits>

#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"

#include "assembly/assembly_detail.hpp"
#include "bodies/aic_inertia_detail.hpp"

namespace seflex::mbd::detail {

using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {

/// The body's share of the iteration matrix cK K T + cC C + cM M (AssemblyOptions::iteration) in one
/// mapping, from its matrices in body axes (sc.Kl with the inertia's K, in.Mt, in.Ct, sc.Cd): with
/// Rhat the frame's rotation on the interface blocks, J^T Rhat X Rhat^T J = (Rhat^T J)^T X (Rhat^T J),
/// so the node maps' columns (J, and G of the convective term) are rotated, not the n x n matrices.
void add_iteration_share(const Model& model, const FlexibleBody& body, const IterationMatrix& im, bool dynamics, bool damped,
                         const std::vector<int>& off, int nc, Data& data, FlexibleBodyData& fd) {
  FlexibleBodyScratch& sc = fd.scratch;
  const InertiaResult& in = sc.inertia;
  const auto N = body.nodes.size();
  sc.X = im.cK * sc.Kl;
  if (dynamics) {
    sc.X.noalias() += im.cM * in.Mt;
    if (in.has_Ct) sc.X.noalias() += im.cC * in.Ct;
    if (damped) sc.X.noalias() += im.cC * sc.Cd;
  }
  const Eigen::Matrix3d R_BW = fd.kin.frame.R_WB.transpose();
  auto rotate = [&](const std::vector<Vector6d>& in6, std::vector<Vector6d>& out6) {
    out6.resize(in6.size());
    for (std::size_t c = 0; c < in6.size(); ++c) {
      out6[c].head<3>().noalias() = R_BW * in6[c].head<3>();
      out6[c].tail<3>().noalias() = R_BW * in6[c].tail<3>();
    }
  };
  sc.JB.resize(N);
  sc.GB.resize(N);
  sc.bmap = sc.map;
  sc.GBp.clear();
  sc.triples.clear();
  for (std::size_t j = 0; j < N; ++j) {
    const auto k = static_cast<std::size_t>(body.nodes[j].value);
    sc.triples.push_back(&data.node_rotation_triples[k]);
    rotate(data.nodes[k].J, sc.JB[j]);
    sc.bmap.J[j] = &sc.JB[j];
    sc.bmap.identity[j] = 0;
    if (model.nodes[k].kind == NodeKind::Free) {  // G = 0: no convective term
      sc.GBp.push_back(nullptr);
      continue;
    }
    rotate(data.nodes[k].G, sc.GB[j]);
    sc.GBp.push_back(&sc.GB[j]);
  }
  NodeSpaceIteration share;
  share.X = &sc.X;
  share.K = im.rotation_jacobians ? &sc.Kl : nullptr;
  share.cK = im.cK;
  share.T = im.rotation_jacobians;
  share.triples = &sc.triples;
  share.M = dynamics && im.cC != 0.0 ? &in.Mt : nullptr;
  share.cC = im.cC;
  share.G = &sc.GBp;
  scatter_iteration(data.S_flex, off, nc, sc.bmap, share, sc.Y);
}

}  // namespace

void assemble_flexible(const Model& model, const State& s, Data& data, const AssemblyOptions& opt, int bi) {
  const FlexibleBody& body = model.flexible_bodies[static_cast<std::size_t>(bi)];
  const AicElement& e = model.superelement(body.se);
  FlexibleBodyData& fd = data.flex[static_cast<std::size_t>(bi)];
  FlexibleBodyScratch& sc = fd.scratch;
  const int N = e.N, n = e.n, m = e.m;
  auto node_of = [&](int j) -> std::size_t { return static_cast<std::size_t>(body.nodes[static_cast<std::size_t>(j)].value); };
  sc.R_WI.resize(static_cast<std::size_t>(N));
  sc.p_WI.resize(static_cast<std::size_t>(N));
  sc.v.resize(n);
  sc.a.resize(n);
  const Vector3d g = opt.load_factor * model.gravity;
  for (int j = 0; j < N; ++j) {
    const NodeKinematics& nk = data.nodes[node_of(j)];
    sc.R_WI[static_cast<std::size_t>(j)] = nk.R * body.R_NI[static_cast<std::size_t>(j)];
    sc.p_WI[static_cast<std::size_t>(j)] = nk.p;
    sc.v.segment<3>(6 * j) = nk.v;
    sc.v.segment<3>(6 * j + 3) = nk.w;
    sc.a.segment<3>(6 * j) = nk.a - g;
    sc.a.segment<3>(6 * j + 3) = nk.alpha;
  }
  const auto eta = s.eta.segment(m > 0 ? body.eta_offset : 0, m);
  if (m > 0) {
    if (opt.dynamics) {
      sc.v.tail(m) = s.v.segment(body.eta_dof, m);
      sc.a.tail(m) = s.vdot.segment(body.eta_dof, m);
    } else {
      sc.v.tail(m).setZero();
      sc.a.tail(m).setZero();
    }
  }
  // Starting frame: the one that gives interface 1 the local pose of the last evaluation (the body
  // moved rigidly since, to first order): one Newton iteration of the recovery fewer than from the
  // state's frame. That evaluation may have been a diverging Newton iterate: then the state's frame.
  const FloatingFrame& state_frame = s.frames[static_cast<std::size_t>(bi)];
  const FloatingFrame* start = &state_frame;
  FloatingFrame guess;
  if (fd.kin.xi.size() == n && fd.kin.xi.allFinite() && fd.kin.xi.segment<3>(3).norm() < 0.5) {
    guess.R_WB = sc.R_WI[0] * e.C[0].transpose() * so3::exp(-fd.kin.xi.segment<3>(3));
    guess.p_WBo = sc.p_WI[0] - guess.R_WB * (e.x[0] + fd.kin.xi.head<3>());
    start = &guess;
  }
  try {
    recover_frame(e, sc.R_WI, sc.p_WI, eta, body.options.recovery, *start, fd.kin);
  } catch (const ConvergenceError&) {
    if (start == &state_frame) throw;
    recover_frame(e, sc.R_WI, sc.p_WI, eta, body.options.recovery, state_frame, fd.kin);
  }
  // The iteration matrix's share is mapped in body axes (the node maps rotated, not the matrices).
  const MatrixAxes axes = opt.iteration ? MatrixAxes::Body : MatrixAxes::World;
  const bool stiffened = model.stiffened(body);
  if (stiffened) {
    stiffening_load_factors(e, fd.kin, sc.v, sc.a, sc.stiffening_loads, sc.aic);
    elastic_force_stiffened(e, fd.kin, body.options.tangent, sc.stiffening_loads, fd.f_el, opt.matrices ? &sc.Kl : nullptr,
                            sc.aic, &fd.elastic, axes);
  } else {
    elastic_force(e, fd.kin, body.options.tangent, fd.f_el, opt.matrices ? &sc.Kl : nullptr, sc.aic, axes);
    fd.elastic = 0.5 * fd.kin.xi.dot(sc.aic.g);  // g = K xi
  }
  if (opt.energies_only && !body.options.interface_loads) {  // an output sample: the energies, no forces
    fd.kinetic = opt.dynamics ? kinetic_energy(e, fd.kin, body.options.inertia, sc.v, sc.aic) : 0.0;
    return;
  }

  InertiaResult& in = sc.inertia;
  const bool need_inertia = opt.dynamics || g.squaredNorm() > 0.0;
  if (need_inertia) {
    const InertiaMatrices wanted = !opt.matrices                 ? InertiaMatrices::None
                                   : opt.inertia_velocity_tangent ? InertiaMatrices::All
                                                                  : InertiaMatrices::NoVelocityTangent;
    inertia_force(e, fd.kin, body.options.inertia, sc.v, sc.a, wanted, in, sc.aic, axes);
    if (opt.matrices && opt.dynamics && stiffened)
      add_stiffening_mass_tangent(e, fd.kin, sc.aic, in.Mt, axes);  // the load factors are the frame's accelerations
    fd.f_in = in.f;
    fd.kinetic = opt.dynamics ? in.kinetic : 0.0;
  } else {
    fd.f_in.setZero(n);
    fd.kinetic = 0.0;
  }
  const bool damped = opt.dynamics && (body.options.stiffness_damping > 0.0 || body.options.modal_damping > 0.0);
  if (damped) {
    if (sc.D.rows() != n) {  // body-axis damping matrix: constant, made at the first evaluation
      sc.D = body.options.stiffness_damping * e.K;
      for (int k = 0; k < m; ++k)
        sc.D(6 * N + k, 6 * N + k) += 2.0 * body.options.modal_damping * e.omega_modes[k] * e.M(6 * N + k, 6 * N + k);
    }
    // f = Tx^T D Tx w and C = Tx^T D Tx, with Tx = I - R6 Zx applied in O(6 n^2) (never formed).
    to_body(e, fd.kin.frame.R_WB, sc.v, sc.w);
    apply_transfer(e, fd.kin, sc.w, sc.xd);
    sc.yd.noalias() = sc.D * sc.xd;
    apply_transfer_transpose(e, fd.kin, sc.yd, sc.fw);
    to_world(e, fd.kin.frame.R_WB, sc.fw, fd.f_damp);
    if (opt.matrices) {
      const auto nb = 6 * N;
      sc.DR.noalias() = sc.D.leftCols(nb) * fd.kin.Phi_rig;  // D R6
      sc.DT = sc.D;
      sc.DT.noalias() -= sc.DR * fd.kin.Zx;                  // D Tx
      sc.RDT.noalias() = fd.kin.Phi_rig.transpose() * sc.DT.topRows(nb);
      sc.Cd = sc.DT;
      sc.Cd.noalias() -= fd.kin.Zx.transpose() * sc.RDT;     // Tx^T D Tx
      if (axes == MatrixAxes::World) rotate_to_world(e, fd.kin.frame.R_WB, sc.Cd);
    }
  } else {
    fd.f_damp.setZero(n);
  }
  // An output sample with interface loads reads f_el, f_in and f_damp (mbd::interface_load): no residual.
  if (opt.energies_only) return;
  sc.f = fd.f_el + fd.f_in + fd.f_damp;
  for (int j = 0; j < N; ++j) data.nodes[node_of(j)].wrench += sc.f.segment<6>(6 * j);
  for (int k = 0; k < m; ++k) data.residual[body.eta_dof + k] += sc.f[6 * N + k];

  // Node-space -> clique map (storage kept between calls).
  const int ci = data.clique_of_flex[static_cast<std::size_t>(bi)];
  const auto& cdofs = data.pattern.dofs[static_cast<std::size_t>(ci)];
  const int nc = static_cast<int>(cdofs.size());
  ElementMap& map = sc.map;
  map.J.clear();
  map.pos.clear();
  map.identity.clear();
  const auto& pos = data.flex_node_pos[static_cast<std::size_t>(bi)];
  for (int j = 0; j < N; ++j) {
    const auto k = node_of(j);
    map.J.push_back(&data.nodes[k].J);
    map.pos.push_back(&pos[static_cast<std::size_t>(j)]);
    map.identity.push_back(model.nodes[k].kind == NodeKind::Free);
  }
  map.extra = &data.flex_eta_pos[static_cast<std::size_t>(bi)];
  sc.sc.setZero(nc);
  add_mapped_abs(sc.sc, map, fd.f_el);
  add_mapped_abs(sc.sc, map, fd.f_in);
  if (damped) add_mapped_abs(sc.sc, map, fd.f_damp);
  // Round-off level of the elastic force: stiffness x (eps x absolute position).
  double pmax = e.length;
  for (const auto& pj : sc.p_WI) pmax = std::max(pmax, pj.norm());
  const double fl = 16.0 * std::numeric_limits<double>::epsilon() * e.K_abs_max * pmax;
  for (int c = 0; c < nc; ++c) {
    data.scale[cdofs[static_cast<std::size_t>(c)]] += sc.sc[c];
    data.floor[cdofs[static_cast<std::size_t>(c)]] += fl;
  }
  if (!opt.matrices) return;
  const auto& off = data.pattern.offsets[static_cast<std::size_t>(ci)];
  if (need_inertia) sc.Kl += in.Kt;
  if (opt.iteration) {
    add_iteration_share(model, body, *opt.iteration, opt.dynamics, damped, off, nc, data, fd);
    return;
  }
  scatter_mapped(data.K, off, nc, map, sc.Kl, sc.Y);
  if (opt.dynamics) {
    scatter_mapped(data.M, off, nc, map, in.Mt, sc.Y);
    if (in.has_Ct) {
      if (damped) in.Ct += sc.Cd;
      scatter_mapped(data.C, off, nc, map, in.Ct, sc.Y);
    } else if (damped) {
      scatter_mapped(data.C, off, nc, map, sc.Cd, sc.Y);
    }
    // Convective terms of the node tree: C += J^T M0 G.
    sc.G.clear();
    for (int j = 0; j < N; ++j) sc.G.push_back(&data.nodes[node_of(j)].G);
    if (convective_map(map, sc.G, sc.gmap)) scatter_mapped(data.C, off, nc, map, in.Mt, sc.Y, &sc.gmap);
  }
}

}  // namespace seflex::mbd::detail
