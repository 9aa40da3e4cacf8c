#pragma once
// The Craig-Bampton superelement as plain data: everything the multibody formulation needs from a
// reduced FE model, computed once by reduction/ and stored in a superelement file by io/.
// mbd/ depends on this header only (never on fem/ or io/).
//
// Body frame B: origin at the floating-frame node f (an FE node, usually not an interface node),
// axes parallel to the FE model's basic axes. All vectors and matrices below are in B.
//
// Reduced coordinates (formulation.md sections 1.2 and 2.5), size n = 6N + m:
//   q = [u_1; theta_1; ...; u_N; theta_N; eta_1 ... eta_m]
// u_j, theta_j: elastic displacement and rotation of interface node j (constraint-mode amplitudes,
// raw, not orthonormalised); eta: amplitudes of the m mass-normalised fixed-interface modes.
// FE displacement field (6 dofs per FE node, node-major): U = recovery * q.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "seflex/superelement/inertia_invariants.hpp"
#include "seflex/superelement/stiffening_invariants.hpp"

namespace seflex::se {

/// One interface node of the body.
struct InterfaceNode {
  int id = 0;                                        ///< FE grid id
  Eigen::Vector3d p_BoN_B = Eigen::Vector3d::Zero(); ///< undeformed position from the frame origin (x_j)
  Eigen::Matrix3d R_BN = Eigen::Matrix3d::Identity();///< nodal triad in B (C_j); identity for basic-axes dofs
};

/// A cell of the FE mesh kept for animation (indices into Superelement::fe_node_ids).
struct MeshCell {
  enum class Type : std::uint8_t { Line = 2, Triangle = 3, Quad = 4 };
  Type type = Type::Line;
  std::array<std::int32_t, 4> nodes{-1, -1, -1, -1};
  std::int32_t element_id = 0;  ///< FE element id (for display)
};

/// What the chosen modes keep of the full model's dynamics ("model no more than a scene needs").
struct TruncationReport {
  /// Fraction of the rigid-body mass (per direction x, y, z, rx, ry, rz, about the frame origin)
  /// captured by the fixed-interface modes kept, relative to all fixed-interface modes: modal
  /// effective mass of the kept modes over the total effective mass of the interior.
  std::array<double, 6> effective_mass_fraction{};
  double first_neglected_hz = 0.0;  ///< lowest fixed-interface frequency not kept (0 = none computed)
  double max_kept_hz = 0.0;
};

struct Superelement {
  // ---- identity and provenance
  std::string name;                 ///< body name (defaults to the source file stem)
  std::string units = "SI";         ///< unit system of the source model (SI: m, kg, s, N)
  std::string seflex_version;
  std::string source_file;          ///< path as given to `seflex reduce`
  std::string source_hash;          ///< SHA-256 (hex) of the source model's bytes (all included files)
  std::string created;              ///< ISO-8601 UTC time of the reduction
  /// Warnings `seflex reduce` printed about the source model (cards the reduction did not use or
  /// read with an approximation; solutions/card_usage.hpp), one line each; shown again by export.
  std::vector<std::string> source_warnings;

  // ---- frame and interfaces
  int frame_node_id = 0;                                   ///< FE grid id of node f
  Eigen::Vector3d p_OBo = Eigen::Vector3d::Zero();         ///< frame origin in the FE model's basic system (X_f)
  std::vector<InterfaceNode> interfaces;                   ///< N interface nodes, in the order of q
  int num_modes = 0;                                       ///< m fixed-interface modes
  Eigen::VectorXd mode_frequencies_hz;                     ///< m

  // ---- reduced matrices, n x n with n = 6N + m
  Eigen::MatrixXd K;                ///< Psi^T K_FE Psi etc. (block-diagonal between q_b and eta)
  Eigen::MatrixXd M;
  Eigen::MatrixXd Phi_f;            ///< 6 x n: the frame node's rows of the CB basis

  // ---- rigid-body mass properties of the full FE model (in B)
  double mass = 0.0;
  Eigen::Vector3d p_BoCm_B = Eigen::Vector3d::Zero();      ///< centre of mass from the frame origin
  Eigen::Matrix3d I_Cm_B = Eigen::Matrix3d::Zero();        ///< inertia tensor about the centre of mass

  // ---- full-mesh data (recovery, full inertia, animation)
  std::vector<int> fe_node_ids;                            ///< n_fe FE grid ids
  Eigen::Matrix3Xd p_BoI_B;                                ///< 3 x n_fe undeformed FE node positions from the frame origin
  Eigen::MatrixXd recovery;                                ///< 6 n_fe x n: U = recovery * q (Psi | Phi_n)
  Eigen::SparseMatrix<double> M_fe;                        ///< 6 n_fe square FE mass (WTMASS applied); may be empty
  std::vector<MeshCell> cells;

  TruncationReport truncation;

  // ---- inertia invariants (full inertia without the mesh; inertia_invariants.hpp); n == 0 when absent
  InertiaInvariants invariants;
  // ---- geometric-stiffness invariants (stress stiffening; stiffening_invariants.hpp); n == 0 when absent
  StiffeningInvariants stiffening;

  int num_interfaces() const { return static_cast<int>(interfaces.size()); }
  int size() const { return 6 * num_interfaces() + num_modes; }
};

/// Structural checks of a superelement (sizes, finiteness, symmetry of K and M within `sym_tol`
/// relative to their largest entry). Returns human-readable problems; empty when consistent.
inline std::vector<std::string> check_consistency(const Superelement& s, double sym_tol = 1e-9) {
  std::vector<std::string> problems;
  const Eigen::Index n = s.size();
  auto dims = [](const auto& A) { return std::to_string(A.rows()) + "x" + std::to_string(A.cols()); };
  if (s.interfaces.empty()) problems.push_back("no interface nodes");
  if (s.num_modes < 0) problems.push_back("negative mode count");
  if (s.K.rows() != n || s.K.cols() != n) problems.push_back("K is " + dims(s.K) + ", expected " + std::to_string(n) + " square");
  if (s.M.rows() != n || s.M.cols() != n) problems.push_back("M is " + dims(s.M) + ", expected " + std::to_string(n) + " square");
  if (s.Phi_f.rows() != 6 || s.Phi_f.cols() != n) problems.push_back("Phi_f is " + dims(s.Phi_f) + ", expected 6x" + std::to_string(n));
  if (s.mode_frequencies_hz.size() != s.num_modes) problems.push_back("mode frequency count differs from the mode count");
  const auto nfe = static_cast<Eigen::Index>(s.fe_node_ids.size());
  if (s.p_BoI_B.cols() != nfe) problems.push_back("FE node positions do not match the FE node count");
  if (s.recovery.size() != 0 && (s.recovery.rows() != 6 * nfe || s.recovery.cols() != n))
    problems.push_back("recovery is " + dims(s.recovery) + ", expected " + std::to_string(6 * nfe) + "x" + std::to_string(n));
  if (s.M_fe.size() != 0 && (s.M_fe.rows() != 6 * nfe || s.M_fe.cols() != 6 * nfe))
    problems.push_back("M_fe is " + dims(s.M_fe) + ", expected " + std::to_string(6 * nfe) + " square");
  for (const auto& c : s.cells)
    for (int k = 0; k < static_cast<int>(c.type); ++k)
      if (c.nodes[k] < 0 || c.nodes[k] >= nfe) { problems.push_back("mesh cell references a node index out of range"); break; }
  if (!problems.empty()) return problems;
  auto finite = [](const auto& A) { return A.size() == 0 || A.allFinite(); };
  if (!finite(s.K)) problems.push_back("K has non-finite entries");
  if (!finite(s.M)) problems.push_back("M has non-finite entries");
  if (!finite(s.Phi_f)) problems.push_back("Phi_f has non-finite entries");
  if (!finite(s.recovery)) problems.push_back("recovery has non-finite entries");
  if (!std::isfinite(s.mass) || !(s.mass >= 0.0)) problems.push_back("mass is not a finite non-negative number");
  auto sym = [&](const Eigen::MatrixXd& A, const char* name) {
    const double scale = A.cwiseAbs().maxCoeff();
    const double asym = (A - A.transpose()).cwiseAbs().maxCoeff();
    if (!(asym <= sym_tol * scale)) problems.push_back(std::string(name) + " is not symmetric");
  };
  if (n > 0 && problems.empty()) {
    sym(s.K, "K");
    sym(s.M, "M");
  }
  return problems;
}

}  // namespace seflex::se
