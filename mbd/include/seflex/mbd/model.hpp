#pragma once
// The multibody model: built once (ModelBuilder), then only read (Pinocchio-style Model/State/Data).
//
// Kinematic nodes. Every point that has a pose is a node:
//  - Free: its position p_WN and rotation R_WN are unknowns (6 dofs: dr, then spatial dpi).
//  - Fixed: ground; its pose is given and never changes (no dofs).
//  - Attached: its pose follows a parent node P rigidly, optionally through a revolute hinge:
//        p_WN = p_WP + R_WP p_PN_P,   R_WN = R_WP exp(phi a~) R_PN          (formulation 4.3)
//    where a is the hinge axis in P's axes and phi the hinge angle (a dof, never wrapped, or
//    prescribed by a drive). Without a hinge the node is a rigid slave (used for rigid bodies).
//  Parents come before children, so the nodes form a forest rooted at Free/Fixed nodes.
// Bodies connect to nodes: a flexible (AIC) body to one node per interface, sharing that node's
// dofs with every other body on it (no Lagrange multipliers); a rigid body to one anchor node, its
// other interfaces becoming rigid slaves of the anchor.
// Unknowns (dofs): 6 per Free node, 1 per undriven hinge, m per flexible body with internal modes.
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "seflex/mbd/bodies/aic_element.hpp"
#include "seflex/mbd/forces/force_element.hpp"
#include "seflex/mbd/ids.hpp"
#include "seflex/superelement/superelement.hpp"

namespace seflex::mbd {

/// Pose of a frame F in W: R_WF and p_WFo.
struct Pose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
};

enum class NodeKind { Free, Fixed, Attached };

struct Node {
  std::string name;
  NodeKind kind = NodeKind::Free;
  Pose X_WN0;                                        ///< pose at t = 0 (Fixed: always)
  NodeIndex parent;                                  ///< Attached only
  Eigen::Vector3d p_PN_P = Eigen::Vector3d::Zero();  ///< Attached: offset from the parent, parent axes
  Eigen::Matrix3d R_PN = Eigen::Matrix3d::Identity();///< Attached: constant rotation after the hinge
  HingeIndex hinge;                                  ///< Attached through a hinge (else rigid slave)
  int dof = -1;                                      ///< Free: first of its 6 dofs
  Eigen::Vector3d v0 = Eigen::Vector3d::Zero();      ///< Free: initial velocity (world)
  Eigen::Vector3d w0 = Eigen::Vector3d::Zero();      ///< Free: initial angular velocity (world)
};

/// Prescribed hinge motion at time t.
struct DriveValue {
  double phi = 0.0, phidot = 0.0, phiddot = 0.0;
};
using Drive = std::function<DriveValue(double t)>;

struct Hinge {
  std::string name;
  NodeIndex parent, child;
  Eigen::Vector3d axis_P = Eigen::Vector3d::UnitZ();  ///< unit axis in the parent node's axes
  double phi0 = 0.0, phidot0 = 0.0;                   ///< initial angle and rate
  Drive drive;                                        ///< empty: phi is a dof
  int dof = -1;                                       ///< -1 when driven or a follower
  /// A follower (ModelBuilder::add_follower_hinge): a hinge made redundant by a closed loop of rigid
  /// bodies (coaxial with `leader` between the same two bodies), no dof and no child node of its own;
  /// phi = follow_sign phi_leader + follow_offset (for the output); force elements act on the leader.
  HingeIndex leader;
  double follow_sign = 1.0, follow_offset = 0.0;
  bool follower() const { return leader.valid(); }
};

struct HingeOptions {
  double phi0 = 0.0;     ///< initial angle; node poses given to the builder are at this angle
  double phidot0 = 0.0;
  Drive drive;           ///< prescribed motion (phi0/phidot0 then come from the drive at t = 0)
};

struct FlexibleBodyOptions {
  InertiaModel inertia = InertiaModel::Simplified;
  TangentModel tangent = TangentModel::Exact;
  FrameRecovery recovery = FrameRecovery::Newton6;
  double stiffness_damping = 0.0;   ///< beta: damping D = beta K (formulation 2.6) [s]
  double modal_damping = 0.0;       ///< damping ratio of the internal modes
  double placement_tolerance = 1e-6;///< allowed mismatch of interface nodes, relative to body size
  /// Stress stiffening from the superelement's geometric-stiffness invariants, when it has them
  /// (docs/geometric-stiffening.md); false: the linear elastic body.
  bool geometric_stiffening = true;
  /// Evaluate the body's interface loads in every output sample (FlexibleBodySample::interface_load):
  /// an output sample without the residual then also forms the inertia and damping forces.
  bool interface_loads = false;
};

struct FlexibleBody {
  std::string name;
  SuperelementIndex se;
  std::vector<NodeIndex> nodes;          ///< one per interface, in the superelement's order
  std::vector<Eigen::Matrix3d> R_NI;     ///< interface triad in the node's axes (constant)
  Pose X_WB0;                            ///< floating frame at t = 0 (undeformed placement)
  FlexibleBodyOptions options;
  int eta_dof = -1;                      ///< first dof of the internal modes (m > 0)
  int eta_offset = 0;                    ///< position of its modes in State::eta
};

struct RigidBody {
  std::string name;
  SuperelementIndex se;
  NodeIndex anchor;
  Eigen::Matrix3d R_NB = Eigen::Matrix3d::Identity();   ///< body frame in the anchor node's axes
  Eigen::Vector3d p_NBo_N = Eigen::Vector3d::Zero();    ///< body origin from the anchor, anchor axes
  std::vector<NodeIndex> nodes;                          ///< interface nodes (anchor and its slaves)
  double mass = 0.0;
  Eigen::Vector3d p_BoCm_B = Eigen::Vector3d::Zero();
  Eigen::Matrix3d I_Cm_B = Eigen::Matrix3d::Zero();
};

/// Force and moment on a node: world-fixed directions, or following the node's triad.
struct NodeLoad {
  std::string name;
  NodeIndex node;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   ///< [N]
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  ///< [N m]
  bool follower = false;                             ///< components in the node's axes if true
  std::function<double(double t)> scale;             ///< time history (empty: 1)
};

struct Model {
  std::vector<Node> nodes;
  std::vector<Hinge> hinges;
  std::vector<AicElement> superelements;      ///< precomputed AIC data, shared by bodies
  std::vector<FlexibleBody> flexible_bodies;
  std::vector<RigidBody> rigid_bodies;
  std::vector<NamedForceElement> force_elements;
  std::vector<NodeLoad> loads;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  ///< [m/s^2], world

  // Derived by ModelBuilder::build().
  int num_dofs = 0;
  int num_modal = 0;                          ///< size of State::eta
  double length_scale = 1.0;                  ///< size of the model (tolerances)
  std::vector<std::vector<int>> node_dofs;    ///< dofs each node's pose depends on (sorted)
  std::vector<std::string> dof_labels;        ///< "node 'n3' rz", "hinge 'HL1'", "body 'yoke' eta 2"
  std::vector<char> dof_kind;                 ///< 't' translation, 'r' rotation, 'h' hinge, 'e' mode
  Eigen::VectorXd dof_weight;                 ///< 1 / natural scale of each dof (increments, errors)
  std::vector<int> rotation_dof_starts;       ///< first rotation dof of each Free node
  std::vector<int> dof_node;                  ///< 't','r': its Free node; 'h': the hinge's child node; 'e': -1
  std::vector<int> dof_owner;                 ///< 'h': hinge index; 'e': flexible body index; else -1

  const Node& node(NodeIndex i) const { return nodes.at(static_cast<std::size_t>(i.value)); }
  const Hinge& hinge(HingeIndex i) const { return hinges.at(static_cast<std::size_t>(i.value)); }
  const AicElement& superelement(SuperelementIndex i) const { return superelements.at(static_cast<std::size_t>(i.value)); }
  /// Whether body b is stress-stiffened: asked for, and its superelement carries the invariants.
  bool stiffened(const FlexibleBody& b) const { return b.options.geometric_stiffening && superelement(b.se).has_stiffening(); }
};

/// Pose of interface j of a superelement placed with its floating frame at X_WB (undeformed).
Pose interface_pose(const se::Superelement& s, int j, const Pose& X_WB);

/// Builds a Model; every add_* checks its input and throws InputError naming the item.
class ModelBuilder {
 public:
  NodeIndex add_node(const std::string& name, const Pose& X_WN);
  NodeIndex add_ground(const std::string& name, const Pose& X_WN);
  /// A node rigidly attached to `parent` (pose given at t = 0).
  NodeIndex add_attached_node(const std::string& name, NodeIndex parent, const Pose& X_WN);
  /// A revolute hinge on `parent` about axis_W (world components at t = 0, through the parent node).
  /// Creates the child node, coincident with the parent, with triad R_WC0 (default: the parent's).
  HingeIndex add_hinge(const std::string& name, NodeIndex parent, const Eigen::Vector3d& axis_W,
                       const HingeOptions& options = {});
  HingeIndex add_hinge(const std::string& name, NodeIndex parent, const Eigen::Vector3d& axis_W,
                       const Eigen::Matrix3d& R_WC0, const HingeOptions& options);
  /// A hinge that the model's kinematics already fixes (docs/scenes.md, "Closed loops of rigid bodies"):
  /// phi = sign phi_leader + (phi0 - sign phi0_leader), sign = +1 or -1 (axes the same or opposite).
  /// No force element may act on it (put them on the leader: build() refuses them).
  HingeIndex add_follower_hinge(const std::string& name, HingeIndex leader, double sign, double phi0 = 0.0);
  NodeIndex hinge_child(HingeIndex h) const { return model_.hinges.at(static_cast<std::size_t>(h.value)).child; }
  void set_initial_velocity(NodeIndex free_node, const Eigen::Vector3d& v_W, const Eigen::Vector3d& w_W);

  SuperelementIndex add_superelement(const se::Superelement& s);  ///< keeps a copy
  SuperelementIndex add_superelement(std::shared_ptr<const se::Superelement> s);  ///< shares it
  /// A flexible body on existing nodes (one per interface). Its interface nodes must lie where
  /// X_WB places the superelement's interfaces (within options.placement_tolerance x body size).
  FlexibleBodyIndex add_flexible_body(const std::string& name, SuperelementIndex se, const std::vector<NodeIndex>& nodes,
                                      const Pose& X_WB, const FlexibleBodyOptions& options = {});
  /// A rigid body with the superelement's mass properties, anchored at an existing node that sits
  /// at interface `anchor_interface` (or at the body origin when anchor_interface = -1); its other
  /// interfaces become new nodes rigidly attached to the anchor (RigidBody::nodes).
  RigidBodyIndex add_rigid_body(const std::string& name, SuperelementIndex se, NodeIndex anchor, int anchor_interface,
                                const Pose& X_WB);
  const RigidBody& rigid_body(RigidBodyIndex b) const { return model_.rigid_bodies.at(static_cast<std::size_t>(b.value)); }

  ForceElementIndex add_force_element(const std::string& name, const ForceElement& fe);
  LoadIndex add_load(const NodeLoad& load);
  void set_gravity(const Eigen::Vector3d& g_W) { model_.gravity = g_W; }

  const Model& model() const { return model_; }
  const se::Superelement& source(SuperelementIndex i) const { return *sources_.at(static_cast<std::size_t>(i.value)); }
  /// Number the dofs, derive the per-node dependencies, and hand the model over.
  Model build();

 private:
  void check_node(NodeIndex n, const std::string& who) const;
  void check_hinge(HingeIndex h, const std::string& who) const;
  NodeIndex push_attached(const std::string& name, NodeIndex parent, const Pose& X_WN, HingeIndex hinge, double phi0,
                          const Eigen::Vector3d& axis_P);
  Model model_;
  std::vector<std::shared_ptr<const se::Superelement>> sources_;
  std::vector<bool> prepared_;  ///< AIC data computed (the superelement is used by a flexible body)
};

}  // namespace seflex::mbd
