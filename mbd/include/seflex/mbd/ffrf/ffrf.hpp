#pragma once
// The classic floating frame of reference formulation with Lagrange multipliers (FFRF-LM), and
// rigid bodies with multipliers (rigid-LM): the baselines of the AIC formulation (issue 7), run on
// the SAME mbd::Model (docs/ffrf.md has the equations).
//
// Coordinates: per body a floating frame (p_WB; R_WB on SO(3), spatial rotation increments) and,
// for a flexible body, k modal coordinates z of the superelement's Craig-Bampton basis with the
// frame node clamped (the n - 6 dimensional null space of Phi_f, diagonalised: the lowest k
// "frame-clamped" normal modes with mass, mass-normalised), so that the local elastic coordinates of the
// superelement are xi = V z; per undriven hinge its angle (never wrapped). Joints: every body
// interface is constrained to the node it sits on (6 equations), where a node is given by the first
// body that carries it, by ground, or through its parent node and hinge (R_WC = R_WP exp(phi a~) R_PC).
// A hinge between two bodies is therefore 3 position + 3 rotation constraints with the hinge angle
// as an extra coordinate, so force elements and lock laws act on the same unwrapped angle as in AIC.
// Index-3 DAE, Lie-group generalized-alpha (Arnold and Bruls 2007), equations of motion scaled by
// beta h^2 and multipliers mu = beta h^2 lambda (Bottasso, Bauchau and Cardona 2007) for a
// step-independent conditioning; Newton on [h Dq; mu]; step control and lock events as `simulate`.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "seflex/mbd/solvers/integrator.hpp"
#include "seflex/mbd/model.hpp"
#include "seflex/mbd/output.hpp"
#include "seflex/mbd/state.hpp"

namespace seflex::mbd {

struct FfrfOptions {
  bool rigid = false;              ///< every flexible body rigid (mass properties only): rigid-LM
  int modes = -1;                  ///< frame-clamped modes kept per flexible body (-1: all n - 6 that carry mass)
  bool scale_constraints = true;   ///< beta h^2 scaling of the equations of motion and multipliers
  bool condition_estimate = false; ///< 2-norm condition number of each iteration matrix (dense SVD: small models)
  /// How a flexible body's inertia is evaluated: the same terms either way (docs/ffrf.md). Invariants:
  /// a cost O(n^2) per evaluation, never the mesh; nodal: sums over the FE nodes, O(n_fe k), cheaper for
  /// small meshes and the reference of the tests. Auto takes per body whichever costs less (the
  /// nodal sums only when the file carries the FE data).
  enum class Inertia { Auto, Invariants, Nodal };
  Inertia inertia = Inertia::Auto;
  /// Nodal sums only: keep the gyroscopic moment quadratic in the elastic rotation rates, the one
  /// term the invariants leave out (docs/inertia-invariants.md). Off by default, so that Auto's choice
  /// does not change the model.
  bool elastic_gyro = false;
  /// The configuration and velocity derivatives (K, C) of the body forces by central differences over
  /// the body's 6 + k coordinates (4 (6 + k) extra evaluations per body and iteration matrix) instead of
  /// analytically: the previous path, kept as the reference of the tests (docs/ffrf.md).
  bool fd_body_jacobians = false;
  /// The configuration derivatives of the joints (d(G^T lambda)/dq) and of the node loads (d(-J^T F)/dq)
  /// by central differences over each element's coordinates (2 evaluations of the perturbed side's pose
  /// per coordinate) instead of analytically: the previous path, kept as the reference of the tests.
  bool fd_joint_jacobians = false;
  /// Remove the constraint equations that depend on the others at the initial configuration (two
  /// coaxial hinges on one rigid body: docs/ffrf.md, "Redundant constraints"), found by Gram-Schmidt
  /// with re-orthogonalisation over the rows of the scaled constraint Jacobian, in the order of the
  /// joints (the later of two dependent equations goes). Off: every equation is kept (a redundant
  /// model then has a singular iteration matrix).
  bool remove_redundant = true;
  /// A row is dependent when its component orthogonal to the rows kept before it is at most this
  /// fraction of the largest row norm (position rows divided by the model's length scale, columns
  /// equilibrated to a largest entry of 1).
  double redundancy_tolerance = 1e-6;
};

/// One constraint equation removed as dependent on the others (docs/ffrf.md, "Redundant constraints").
struct RedundantEquation {
  int equation = -1;       ///< row 6 c + k of the constraint equations (c: FfrfSystem::constraints)
  std::string joint;       ///< "hinge 'HL2b'", or the body interface and node it joins
  std::string direction;   ///< e.g. "translation along x", "rotation about (0, 0, 1)" (world, at t = 0)
};

/// What an FFRF run reports beyond RunStats.
struct FfrfStats {
  RunStats run;
  int coordinates = 0;            ///< generalised coordinates (frames, modes, hinge angles)
  int constraints = 0;            ///< constraint equations (multipliers), those removed as redundant not counted
  double drift_position = 0.0;    ///< max |g_position| over the accepted states [m]
  double drift_rotation = 0.0;    ///< max |g_rotation| [rad]
  double drift_velocity = 0.0;    ///< max |dg_position/dt| [m/s] (index 3: velocities are not enforced)
  double drift_angular = 0.0;     ///< max |dg_rotation/dt| [rad/s]
  double condition_min = 0.0;     ///< over the iteration matrices (condition_estimate only)
  double condition_max = 0.0;
  std::vector<RedundantEquation> redundant;  ///< equations removed at t = 0 (their reactions are indeterminate: zero)
};

/// The removed equations joint by joint, e.g. "hinge 'HL2b': translation along x, y, z; rotation about
/// (1, 0, 0), (0, 1, 0)" (joints separated by " | "); empty when none.
std::string describe_redundant(const std::vector<RedundantEquation>& removed);

/// Integrate `model` from t = 0 to settings.t_end with FFRF-LM (or rigid-LM). Samples go to
/// `observer` as with `simulate` (flexible bodies report xi = V z in the superelement's order).
/// Throws InputError when the model cannot be expressed (a Free node that no body carries; a
/// flexible body whose superelement has neither inertia invariants nor FE recovery/mass data, or no
/// FE data with Inertia::Nodal; unless options.rigid), and
/// ConvergenceError (after delivering the last accepted state) when Newton fails at h_min, or when
/// the rank of the constraint equations changes during the run (equations removed as redundant at
/// t = 0 become independent, or kept ones dependent): the message names the joints.
FfrfStats simulate_ffrf(const Model& model, const IntegratorSettings& settings, const FfrfOptions& options = {},
                        Observer* observer = nullptr);

// ---- The system, exposed for tests and studies --------------------------------------------------

/// One body: coordinates [p_WB (3); rotation (3); z (k)] from `coord` on.
struct FfrfBody {
  std::string name;
  bool flexible = false;            ///< false: rigid kernel (mass, centre of mass, inertia)
  int model_index = -1;             ///< index in Model::flexible_bodies (flexible or made rigid) or rigid_bodies
  bool from_rigid = false;          ///< the source is a Model::rigid_bodies entry
  int coord = 0, k = 0, z_offset = 0;
  Pose X_WB0;
  double mass = 0.0;
  Eigen::Vector3d p_BoCm_B = Eigen::Vector3d::Zero();
  Eigen::Matrix3d I_Cm_B = Eigen::Matrix3d::Zero();
  Eigen::MatrixXd V;                ///< n x k frame-clamped modes: xi = V z, V^T M V = I, Phi_f V = 0
  Eigen::MatrixXd PV;               ///< 6 n_fe x k FE displacements per mode (recovery * V; nodal inertia only)
  Eigen::VectorXd amplitude;        ///< k: largest translation per unit modal coordinate [m] (its natural scale)
  Eigen::MatrixXd MppV;             ///< n x k: Mpp V (the invariants' P^T M P times the modes)
  Eigen::MatrixXd VMppV;            ///< k x k: V^T Mpp V
  Eigen::MatrixXd AV;               ///< (45 n + 72) x k: the stacked invariants AicElement::inv_by_xi times V (d/dz of the inertia)
  Eigen::VectorXd omega2;           ///< k squared frequencies: V^T K V = diag(omega2)
  bool nodal = false;               ///< inertia from the FE node sums (FfrfOptions::inertia), else the invariants
  bool stiffening = false;          ///< geometric stiffening from the superelement's invariants (docs/geometric-stiffening.md)
  double stiffness_damping = 0.0;   ///< beta of D = beta K
  std::vector<NodeIndex> nodes;     ///< one per interface
  std::vector<Pose> X_BN;           ///< node pose in B at z = 0 (rigid: exact; flexible: undeformed)
  std::vector<Eigen::Matrix3d> R_IN;///< flexible: node triad in the interface's (R_NI^T)
};

/// Where a node's pose comes from.
struct FfrfNodeSource {
  enum class Kind { Fixed, Body, Chain } kind = Kind::Fixed;
  int body = -1, interface = -1;  ///< Kind::Body
};

/// Six equations: interface `interface` of body `body` coincides with `node` (as its source gives it,
/// or, when `chain`, as its parent node and hinge give it).
struct FfrfConstraint {
  int body = -1, interface = -1;
  NodeIndex node;
  bool chain = false;
};

struct FfrfSystem {
  const Model* model = nullptr;  ///< must outlive the system
  FfrfOptions options;
  std::vector<FfrfBody> bodies;
  std::vector<FfrfNodeSource> node_source;  ///< per model node
  std::vector<FfrfConstraint> constraints;
  std::vector<int> hinge_coord;             ///< per hinge; -1 when driven
  int num_coords = 0, num_z = 0;
  std::vector<char> kind;                   ///< per coordinate: 't', 'r', 'e' (mode), 'h' (hinge)
  std::vector<int> owner;                   ///< per coordinate: its body ('t', 'r', 'e') or hinge ('h')
  Eigen::VectorXd weight;                   ///< per coordinate: 1 / natural scale
  /// Per equation (6 per constraint): 1 when removed as redundant. A removed equation keeps its row
  /// and multiplier, held at zero (the row of the iteration matrix is the identity on it).
  std::vector<char> removed;
  std::vector<RedundantEquation> redundant; ///< the removed equations, named
  int num_multipliers() const { return 6 * static_cast<int>(constraints.size()); }
  bool is_removed(Eigen::Index equation) const { return !removed.empty() && removed[static_cast<std::size_t>(equation)] != 0; }
};

/// Build the FFRF system of a model (InputError as for simulate_ffrf), its redundant constraint
/// equations at the initial configuration removed (FfrfOptions::remove_redundant).
FfrfSystem make_ffrf_system(const Model& model, const FfrfOptions& options);

struct FfrfState {
  double t = 0.0;
  std::vector<Eigen::Matrix3d> R_WB;  ///< per body
  std::vector<Eigen::Vector3d> p_WB;
  Eigen::VectorXd z;                  ///< modal coordinates of all bodies
  Eigen::VectorXd phi;                ///< per hinge (driven: the drive's value at t)
  Eigen::VectorXd v, vdot, a;         ///< num_coords: [dp/dt; omega (world); dz/dt] per body, then hinge rates
  Eigen::VectorXd lambda;             ///< multipliers: [force (3); moment (3)] per constraint
  std::vector<LockState> locks;       ///< per force element
};

/// The state at t = 0: frames where the model places the bodies, z = 0, velocities from the
/// model's initial node velocities and hinge rates projected onto the velocity constraints
/// (mass-weighted), consistent accelerations and multipliers.
FfrfState ffrf_initial_state(const FfrfSystem& system);

/// Residual R and (if S != nullptr) iteration matrix dR/dx of the Newton system of one
/// generalized-alpha step of size h from s0, at the unknowns x = [h Dq (num_coords); mu
/// (multipliers)]; s1 receives the configuration, velocities, accelerations and multipliers.
void ffrf_step_system(const FfrfSystem& system, const FfrfState& s0, double h, double rho_inf, const Eigen::VectorXd& x,
                      FfrfState& s1, Eigen::VectorXd& R, Eigen::SparseMatrix<double>* S);

/// Constraint residual g (6 per constraint: position [m], rotation log(R_B^T R_A) [rad]) and its
/// time derivative at state s.
void ffrf_constraints(const FfrfSystem& system, const FfrfState& s, Eigen::VectorXd& g, Eigen::VectorXd& gdot);

/// A sample of state s (same content as the AIC solver's).
Sample ffrf_sample(const FfrfSystem& system, const FfrfState& s);

}  // namespace seflex::mbd
