#pragma once
// Internal pieces of FFRF-LM: poses with their Jacobians, body forces, constraint evaluation and
// assembly (finite-difference configuration and velocity derivatives of each element, locally).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "seflex/mbd/bodies/aic_workspace.hpp"
#include "seflex/mbd/ffrf/ffrf.hpp"
#include "seflex/mbd/forces/hinge_force.hpp"

namespace seflex::mbd::detail {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6Xd = Eigen::Matrix<double, 6, Eigen::Dynamic>;

/// A pose and its Jacobian: column c = [dp; dpi] (world, spatial rotation) per unit of coordinate
/// cols[c]; a driven hinge h appears as column -(h + 1) (for time derivatives only).
struct PoseJ {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  std::vector<int> cols;
  Matrix6Xd J;
};

/// Pose of the node on interface j of body b, as that body's coordinates give it.
PoseJ interface_pose(const FfrfSystem& sys, const FfrfState& s, int b, int j);
/// Pose of node k from its source (chain: through its parent and hinge even if a body carries it).
PoseJ node_pose(const FfrfSystem& sys, const FfrfState& s, int k, bool chain);

/// g = [p_A - p_B; log(R_B^T R_A)] of constraint c, its Jacobian over cols (union of both sides).
struct ConstraintEval {
  Vector6d g = Vector6d::Zero();
  std::vector<int> cols;
  Matrix6Xd G;
};
void eval_constraint(const FfrfSystem& sys, const FfrfState& s, int c, ConstraintEval& out);

/// Body force (world: force and moment about the frame origin; modal forces), gravity included:
/// inertia + elastic + damping - gravity, as a function of the body's coordinates, velocities and
/// accelerations in s. M: the mass matrix (if want_mass).
struct BodyForce {
  Eigen::VectorXd f;
  Eigen::MatrixXd M;
  double kinetic = 0.0, elastic = 0.0;
  AicWorkspace ws;  ///< scratch of the invariant evaluation
};
void body_force(const FfrfSystem& sys, const FfrfState& s, int b, bool want_mass, BodyForce& out);

/// Perturb coordinate i of s by eps (rotation: R <- exp(eps e) R), returning what restores it.
struct Saved {
  Eigen::Matrix3d R;
  double x = 0.0;
};
Saved perturb(const FfrfSystem& sys, FfrfState& s, int i, double eps);
void restore(const FfrfSystem& sys, FfrfState& s, int i, const Saved& saved);
/// Finite-difference step for coordinate i (relative to its natural scale).
double fd_step(const FfrfSystem& sys, int i);

/// Everything evaluated at one state.
struct FfrfEval {
  Eigen::VectorXd r;       ///< num_coords: body forces - loads - force elements + G^T lambda
  Eigen::VectorXd scale;   ///< num_coords: sum of |contributions|
  Eigen::VectorXd g;       ///< 6 per constraint
  std::vector<Eigen::Triplet<double>> K, C, M, G;  ///< dr/dq (spatial increments), dr/dv, dr/dvdot, dg/dq
  std::vector<BodyForce> bodies;
  std::vector<HingeForceResult> forces;
  Eigen::VectorXd joint_torque;  ///< per hinge: a . constraint moment - sum tau (driven: drive torque)
};
/// Evaluate at s (s is perturbed and restored for the finite differences when `matrices`).
void ffrf_assemble(const FfrfSystem& sys, FfrfState& s, bool matrices, FfrfEval& ev);

/// Drive values or state values of every hinge angle and rate at s.
void hinge_values(const FfrfSystem& sys, const FfrfState& s, Eigen::VectorXd& phi, Eigen::VectorXd& phidot);

}  // namespace seflex::mbd::detail
