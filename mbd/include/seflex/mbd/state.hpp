#pragma once
// The changing state of a multibody model (Model/State/Data split):
//  - configuration: poses of Free nodes, hinge angles (never wrapped), internal-mode amplitudes;
//  - generalised velocities v, accelerations vdot and the generalized-alpha algorithmic
//    accelerations a (all of size Model::num_dofs; Free-node entries are [dr/dt; omega] in world
//    components, omega the spatial angular velocity);
//  - the floating frame of each flexible body (warm start of the next frame recovery);
//  - the latch state of each lock.
// Poses of Attached nodes are derived; they are refreshed by update_node_poses (kinematics.hpp).
#include <Eigen/Core>
#include <vector>

#include "seflex/mbd/bodies/aic_element.hpp"
#include "seflex/mbd/model.hpp"

namespace seflex::mbd {

struct LockState {
  bool latched = false;
  double t_latch = 0.0;  ///< time the lock latched (valid when latched)
  double side = 1.0;     ///< +1: the angle approaches phi_lock from below, -1: from above
};

struct State {
  double t = 0.0;
  std::vector<Eigen::Vector3d> p_WN;   ///< per node
  std::vector<Eigen::Matrix3d> R_WN;   ///< per node
  Eigen::VectorXd phi;                 ///< per hinge (driven hinges: the drive's value at t)
  Eigen::VectorXd eta;                 ///< internal-mode amplitudes of all bodies (Model::num_modal)
  Eigen::VectorXd v, vdot, a;          ///< num_dofs each
  std::vector<FloatingFrame> frames;   ///< per flexible body
  std::vector<LockState> locks;        ///< per force element (used by locks)
};

/// The state at t = 0: node poses, hinge angles and rates from the model, accelerations zero
/// (the integrator computes consistent initial accelerations), frames recovered from the nodes.
State initial_state(const Model& model);

/// Set the velocities of all Free nodes and the frames' motion to the rigid motion with
/// velocity v_W of the world origin and angular velocity w_W (hinge rates are left unchanged).
void set_rigid_velocity(const Model& model, State& s, const Eigen::Vector3d& v_W, const Eigen::Vector3d& w_W);

/// The angles of follower hinges (Hinge::leader) from their leaders' in s.
void follow_leaders(const Model& model, State& s);
/// x <- x (+) dx: Free nodes p += dr, R <- exp(dpi) R (spatial); hinge angles and modes add.
void apply_increment(const Model& model, State& s, const Eigen::Ref<const Eigen::VectorXd>& dx);

}  // namespace seflex::mbd
