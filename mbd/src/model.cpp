// ModelBuilder: input checks, node attachment, dof numbering and per-node dependencies.
#include "seflex/mbd/model.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"

namespace seflex::mbd {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

std::string fmt(const Vector3d& v) {
  std::ostringstream os;
  os.precision(6);
  os << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return os.str();
}

void check_pose(const Pose& X, const std::string& who) {
  if (!X.p.allFinite() || !X.R.allFinite()) throw InputError(who + ": pose has non-finite entries");
  if (!((X.R.transpose() * X.R - Matrix3d::Identity()).norm() < 1e-8) || !(X.R.determinant() > 0.0))
    throw InputError(who + ": orientation is not a rotation matrix (orthonormal, determinant +1)");
}

}  // namespace

Pose interface_pose(const se::Superelement& s, int j, const Pose& X_WB) {
  SEFLEX_DEMAND(j >= 0 && j < s.num_interfaces(), "interface index out of range");
  const auto& itf = s.interfaces[static_cast<std::size_t>(j)];
  return Pose{X_WB.R * itf.R_BN, X_WB.p + X_WB.R * itf.p_BoN_B};
}

void ModelBuilder::check_node(NodeIndex n, const std::string& who) const {
  if (!n.valid() || n.value >= static_cast<int>(model_.nodes.size()))
    throw InputError(who + ": refers to node index " + std::to_string(n.value) + ", which does not exist");
}

void ModelBuilder::check_hinge(HingeIndex h, const std::string& who) const {
  if (!h.valid() || h.value >= static_cast<int>(model_.hinges.size()))
    throw InputError(who + ": refers to hinge index " + std::to_string(h.value) + ", which does not exist");
  const Hinge& hg = model_.hinges[static_cast<std::size_t>(h.value)];
  if (hg.follower())
    throw InputError(who + ": acts on hinge '" + hg.name + "', which follows hinge '" + model_.hinges[static_cast<std::size_t>(hg.leader.value)].name +
                     "' (a redundant hinge of a closed loop of rigid bodies); put the element on the leader");
}

NodeIndex ModelBuilder::add_node(const std::string& name, const Pose& X_WN) {
  check_pose(X_WN, "node '" + name + "'");
  Node n;
  n.name = name;
  n.kind = NodeKind::Free;
  n.X_WN0 = X_WN;
  model_.nodes.push_back(n);
  return NodeIndex(static_cast<int>(model_.nodes.size()) - 1);
}

NodeIndex ModelBuilder::add_ground(const std::string& name, const Pose& X_WN) {
  const NodeIndex i = add_node(name, X_WN);
  model_.nodes.back().kind = NodeKind::Fixed;
  return i;
}

NodeIndex ModelBuilder::push_attached(const std::string& name, NodeIndex parent, const Pose& X_WN, HingeIndex hinge,
                                      double phi0, const Vector3d& axis_P) {
  const Pose& XP = model_.nodes[static_cast<std::size_t>(parent.value)].X_WN0;
  Node n;
  n.name = name;
  n.kind = NodeKind::Attached;
  n.X_WN0 = X_WN;
  n.parent = parent;
  n.hinge = hinge;
  n.p_PN_P = XP.R.transpose() * (X_WN.p - XP.p);
  n.R_PN = so3::exp(-phi0 * axis_P) * XP.R.transpose() * X_WN.R;
  model_.nodes.push_back(n);
  return NodeIndex(static_cast<int>(model_.nodes.size()) - 1);
}

NodeIndex ModelBuilder::add_attached_node(const std::string& name, NodeIndex parent, const Pose& X_WN) {
  const std::string who = "node '" + name + "'";
  check_node(parent, who);
  check_pose(X_WN, who);
  return push_attached(name, parent, X_WN, HingeIndex(), 0.0, Vector3d::UnitZ());
}

HingeIndex ModelBuilder::add_hinge(const std::string& name, NodeIndex parent, const Vector3d& axis_W,
                                   const HingeOptions& options) {
  check_node(parent, "hinge '" + name + "'");
  return add_hinge(name, parent, axis_W, model_.nodes[static_cast<std::size_t>(parent.value)].X_WN0.R, options);
}

HingeIndex ModelBuilder::add_hinge(const std::string& name, NodeIndex parent, const Vector3d& axis_W, const Matrix3d& R_WC0,
                                   const HingeOptions& options) {
  const std::string who = "hinge '" + name + "'";
  check_node(parent, who);
  if (!axis_W.allFinite() || !(axis_W.norm() > 1e-12)) throw InputError(who + ": axis must be a nonzero vector");
  const Pose& XP = model_.nodes[static_cast<std::size_t>(parent.value)].X_WN0;
  check_pose(Pose{R_WC0, XP.p}, who + " child triad");
  Hinge h;
  h.name = name;
  h.parent = parent;
  h.axis_P = XP.R.transpose() * axis_W.normalized();
  h.phi0 = options.phi0;
  h.phidot0 = options.phidot0;
  h.drive = options.drive;
  if (h.drive) {
    const DriveValue d0 = h.drive(0.0);
    h.phi0 = d0.phi;
    h.phidot0 = d0.phidot;
  }
  if (!std::isfinite(h.phi0) || !std::isfinite(h.phidot0)) throw InputError(who + ": initial angle and rate must be finite");
  const HingeIndex hi(static_cast<int>(model_.hinges.size()));
  model_.hinges.push_back(h);
  model_.hinges.back().child = push_attached(name + ".child", parent, Pose{R_WC0, XP.p}, hi, h.phi0, h.axis_P);
  return hi;
}

HingeIndex ModelBuilder::add_follower_hinge(const std::string& name, HingeIndex leader, double sign, double phi0) {
  const std::string who = "hinge '" + name + "'";
  if (!leader.valid() || leader.value >= static_cast<int>(model_.hinges.size()))
    throw InputError(who + ": the leader is not a hinge of this model");
  const Hinge& L = model_.hinges[static_cast<std::size_t>(leader.value)];
  if (L.follower()) throw InputError(who + ": the leader '" + L.name + "' is itself a follower");
  if (sign != 1.0 && sign != -1.0) throw InputError(who + ": the sign must be +1 or -1");
  if (!std::isfinite(phi0)) throw InputError(who + ": initial angle must be finite");
  Hinge h;
  h.name = name;
  h.parent = L.parent;
  h.axis_P = sign * L.axis_P;
  h.leader = leader;
  h.follow_sign = sign;
  h.follow_offset = phi0 - sign * L.phi0;
  h.phi0 = phi0;
  h.phidot0 = sign * L.phidot0;
  const HingeIndex hi(static_cast<int>(model_.hinges.size()));
  model_.hinges.push_back(h);
  return hi;
}

void ModelBuilder::set_initial_velocity(NodeIndex n, const Vector3d& v_W, const Vector3d& w_W) {
  check_node(n, "initial velocity");
  auto& node = model_.nodes[static_cast<std::size_t>(n.value)];
  if (node.kind != NodeKind::Free) throw InputError("node '" + node.name + "': only free nodes take an initial velocity");
  node.v0 = v_W;
  node.w0 = w_W;
}

SuperelementIndex ModelBuilder::add_superelement(const se::Superelement& s) {
  return add_superelement(std::make_shared<const se::Superelement>(s));
}

SuperelementIndex ModelBuilder::add_superelement(std::shared_ptr<const se::Superelement> s) {
  SEFLEX_DEMAND(s != nullptr, "add_superelement: no superelement");
  AicElement placeholder;
  placeholder.name = s->name;
  sources_.push_back(std::move(s));
  prepared_.push_back(false);
  model_.superelements.push_back(std::move(placeholder));
  return SuperelementIndex(static_cast<int>(sources_.size()) - 1);
}

FlexibleBodyIndex ModelBuilder::add_flexible_body(const std::string& name, SuperelementIndex sei,
                                                  const std::vector<NodeIndex>& nodes, const Pose& X_WB,
                                                  const FlexibleBodyOptions& options) {
  const std::string who = "flexible body '" + name + "'";
  if (!sei.valid() || sei.value >= static_cast<int>(sources_.size()))
    throw InputError(who + ": refers to a superelement that was not added");
  check_pose(X_WB, who + " placement");
  const auto k = static_cast<std::size_t>(sei.value);
  if (!prepared_[k]) {
    model_.superelements[k] = make_aic_element(*sources_[k]);
    prepared_[k] = true;
  }
  const AicElement& e = model_.superelements[k];
  const se::Superelement& s = *sources_[k];
  if (static_cast<int>(nodes.size()) != e.N)
    throw InputError(who + ": superelement '" + e.name + "' has " + std::to_string(e.N) + " interface nodes, " +
                     std::to_string(nodes.size()) + " nodes were given");
  if (options.inertia == InertiaModel::Full && !e.inv.present())
    throw InputError(who + ": full inertia needs the inertia invariants of superelement '" + e.name +
                     "' (or its FE recovery matrix and FE mass to compute them), which it does not carry: reduce it again "
                     "with this seflex (`seflex reduce` stores the invariants, also with --no-mesh), or use the simplified inertia");
  if (!(options.stiffness_damping >= 0.0) || !(options.modal_damping >= 0.0))
    throw InputError(who + ": damping coefficients must be non-negative");
  FlexibleBody b;
  b.name = name;
  b.se = sei;
  b.nodes = nodes;
  b.X_WB0 = X_WB;
  b.options = options;
  for (int j = 0; j < e.N; ++j) {
    check_node(nodes[static_cast<std::size_t>(j)], who);
    for (int i = 0; i < j; ++i)
      if (nodes[static_cast<std::size_t>(i)] == nodes[static_cast<std::size_t>(j)])
        throw InputError(who + ": interfaces " + std::to_string(i + 1) + " and " + std::to_string(j + 1) + " are on the same node");
    const Node& n = model_.nodes[static_cast<std::size_t>(nodes[static_cast<std::size_t>(j)].value)];
    const Pose XI = interface_pose(s, j, X_WB);
    const double d = (n.X_WN0.p - XI.p).norm();
    if (!(d <= options.placement_tolerance * e.length + 1e-12)) {
      std::ostringstream os;
      os << who << ": interface " << j + 1 << " (grid " << s.interfaces[static_cast<std::size_t>(j)].id << ") is placed at "
         << fmt(XI.p) << " but its node '" << n.name << "' is at " << fmt(n.X_WN0.p) << " (" << d
         << " m apart); the body would start pre-strained";
      throw InputError(os.str());
    }
    b.R_NI.push_back(n.X_WN0.R.transpose() * XI.R);
  }
  if (e.m > 0) {
    b.eta_offset = model_.num_modal;
    model_.num_modal += e.m;
  }
  model_.flexible_bodies.push_back(b);
  return FlexibleBodyIndex(static_cast<int>(model_.flexible_bodies.size()) - 1);
}

RigidBodyIndex ModelBuilder::add_rigid_body(const std::string& name, SuperelementIndex sei, NodeIndex anchor,
                                            int anchor_interface, const Pose& X_WB) {
  const std::string who = "rigid body '" + name + "'";
  if (!sei.valid() || sei.value >= static_cast<int>(sources_.size()))
    throw InputError(who + ": refers to a superelement that was not added");
  check_node(anchor, who);
  check_pose(X_WB, who + " placement");
  const se::Superelement& s = *sources_[static_cast<std::size_t>(sei.value)];
  if (!(s.mass > 0.0) || !std::isfinite(s.mass)) throw InputError(who + ": superelement '" + s.name + "' has no mass");
  if (!s.I_Cm_B.allFinite() || !s.p_BoCm_B.allFinite()) throw InputError(who + ": mass properties are not finite");
  if (anchor_interface < -1 || anchor_interface >= s.num_interfaces())
    throw InputError(who + ": anchor interface " + std::to_string(anchor_interface) + " does not exist");
  const Pose XA = model_.nodes[static_cast<std::size_t>(anchor.value)].X_WN0;
  const Vector3d expected = anchor_interface >= 0 ? interface_pose(s, anchor_interface, X_WB).p : X_WB.p;
  const double len = [&] {
    double l = 1e-3;
    for (const auto& itf : s.interfaces) l = std::max(l, itf.p_BoN_B.norm());
    return l;
  }();
  if (!((XA.p - expected).norm() <= 1e-6 * len + 1e-12))
    throw InputError(who + ": its anchor node '" + model_.nodes[static_cast<std::size_t>(anchor.value)].name + "' is at " + fmt(XA.p) +
                     " but the placement puts the anchor at " + fmt(expected));
  RigidBody b;
  b.name = name;
  b.se = sei;
  b.anchor = anchor;
  b.R_NB = XA.R.transpose() * X_WB.R;
  b.p_NBo_N = XA.R.transpose() * (X_WB.p - XA.p);
  b.mass = s.mass;
  b.p_BoCm_B = s.p_BoCm_B;
  b.I_Cm_B = 0.5 * (s.I_Cm_B + s.I_Cm_B.transpose());
  for (int j = 0; j < s.num_interfaces(); ++j) {
    if (j == anchor_interface) {
      b.nodes.push_back(anchor);
      continue;
    }
    const Pose XI = interface_pose(s, j, X_WB);
    b.nodes.push_back(push_attached(name + ":" + std::to_string(s.interfaces[static_cast<std::size_t>(j)].id), anchor, XI,
                                    HingeIndex(), 0.0, Vector3d::UnitZ()));
  }
  model_.rigid_bodies.push_back(b);
  return RigidBodyIndex(static_cast<int>(model_.rigid_bodies.size()) - 1);
}

ForceElementIndex ModelBuilder::add_force_element(const std::string& name, const ForceElement& fe) {
  std::visit([&](const auto& el) { validate(el, name); }, fe);
  const std::string who = std::string(kind_name(fe)) + " '" + name + "'";
  std::visit(
      [&](const auto& el) {
        using T = std::decay_t<decltype(el)>;
        if constexpr (std::is_same_v<T, CableLoop>) {
          for (auto h : el.hinges_a) check_hinge(h, who);
          for (auto h : el.hinges_b) check_hinge(h, who);
        } else {
          check_hinge(el.hinge, who);
        }
      },
      fe);
  model_.force_elements.push_back(NamedForceElement{name, fe});
  return ForceElementIndex(static_cast<int>(model_.force_elements.size()) - 1);
}

LoadIndex ModelBuilder::add_load(const NodeLoad& load) {
  const std::string who = "load '" + load.name + "'";
  check_node(load.node, who);
  if (!load.force.allFinite() || !load.moment.allFinite()) throw InputError(who + ": force and moment must be finite");
  model_.loads.push_back(load);
  return LoadIndex(static_cast<int>(model_.loads.size()) - 1);
}

Model ModelBuilder::build() {
  Model& m = model_;
  static const char* comp[] = {"x", "y", "z", "rx", "ry", "rz"};
  m.num_dofs = 0;
  m.dof_labels.clear();
  m.dof_kind.clear();
  m.dof_node.clear();
  m.dof_owner.clear();
  m.rotation_dof_starts.clear();
  m.node_dofs.assign(m.nodes.size(), {});
  auto push = [&](const std::string& label, char kind, int node, int owner) {
    m.dof_labels.push_back(label);
    m.dof_kind.push_back(kind);
    m.dof_node.push_back(node);
    m.dof_owner.push_back(owner);
    return m.num_dofs++;
  };
  for (std::size_t k = 0; k < m.nodes.size(); ++k) {
    Node& n = m.nodes[k];
    if (n.kind == NodeKind::Free) {
      n.dof = m.num_dofs;
      for (int c = 0; c < 6; ++c) push("node '" + n.name + "' " + comp[c], c < 3 ? 't' : 'r', static_cast<int>(k), -1);
      m.rotation_dof_starts.push_back(n.dof + 3);
      for (int c = 0; c < 6; ++c) m.node_dofs[k].push_back(n.dof + c);
    } else if (n.kind == NodeKind::Attached) {
      SEFLEX_DEMAND(n.parent.value < static_cast<int>(k), "attached node before its parent");
      m.node_dofs[k] = m.node_dofs[static_cast<std::size_t>(n.parent.value)];
      if (n.hinge.valid()) {
        Hinge& h = m.hinges[static_cast<std::size_t>(n.hinge.value)];
        if (!h.drive) {
          h.dof = push("hinge '" + h.name + "'", 'h', static_cast<int>(k), n.hinge.value);
          m.node_dofs[k].push_back(h.dof);
        } else {
          h.dof = -1;
        }
      }
      std::sort(m.node_dofs[k].begin(), m.node_dofs[k].end());
    }
  }
  for (std::size_t b = 0; b < m.flexible_bodies.size(); ++b) {
    FlexibleBody& body = m.flexible_bodies[b];
    const AicElement& e = m.superelements[static_cast<std::size_t>(body.se.value)];
    body.eta_dof = e.m > 0 ? m.num_dofs : -1;
    for (int k = 0; k < e.m; ++k) push("body '" + body.name + "' mode " + std::to_string(k + 1), 'e', -1, static_cast<int>(b));
  }
  // Length scale: extent of the initial node cloud, at least the largest body.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto& n : m.nodes) {
    lo = lo.cwiseMin(n.X_WN0.p);
    hi = hi.cwiseMax(n.X_WN0.p);
  }
  m.length_scale = m.nodes.empty() ? 1.0 : (hi - lo).norm();
  for (const auto& b : m.flexible_bodies) m.length_scale = std::max(m.length_scale, m.superelement(b.se).length);
  m.length_scale = std::max(m.length_scale, 1e-3);
  m.dof_weight = Eigen::VectorXd::Ones(m.num_dofs);
  for (int i = 0; i < m.num_dofs; ++i) {
    if (m.dof_kind[static_cast<std::size_t>(i)] == 't') m.dof_weight[i] = 1.0 / m.length_scale;
  }
  for (const auto& body : m.flexible_bodies) {
    const AicElement& e = m.superelement(body.se);
    for (int k = 0; k < e.m; ++k) m.dof_weight[body.eta_dof + k] = e.eta_amplitude[k] / m.length_scale;
  }
  Model out = std::move(model_);
  model_ = Model{};
  sources_.clear();
  prepared_.clear();
  return out;
}

}  // namespace seflex::mbd
