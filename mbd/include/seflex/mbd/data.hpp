#pragma once
// Scratch of the multibody algorithms (Model/State/Data split): node kinematics, per-body kernel
// results, the assembled residual and matrices on a fixed sparse pattern, the sparse LU.
// Made once per model (Data data(model)); every algorithm overwrites what it uses.
#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <array>
#include <vector>

#include "seflex/mbd/assembly/iteration_matrix.hpp"
#include "seflex/mbd/bodies/aic_element.hpp"
#include "seflex/mbd/forces/hinge_force.hpp"
#include "seflex/mbd/model.hpp"

namespace seflex::mbd {

using Vector6d = Eigen::Matrix<double, 6, 1>;

/// Pose, twist and acceleration of one node, the Jacobian of its pose with respect to the dofs in
/// Model::node_dofs (columns [dr; dpi]), and the residual wrench accumulated on it.
struct NodeKinematics {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  Eigen::Vector3d v = Eigen::Vector3d::Zero(), w = Eigen::Vector3d::Zero();
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), alpha = Eigen::Vector3d::Zero();
  std::vector<Vector6d> J;
  std::vector<Vector6d> G;             ///< d[a; alpha]/dv at fixed vdot (convective terms), same columns as J
  Vector6d wrench = Vector6d::Zero();  ///< [force; moment about the node], world
  Vector6d subtree = Vector6d::Zero(); ///< wrench of the node and its descendants, about the node
};

struct HingeKinematics {
  Eigen::Vector3d axis_W = Eigen::Vector3d::UnitZ();
  double phi = 0.0, phidot = 0.0, phiddot = 0.0;
  double joint_torque = 0.0;  ///< torque the hinge transmits about its axis (driven: drive torque)
};

/// How the node-space rows of one element map onto its dof clique: per node block (6 rows) the
/// node's Jacobian columns and their clique positions (identity for a Free node), then scalar rows
/// (modal dofs) with their clique positions.
struct ElementMap {
  std::vector<const std::vector<Vector6d>*> J;
  std::vector<const std::vector<int>*> pos;
  std::vector<char> identity;
  const std::vector<int>* extra = nullptr;
  int rows() const { return 6 * static_cast<int>(J.size()) + (extra ? static_cast<int>(extra->size()) : 0); }
};

/// Scratch of one flexible body's assembly, sized at its first evaluation and reused.
struct FlexibleBodyScratch {
  AicWorkspace aic;
  InertiaResult inertia;
  std::vector<Eigen::Matrix3d> R_WI;
  std::vector<Eigen::Vector3d> p_WI;
  Eigen::VectorXd v, a, f, w, fw, sc, xd, yd;
  Eigen::MatrixXd Kl, D, DT, Cd;      ///< D: the damping matrix in body axes (constant, made once)
  Eigen::MatrixXd DR, RDT;            ///< n x 6, 6 x n: damping products with the rigid modes
  ElementMap map, gmap;
  std::vector<const std::vector<Vector6d>*> G;
  std::vector<Eigen::MatrixXd> Y;     ///< scatter blocks
  Eigen::MatrixXd X;                  ///< the body's share of the iteration matrix (AssemblyOptions::iteration)
  std::vector<const std::vector<std::array<int, 2>>*> triples;  ///< per interface: Data::node_rotation_triples of its node
  std::vector<std::vector<Vector6d>> JB, GB;  ///< per interface: its node's J and G columns in body axes
  std::vector<const std::vector<Vector6d>*> GBp;
  ElementMap bmap;                    ///< the body's map with the columns in body axes
  StiffeningLoads stiffening_loads = StiffeningLoads::Zero();  ///< load factors of the stiffening (aic_stiffening.cpp)
};

struct FlexibleBodyData {
  AicKinematics kin;
  Eigen::VectorXd f_el, f_in, f_damp;  ///< n each (world on the interface part)
  double kinetic = 0.0, elastic = 0.0;
  FlexibleBodyScratch scratch;
};

struct RigidBodyData {
  Vector6d f = Vector6d::Zero();  ///< inertia wrench at the anchor
  double kinetic = 0.0;
  Eigen::Vector3d p_WCm = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 6, Eigen::Dynamic> J, G, XY;  ///< scratch: anchor Jacobian, convective terms, X6 Y
  Eigen::MatrixXd JtXY;                               ///< scratch: J^T X6 Y on the clique
};

/// Sparse pattern made of dense cliques (body, node and force-element dof sets).
struct CliquePattern {
  std::vector<std::vector<int>> dofs;     ///< per clique, sorted
  std::vector<std::vector<int>> offsets;  ///< per clique: value index of (dofs[a], dofs[b]) at a + n*b
  Eigen::SparseMatrix<double> matrix;     ///< the pattern (values are scratch)
};

struct Data {
  explicit Data(const Model& model);

  std::vector<NodeKinematics> nodes;
  std::vector<HingeKinematics> hinges;
  std::vector<FlexibleBodyData> flex;
  std::vector<RigidBodyData> rigid;
  std::vector<HingeForceResult> forces;

  // Assembly output.
  Eigen::VectorXd residual;  ///< num_dofs: inertia + damping + internal - external
  Eigen::VectorXd scale;     ///< num_dofs: sum of |contributions| (residual scale)
  Eigen::VectorXd floor;     ///< num_dofs: round-off level of the residual (stiffness x eps x position)
  CliquePattern pattern;
  std::vector<int> clique_of_flex, clique_of_rigid, clique_of_node, clique_of_force;
  std::vector<std::vector<std::vector<int>>> flex_node_pos;  ///< [body][interface][k] clique position of node_dofs[k]
  std::vector<std::vector<int>> flex_eta_pos;                ///< [body][k] clique position of eta dof k
  std::vector<double> K, C, M;  ///< values on the pattern
  std::vector<double> K_rotated;  ///< K with the rotation columns times J_l (combine_matrices)
  /// The flexible bodies' share of the iteration matrix, when assembled with AssemblyOptions::iteration
  /// (S_flex_for: its coefficients; S_flex_filled: this assembly made it).
  std::vector<double> S_flex;
  IterationMatrix S_flex_for;
  bool S_flex_filled = false;
  /// Per node: the first column of each Free node's rotation triple among its Jacobian columns, and
  /// that Free node's index in Model::rotation_dof_starts (the columns T right-multiplies).
  std::vector<std::vector<std::array<int, 2>>> node_rotation_triples;
  Eigen::VectorXd hinge_phi, hinge_phidot;  ///< scratch of the force-element assembly
  std::vector<int> force_pos;

  /// Factorise a matrix on the pattern (iteration matrix, mass, tangent stiffness): a dense LU with
  /// partial pivoting up to kDenseDofs dofs (no allocation once sized; the cost of a 100-dof dense
  /// factorisation is that of assembling it), the sparse LU (pattern analysed once) above.
  /// False when the matrix is singular.
  bool factorize(const Eigen::SparseMatrix<double>& S);
  /// x = -S^-1 r with the last factorisation (the Newton correction of residual r; x is resized
  /// only when its size differs).
  void solve_negated(const Eigen::VectorXd& r, Eigen::VectorXd& x) const;
  static constexpr int kDenseDofs = 150;

 private:
  Eigen::MatrixXd dense_;
  Eigen::PartialPivLU<Eigen::MatrixXd> dense_lu_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
  bool analyzed_ = false;
};

}  // namespace seflex::mbd
