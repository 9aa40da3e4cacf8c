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

/// A pose and its Jacobian: column c < size() = [dp; dpi] (world, spatial rotation) per unit of
/// coordinate cols[c]; a driven hinge h appears as column -(h + 1) (for time derivatives only).
/// Scratch: J holds at least size() columns (only the first size() are meaningful) and grows, never
/// shrinks, so that a PoseJ reused for poses of different widths stops allocating once warm.
struct PoseJ {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  std::vector<int> cols;
  Matrix6Xd J;
  Eigen::Index size() const { return static_cast<Eigen::Index>(cols.size()); }
  /// The columns in use: 6 x size().
  auto jacobian() const { return J.leftCols(size()); }
  /// n columns in use, set to zero (cols resized, entries left to the caller).
  void reset(Eigen::Index n);
  /// One more column (coordinate col), set to zero.
  void push_column(int col);
  /// This pose becomes a copy of `from` (the used columns only: no allocation once the storage is large enough).
  void assign(const PoseJ& from);
};

/// Scratch of the joints' and node loads' analytic tangents (ffrf_joint_tangents.hpp), grown (never
/// shrunk) to the widest element, so that it stops allocating.
struct JointTangentScratch {
  Eigen::MatrixXd HA, HB, K;  ///< the two sides' H and the element's tangent (leading blocks used)
  Eigen::Matrix3Xd Dr, JBr;   ///< constraint: J_A,r - J_B,r and J_B,r over its columns
  PoseJ P;                    ///< a pose evaluated again on the way down a chain
};

/// Pose of the node on interface j of body b, as that body's coordinates give it, into out.
void interface_pose(const FfrfSystem& sys, const FfrfState& s, int b, int j, PoseJ& out);
/// Pose of node k from its source (chain: through its parent and hinge even if a body carries it).
void node_pose(const FfrfSystem& sys, const FfrfState& s, int k, bool chain, PoseJ& out);
/// out: the pose of node k's parent in, node k's (through its offset and hinge) out.
void attach_to_parent(const FfrfSystem& sys, const FfrfState& s, int k, PoseJ& out);

/// g = [p_A - p_B; log(R_B^T R_A)] of constraint c, its Jacobian G (6 x cols.size(), the first
/// columns of G) over cols (union of both sides); A and B are the scratch of the two poses.
struct ConstraintEval {
  Vector6d g = Vector6d::Zero();
  std::vector<int> cols;
  std::vector<int> b_at;  ///< per column of B: its position in cols (combine_constraint)
  Matrix6Xd G;
  PoseJ A, B;
  Eigen::Index size() const { return static_cast<Eigen::Index>(cols.size()); }
  auto jacobian() const { return G.leftCols(size()); }
};
void eval_constraint(const FfrfSystem& sys, const FfrfState& s, int c, ConstraintEval& out);
/// The rest of out (g, cols, G) from its two poses out.A and out.B (eval_constraint = both poses and this).
void combine_constraint(ConstraintEval& out);
/// g and dg/dt of every constraint at s (ffrf_constraints with its scratch: phi, phidot, ce).
void constraint_rates(const FfrfSystem& sys, const FfrfState& s, Eigen::VectorXd& phi, Eigen::VectorXd& phidot, ConstraintEval& ce,
                      Eigen::VectorXd& g, Eigen::VectorXd& gdot);

/// Body force (world: force and moment about the frame origin; modal forces), gravity included:
/// inertia + elastic + damping - gravity, as a function of the body's coordinates, velocities and
/// accelerations in s. M: the mass matrix (if want_mass); K, C: its derivatives w.r.t. the body's
/// coordinates (rotation: R <- exp(dpi~) R, as perturb) and velocities (if want_tangents), analytic
/// (ffrf_body_tangents.cpp).
struct BodyForce {
  Eigen::VectorXd f;
  Eigen::MatrixXd M, K, C;
  double kinetic = 0.0, elastic = 0.0;
  AicWorkspace ws;  ///< scratch of the invariant evaluation
  /// Scratch of one body's evaluation, sized at its first use (a BodyForce serves one body).
  struct Scratch {
    Eigen::VectorXd v, ab, z, fw, xi, g, t6, tk;  ///< body-axis velocities/accelerations, z, body-axis force, xi = V z, ...
    Eigen::MatrixXd Mw, Rh, RhMw;                 ///< body-axis mass, blkdiag(R, R, I), Rh Mw
    Eigen::MatrixXd N, MN;                        ///< nodal sums: N(z) (6 n_fe x nb), M_fe N
    Eigen::VectorXd U, Ud, cfe, gyro, Xd, Xdd, MXd, MXdd;
    // Tangents (body axes): Cw = d fw / d w, Kz = d f_w / d z (nb x k), and their scratch.
    Eigen::MatrixXd Cw, Kz, D, MD, Dz, MDz, nk, nk2, nn, n3, Snb, RhC;
    Eigen::VectorXd Va;
  } scratch;
};
void body_force(const FfrfSystem& sys, const FfrfState& s, int b, bool want_mass, BodyForce& out, bool want_tangents = false);

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
  /// Scratch of the assembly, sized at the first evaluation with matrices (no allocation after it).
  struct Scratch {
    std::vector<BodyForce> fd_bodies;  ///< per body: its perturbed evaluations
    Eigen::VectorXd fp, fm, d, q;      ///< finite differences (at least as long as the element), G^T lambda
    std::vector<int> idx;
    ConstraintEval ce, cp;             ///< a constraint and its perturbed evaluations
    PoseJ pose;                        ///< node loads
    JointTangentScratch jt;            ///< analytic joint and load tangents
    Eigen::VectorXd phi, phidot;       ///< hinge values
    /// Upper bounds of the triplet counts (structural: the same at every evaluation with matrices),
    /// reserved after the first, so that the lists never grow after it.
    std::size_t max_K = 0, max_C = 0, max_M = 0, max_G = 0;
  } scratch;
};
/// Evaluate at s (s is perturbed and restored for the finite differences when `matrices`).
void ffrf_assemble(const FfrfSystem& sys, FfrfState& s, bool matrices, FfrfEval& ev);

/// Drive values or state values of every hinge angle and rate at s.
void hinge_values(const FfrfSystem& sys, const FfrfState& s, Eigen::VectorXd& phi, Eigen::VectorXd& phidot);

/// The sample of `state` into `out`, its storage reused (as make_sample); s and ev are scratch.
struct SampleScratch {
  FfrfState s;
  FfrfEval ev;
  PoseJ pose;
  Eigen::VectorXd phi, phidot;
};
void ffrf_sample(const FfrfSystem& sys, const FfrfState& state, SampleScratch& w, Sample& out);

}  // namespace seflex::mbd::detail
