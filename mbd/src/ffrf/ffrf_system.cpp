// FFRF-LM system: bodies with frame-clamped modes, node sources, constraints, coordinate numbering.
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "ffrf/ffrf_detail.hpp"
#include "ffrf/ffrf_redundancy.hpp"
#include "seflex/common/error.hpp"

namespace seflex::mbd {

using Eigen::MatrixXd;

namespace {

Pose relative(const Pose& X_WA, const Pose& X_WB) {  // X_AB = X_WA^-1 X_WB
  return Pose{X_WA.R.transpose() * X_WB.R, X_WA.R.transpose() * (X_WB.p - X_WA.p)};
}

/// Frame-clamped modes: the null space of Phi_f (frame node held), diagonalised with K and M.
/// The pencil is solved as Mq x = mu Kq x with the stiffness as the metric: with the frame node held
/// Kq is positive definite, whereas Mq is only semi-definite when the FE mass lumps translations
/// (Nastran CBAR/CBEAM default: no rotational inertia), e.g. the antisymmetric twist of a bar whose
/// only torsional inertia is a CONM2 at mid-span. Such massless directions (mu = 0, infinite
/// frequency) cannot be mass-normalised and are left out, as truncation would drop them first;
/// the remaining modes are the finite-frequency ones, lowest first (omega^2 = 1 / mu).
void frame_clamped_modes(const AicElement& e, int modes, bool nodal, FfrfBody& b) {
  Eigen::JacobiSVD<MatrixXd> svd(e.Phi_f, Eigen::ComputeFullV);
  const MatrixXd Q = svd.matrixV().rightCols(e.n - 6);  // Phi_f Q = 0 (Phi_f has full row rank)
  const MatrixXd Kq = Q.transpose() * e.K * Q, Mq = Q.transpose() * e.M * Q;
  const MatrixXd Ks = 0.5 * (Kq + Kq.transpose()), Ms = 0.5 * (Mq + Mq.transpose());
  SEFLEX_DEMAND(Eigen::LLT<MatrixXd>(Ks).info() == Eigen::Success,
                "superelement " + e.name + ": the stiffness with the frame node held is not positive definite");
  Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> es(Ms, Ks);  // x^T Ks x = 1, mu ascending
  SEFLEX_DEMAND(es.info() == Eigen::Success, "frame-clamped eigenproblem of superelement " + e.name);
  const Eigen::VectorXd& mu = es.eigenvalues();
  const Eigen::Index nq = mu.size();
  const double mu_max = nq > 0 ? std::max(mu[nq - 1], 0.0) : 0.0;
  int finite = 0;
  while (finite < nq && mu[nq - 1 - finite] > 1e-12 * mu_max) ++finite;
  b.k = modes < 0 ? finite : std::min(modes, finite);
  b.V.resize(e.n, b.k);
  b.omega2.resize(b.k);
  for (int i = 0; i < b.k; ++i) {
    const Eigen::Index c = nq - 1 - i;                                    // largest mu: lowest frequency
    b.V.col(i) = Q * es.eigenvectors().col(c) / std::sqrt(mu[c]);  // x^T Mq x = mu
    b.omega2[i] = 1.0 / mu[c];
  }
  // Natural scale of each modal coordinate: its largest translation [m] per unit amplitude, over the
  // FE nodes when the recovery is at hand, else over the interface nodes and internal modes.
  b.amplitude = Eigen::VectorXd::Zero(b.k);
  if (e.has_fe_data) {
    const MatrixXd PV = e.Psi * b.V;
    for (int m = 0; m < b.k; ++m)
      for (Eigen::Index r = 0; r < PV.rows(); r += 6) b.amplitude[m] = std::max(b.amplitude[m], PV.col(m).segment<3>(r).cwiseAbs().maxCoeff());
    if (nodal) b.PV = PV;
  } else {
    for (int m = 0; m < b.k; ++m) {
      for (Eigen::Index r = 0; r < 6 * e.N; r += 6) b.amplitude[m] = std::max(b.amplitude[m], b.V.col(m).segment<3>(r).cwiseAbs().maxCoeff());
      for (int i = 0; i < e.m; ++i) b.amplitude[m] = std::max(b.amplitude[m], std::abs(b.V(6 * e.N + i, m)) * e.eta_amplitude[i]);
    }
  }
  if (!nodal) {
    b.MppV = e.inv.Mpp * b.V;
    b.VMppV = b.V.transpose() * b.MppV;
    b.AV = e.inv_by_xi * (e.V_f.transpose() * b.V);  // the columns of V satisfy the frame condition
  }
}

}  // namespace

FfrfSystem make_ffrf_system(const Model& model, const FfrfOptions& options) {
  FfrfSystem sys;
  sys.model = &model;
  sys.options = options;
  if (options.modes < -1) throw InputError("ffrf options: modes must be -1 (all) or a non-negative count");
  for (std::size_t i = 0; i < model.flexible_bodies.size(); ++i) {
    const FlexibleBody& fb = model.flexible_bodies[i];
    const AicElement& e = model.superelement(fb.se);
    FfrfBody b;
    b.name = fb.name;
    b.model_index = static_cast<int>(i);
    b.flexible = !options.rigid;
    b.X_WB0 = fb.X_WB0;
    b.nodes = fb.nodes;
    b.mass = e.mass;
    b.p_BoCm_B = e.p_BoCm_B;
    b.I_Cm_B = e.I_Cm_B;
    b.stiffness_damping = fb.options.stiffness_damping;
    for (int j = 0; j < e.N; ++j) {
      b.R_IN.push_back(fb.R_NI[static_cast<std::size_t>(j)].transpose());
      if (b.flexible)
        b.X_BN.push_back(Pose{e.C[static_cast<std::size_t>(j)] * b.R_IN.back(), e.x[static_cast<std::size_t>(j)]});
      else
        b.X_BN.push_back(relative(fb.X_WB0, model.node(fb.nodes[static_cast<std::size_t>(j)]).X_WN0));
    }
    if (b.flexible) {
      using Inertia = FfrfOptions::Inertia;
      if (options.inertia == Inertia::Nodal && !e.has_fe_data)
        throw InputError("flexible body '" + fb.name + "': the floating-frame formulation with nodal inertia needs the FE recovery matrix, FE node positions and FE mass (M_fe) of superelement '" +
                         e.name + "', which it does not carry (use the inertia invariants or a superelement file with FE data)");
      if (options.inertia != Inertia::Nodal && !e.inv.present())
        throw InputError("flexible body '" + fb.name + "': the floating-frame formulation needs the inertia invariants or the FE data of superelement '" + e.name +
                         "', which it carries neither of (reduce it again with seflex reduce, or use the rigid formulation)");
      // Auto: per evaluation the nodal sums cost about 24 n_fe (6 + k) flops (N(z), M_fe products), the
      // invariants about 51 n^2 (the stacked products with xi and xi_dot); measured on the spin-up beam
      // (21 grids, n = 18, k = 12), the nodal sums took 0.55x the invariants' time.
      const auto n_fe = static_cast<double>(e.X.cols());
      const double k_est = options.modes < 0 ? e.n - 6 : std::min(options.modes, e.n - 6);
      b.nodal = options.inertia == Inertia::Nodal ||
                (options.inertia == Inertia::Auto && e.has_fe_data && 24.0 * n_fe * (6.0 + k_est) < 51.0 * e.n * e.n);
      frame_clamped_modes(e, options.modes, b.nodal, b);
      b.stiffening = model.stiffened(fb);
    }
    sys.bodies.push_back(std::move(b));
  }
  for (std::size_t i = 0; i < model.rigid_bodies.size(); ++i) {
    const RigidBody& rb = model.rigid_bodies[i];
    const Pose& XA = model.node(rb.anchor).X_WN0;
    FfrfBody b;
    b.name = rb.name;
    b.model_index = static_cast<int>(i);
    b.from_rigid = true;
    b.X_WB0 = Pose{XA.R * rb.R_NB, XA.p + XA.R * rb.p_NBo_N};
    b.nodes = rb.nodes;
    b.mass = rb.mass;
    b.p_BoCm_B = rb.p_BoCm_B;
    b.I_Cm_B = rb.I_Cm_B;
    for (NodeIndex n : rb.nodes) b.X_BN.push_back(relative(b.X_WB0, model.node(n).X_WN0));
    sys.bodies.push_back(std::move(b));
  }
  // Coordinates: bodies, then undriven hinges.
  const double L = model.length_scale;
  auto push = [&](char kind, double w, int owner) {
    sys.kind.push_back(kind);
    sys.owner.push_back(owner);
    sys.weight.conservativeResize(sys.num_coords + 1);
    sys.weight[sys.num_coords] = w;
    return sys.num_coords++;
  };
  for (std::size_t bi = 0; bi < sys.bodies.size(); ++bi) {
    FfrfBody& b = sys.bodies[bi];
    const int owner = static_cast<int>(bi);
    b.coord = sys.num_coords;
    b.z_offset = sys.num_z;
    sys.num_z += b.k;
    for (int c = 0; c < 6; ++c) push(c < 3 ? 't' : 'r', c < 3 ? 1.0 / L : 1.0, owner);
    for (int m = 0; m < b.k; ++m) push('e', std::max(b.amplitude[m], 1e-12) / L, owner);
  }
  for (std::size_t h = 0; h < model.hinges.size(); ++h)
    sys.hinge_coord.push_back(model.hinges[h].drive || model.hinges[h].follower() ? -1 : push('h', 1.0, static_cast<int>(h)));
  // Node sources and constraints.
  using Kind = FfrfNodeSource::Kind;
  sys.node_source.assign(model.nodes.size(), FfrfNodeSource{});
  std::vector<bool> sourced(model.nodes.size(), false);
  for (std::size_t k = 0; k < model.nodes.size(); ++k) sourced[k] = model.nodes[k].kind == NodeKind::Fixed;
  for (std::size_t b = 0; b < sys.bodies.size(); ++b)
    for (std::size_t j = 0; j < sys.bodies[b].nodes.size(); ++j) {
      const auto k = static_cast<std::size_t>(sys.bodies[b].nodes[j].value);
      if (!sourced[k]) {
        sys.node_source[k] = FfrfNodeSource{Kind::Body, static_cast<int>(b), static_cast<int>(j)};
        sourced[k] = true;
      } else {
        sys.constraints.push_back(FfrfConstraint{static_cast<int>(b), static_cast<int>(j), NodeIndex(static_cast<int>(k)), false});
      }
    }
  for (std::size_t k = 0; k < model.nodes.size(); ++k) {
    const Node& n = model.nodes[k];
    FfrfNodeSource& src = sys.node_source[k];
    if (n.kind == NodeKind::Free && !sourced[k])
      throw InputError("node '" + n.name + "' is free but no body carries it; the floating-frame formulation needs every free node on a body");
    if (n.kind != NodeKind::Attached) continue;
    if (!sourced[k]) {
      src.kind = Kind::Chain;
      continue;
    }
    // Carried by a body and attached to a parent: a joint, unless it is a rigid slave that the same
    // rigid body already places exactly (its interface poses come from the same initial poses).
    const FfrfNodeSource& ps = sys.node_source[static_cast<std::size_t>(n.parent.value)];
    const bool same_rigid = !n.hinge.valid() && ps.kind == Kind::Body && ps.body == src.body &&
                            !sys.bodies[static_cast<std::size_t>(src.body)].flexible;
    if (!same_rigid) sys.constraints.push_back(FfrfConstraint{src.body, src.interface, NodeIndex(static_cast<int>(k)), true});
  }
  detail::find_redundant(sys);
  return sys;
}

}  // namespace seflex::mbd
