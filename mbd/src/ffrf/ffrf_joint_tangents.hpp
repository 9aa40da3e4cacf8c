#pragma once
// Analytic configuration tangents of the FFRF-LM joints and node loads (ffrf_joint_tangents.cpp):
// for a pose P with Jacobian J (ffrf_kinematics.cpp) and a world wrench w = [F; M] held fixed,
// H(w) = d(J^T w)/dq over P's columns (rotation increments R <- exp(dpi~) R, as perturb); from it the
// joints' geometric stiffness d(G^T lambda)/dq and the node loads' d(-J^T F)/dq (docs/ffrf.md
// "Joint and node-load tangents").
#include <Eigen/Core>

#include "ffrf/ffrf_detail.hpp"

namespace seflex::mbd::detail {

/// d(J_l(theta)^T u)/dtheta (J_l the left Jacobian, so3::jl), 3 x 3.
Eigen::Matrix3d jl_transpose_tangent(const Eigen::Vector3d& theta, const Eigen::Vector3d& u);
/// d(J_l^-1(theta)^T u)/dtheta (so3::jl_inv), 3 x 3.
Eigen::Matrix3d jl_inv_transpose_tangent(const Eigen::Vector3d& theta, const Eigen::Vector3d& u);

/// The pose of interface j of body b (as interface_pose, into P) and H(w) over its columns into
/// H.topLeftCorner(P.size(), P.size()).
void interface_tangent(const FfrfSystem& sys, const FfrfState& s, int b, int j, const Vector6d& w, PoseJ& P,
                       Eigen::MatrixXd& H);
/// The same for node k as node_pose(sys, s, k, chain) gives it (through its parents and hinges).
void node_tangent(const FfrfSystem& sys, const FfrfState& s, int k, bool chain, const Vector6d& w, PoseJ& P,
                  Eigen::MatrixXd& H);

/// d(G^T lambda)/dq of constraint con (6 multipliers lam) at ce = eval_constraint(...) into
/// w.K.topLeftCorner(ce.size(), ce.size()), over ce.cols.
void constraint_tangent(const FfrfSystem& sys, const FfrfState& s, const FfrfConstraint& con, const ConstraintEval& ce,
                        const Vector6d& lam, JointTangentScratch& w);
/// d(-J^T F)/dq of a node load at its node pose P (node_pose(..., false)), F = the load's world wrench
/// (a follower's turns with the node), into w.K.topLeftCorner(P.size(), P.size()).
void load_tangent(const FfrfSystem& sys, const FfrfState& s, const NodeLoad& load, const PoseJ& P, const Vector6d& F,
                  JointTangentScratch& w);

}  // namespace seflex::mbd::detail
