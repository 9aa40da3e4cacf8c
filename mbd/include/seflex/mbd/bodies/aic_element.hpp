#pragma once
// The absolute-interface-coordinate (AIC) superelement kernel (formulation.md sections 1-3, 2.5):
// everything one flexible body computes from the absolute poses of its N interface nodes.
//
// Frames: W world, B the floating frame (origin at the superelement's frame node f, axes parallel
// to the FE model's basic axes at t = 0), I_j the triad of interface j. Vectors of size
// n = 6N + m are ordered like the superelement's q: [u_1; theta_1; ...; u_N; theta_N; eta].
//
// Per evaluation (AicKinematics): the floating frame (R_WB, p_WBo) is recovered from the interface
// poses by Newton on the frame condition Phi_f xi = 0 (section 1.5, algorithm A "Newton6" or the
// decoupled algorithm B "Decoupled3"), warm-started from the previous frame. Then
//   u_j = R_WB^T (p_WI_j - p_WBo) - x_j,  theta_j = log(R_WB^T R_WI_j C_j^T)        (1.6)
//   Zx = (Phi_fb Phi_rig(u))^-1 [Phi_fb, Phi_fn]          6 x n   frame increments  (1.4, 2.5)
//   Tx = I_n - [Phi_rig(u); 0] Zx                          n x n   local increments
// so that, with w = blockdiag(R_WB^T ..., I_m) [dr_1; dpi_1; ...; deta] (body-axis interface
// increments; spatial rotation increments), d[r_B; pi_B]_B = Zx w and d xi = Tx w.
// Elastic force in body axes f_w = Tx^T K xi (2.2); world: f = Rhat f_w, Rhat = blockdiag(R_WB x 2N, I_m).
// The exact tangent (3) uses Lambda_j = J_l^-1(theta_j); the simplified tangent sets Lambda = I.
#include <Eigen/Core>
#include <array>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "seflex/mbd/bodies/aic_workspace.hpp"
#include "seflex/superelement/superelement.hpp"

namespace seflex::mbd {

enum class FrameRecovery { Newton6, Decoupled3 };
enum class TangentModel { Exact, Simplified };
enum class InertiaModel { Simplified, Full };
/// Which derivatives inertia_force forms besides the force: none; all (Mt, Ct, Kt); or Mt and Kt
/// without Ct (InertiaResult::has_Ct false): a Newton iteration matrix without the gyroscopic/Coriolis
/// tangent, whose weight against the mass is about h |Omega|, so Newton still converges where
/// h |Omega| << 1.
enum class InertiaMatrices { None, All, NoVelocityTangent };

/// The components the kernels leave their n x n matrices in: world (Rhat A Rhat^T, Rhat the frame's
/// rotation on the 2N interface 3-blocks) or the body axes of the floating frame, for a caller that
/// rotates its node maps instead (the flexible body's share of the iteration matrix).
enum class MatrixAxes { World, Body };

/// Configuration-independent data of one superelement, precomputed once (make_aic_element).
struct AicElement {
  std::string name;
  int N = 0;  ///< interface nodes
  int m = 0;  ///< internal (fixed-interface) modes
  int n = 0;  ///< 6N + m
  std::vector<Eigen::Vector3d> x;  ///< x_j = p_BoI_B of interface j (undeformed)
  std::vector<Eigen::Matrix3d> C;  ///< C_j = R_BI of interface j (undeformed triad in B)
  Eigen::MatrixXd Phi_f;           ///< 6 x n frame-node rows of the CB basis
  Eigen::MatrixXd K, M;            ///< n x n reduced stiffness and mass
  double length = 1.0;             ///< size of the body (max |x_j|, at least 1e-3): scales tolerances
  double K_abs_max = 0.0;          ///< largest |K_ij| (round-off level of the elastic force)

  // Rigid-body mass properties implied by M (Phi_rig0^T M_bb Phi_rig0), about the frame origin, in B.
  double mass = 0.0;
  Eigen::Vector3d p_BoCm_B = Eigen::Vector3d::Zero();
  Eigen::Matrix3d I_Cm_B = Eigen::Matrix3d::Zero();

  // Full inertia (section 2.4) from the inertia invariants (docs/inertia-invariants.md): taken from
  // the superelement, or computed here from its recovery and M_fe when the file predates them.
  se::InertiaInvariants inv;
  // The same invariants stacked for the time loop (made by make_aic_element): one product with xi
  // and one with xi_dot = Tx w give every contraction of an evaluation; row layout in
  // StackedInvariantRows (aic_inertia.cpp reads them in place).
  //
  // xi and xi_dot = Tx w always satisfy the frame condition Phi_f xi = 0 (Phi_f Tx = 0, formulation
  // 1.3-1.4), so they live in the (n - 6)-dimensional null space of Phi_f: xi = V_f (V_f^T xi). The
  // stacked invariants are kept multiplied by V_f, and every contraction reads (n - 6) columns
  // instead of n (docs/inertia-invariants.md, "The frame condition").
  Eigen::MatrixXd V_f;                       ///< n x (n - 6): orthonormal basis of null(Phi_f)
  Eigen::MatrixXd inv_by_xi;                 ///< (45 n + 72) x (n - 6): the xi-stack times V_f
  Eigen::MatrixXd inv_by_xid;                ///< (6 n + 27) x (n - 6): the xi_dot-stack times V_f
  std::array<Eigen::MatrixXd, 3> inv_GPV;    ///< n x n: PmGP[a] + PgOV[a]

  // Geometric-stiffness invariants (se::StiffeningInvariants, docs/geometric-stiffening.md): k = 12 + 6N
  // symmetric n x n matrices G_c, the 12 inertia load cases, then the 6N constraint modes. They span a
  // space of dimension r <= k, on real bodies far below k (the rigid motions of the interfaces stress
  // nothing; a plate's bending cases no membrane; docs/geometric-stiffening.md, "The rank of the
  // invariants"), kept as G_c = sum_i U_i W(i, c) with r orthonormal symmetric U_i: every product
  // reads r matrices, not k.
  // Empty (r = 0) when the superelement carries none or all its G_c vanish.
  Eigen::MatrixXd G_basis;        ///< n x r n: [U_0 ... U_{r-1}] side by side (column-major: n^2 x r)
  Eigen::MatrixXd G_coef;         ///< r x k: W, G_c = sum_i U_i W(i, c)
  Eigen::MatrixXd G_basis_t_V;    ///< r n x (n - 6): G_basis^T V_f, so that [U_i xi]_i = G_basis_t_V (V_f^T xi)
  Eigen::MatrixXd G_foreshortening;  ///< r x r: W_b Kbb^+ W_b^T (W_b: W's 6N interface columns)
  /// 6N x 6N pseudo-inverse of K's interface block (its null space: the rigid motions): the compliance
  /// through which the bending's foreshortening loads the interface (the quartic energy term).
  Eigen::MatrixXd Kbb_pinv;
  bool stiffening = false;  ///< the superelement carries geometric-stiffness invariants
  bool has_stiffening() const { return stiffening; }

  // FE-level data (FFRF baseline, the nodal reference of the tests); present when the superelement
  // carries recovery and M_fe.
  bool has_fe_data = false;
  Eigen::MatrixXd Psi;                    ///< 6 n_fe x n recovery matrix [Psi | Phi_n]
  Eigen::SparseMatrix<double> M_fe;       ///< 6 n_fe square FE mass
  Eigen::Matrix3Xd X;                     ///< undeformed FE node positions from the frame origin
  std::vector<Eigen::Matrix3d> J_node;    ///< rotary inertia block of each FE node (gyroscopic term)
  Eigen::VectorXd eta_amplitude;          ///< m: largest FE translation of mode k per unit eta [m]
  Eigen::VectorXd omega_modes;            ///< m: sqrt(K_kk / M_kk) of the internal modes (rad/s)
};

/// First rows of each invariant in AicElement::inv_by_xi (a) and inv_by_xid (b), for size n.
struct StackedInvariantRows {
  explicit StackedInvariantRows(Eigen::Index n)
      : HP(0), HE0(3 * n), HE1(3 * n + 18), LP(12 * n + 18), E0LP(18 * n + 18), HLX(18 * n + 54), HLP(18 * n + 72),
        HGP(36 * n + 72), by_xi(45 * n + 72), PmGP(0), E0mGP(3 * n), PgOV(3 * n + 18), EgOV(6 * n + 18),
        by_xid(6 * n + 27) {}
  // (a) times xi: HP 3n, HE0 18, HE1 9n, PmLP[s] n each, E0mLP[s] 6 each, HLX 18, HLP[s] 3n each, HGP[a] 3n each.
  Eigen::Index HP, HE0, HE1, LP, E0LP, HLX, HLP, HGP, by_xi;
  // (b) times xi_dot: PmGP[a] n each, E0mGP[a] 6 each, PgOV[a] n each, EgOV[a] 3 each.
  Eigen::Index PmGP, E0mGP, PgOV, EgOV, by_xid;
};

/// Validate a superelement for the AIC formulation and precompute its data.
/// Throws InputError (naming the superelement) when sizes are inconsistent, the frame node rows do
/// not reproduce rigid motion (Phi_f Phi_rig0 = I within 1e-6), or K/M are not symmetric.
AicElement make_aic_element(const se::Superelement& s);

/// Pose of the floating frame B in W.
struct FloatingFrame {
  Eigen::Matrix3d R_WB = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p_WBo = Eigen::Vector3d::Zero();
};

/// Configuration-dependent kernel quantities of one body at one evaluation.
struct AicKinematics {
  FloatingFrame frame;
  Eigen::VectorXd xi;       ///< n local elastic coordinates [q; eta]
  Eigen::MatrixXd Phi_rig;  ///< 6N x 6 rigid modes at the deformed interface positions
  Eigen::MatrixXd Zx;       ///< 6 x n: frame increment per local increment (Lambda = I)
  Eigen::MatrixXd ZxL;      ///< the same with Lambda: exact frame/local increments (section 3)
  // Tx = I - [Phi_rig; 0] Zx (n x n) has a rank-6 defect and is never formed in the time loop:
  // apply_transfer / apply_transfer_transpose apply it in O(6n); transfer_matrix forms it.
  std::vector<Eigen::Matrix3d> Lambda;  ///< N blocks J_l^-1(theta_j)
  int iterations = 0;       ///< frame-recovery iterations used
};

/// Recover the floating frame from the interface poses (R_WI[j], p_WI[j]) and the modal
/// coordinates eta (size m), starting from `frame` (warm start), and fill `kin`.
/// Throws ConvergenceError naming the body when the recovery does not converge in 30 iterations
/// (deformation far outside the small-strain range). Allocates nothing once `kin` is sized (the
/// time loop keeps one per body).
void recover_frame(const AicElement& e, const std::vector<Eigen::Matrix3d>& R_WI,
                   const std::vector<Eigen::Vector3d>& p_WI, const Eigen::Ref<const Eigen::VectorXd>& eta,
                   FrameRecovery method, const FloatingFrame& warm_start, AicKinematics& kin);

/// y = Tx x and y = Tx^T x in O(6n), Tx = I - [Phi_rig; 0] Zx (formulation 1.6).
void apply_transfer(const AicElement& e, const AicKinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& x,
                    Eigen::VectorXd& y);
void apply_transfer_transpose(const AicElement& e, const AicKinematics& kin,
                              const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::VectorXd& y);
/// Tx formed (n x n): for reference evaluations and tests, not for the time loop.
Eigen::MatrixXd transfer_matrix(const AicElement& e, const AicKinematics& kin);

/// A first guess of the floating frame from interface 0 (used at t = 0).
FloatingFrame frame_guess(const AicElement& e, const Eigen::Matrix3d& R_WI0, const Eigen::Vector3d& p_WI0);

/// Elastic force f (n; world components on the 6N interface part: forces and moments about the
/// interface nodes; generalised forces on eta) and, if Kt != nullptr, its tangent (n x n) with
/// respect to [dr_1; dpi_1; ...; deta] (spatial rotation increments; world components, or body axes
/// with MatrixAxes::Body). Formulation sections 2.2, 3.
void elastic_force(const AicElement& e, const AicKinematics& kin, TangentModel tangent, Eigen::VectorXd& f,
                   Eigen::MatrixXd* Kt);
void elastic_force(const AicElement& e, const AicKinematics& kin, TangentModel tangent, Eigen::VectorXd& f,
                   Eigen::MatrixXd* Kt, AicWorkspace& ws, MatrixAxes axes = MatrixAxes::World);

/// Geometric stiffening (docs/geometric-stiffening.md). The load factors of the 12 inertia load cases
/// of se::StiffeningInvariants at this evaluation, body axes: [a_o - g; alpha; w_s(Om~ Om~)], from the
/// world velocities v and accelerations a (gravity subtracted) as inertia_force takes them:
/// [a_o - g; alpha] = Zx (a_b - c), Om = Zx_r w (formulation 2.4-2.5).
using StiffeningLoads = Eigen::Matrix<double, 12, 1>;
void stiffening_load_factors(const AicElement& e, const AicKinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& v,
                             const Eigen::Ref<const Eigen::VectorXd>& a, StiffeningLoads& lambda, AicWorkspace& ws);
/// Elastic force and tangent (as elastic_force) with the stress stiffening (docs/geometric-stiffening.md):
/// the local force is the gradient of the potential 1/2 xi^T (K + sum_c lambda_c G_c) xi + xi_b . b
/// + 1/2 b . s, with b_j = 1/2 xi^T G_j xi (the bending's foreshortening load on interface coordinate
/// j < 6N) and s = Kbb^+ b, i.e. (K + sum_c lambda_c G_c + sum_j (xi_j + s_j) G_j) xi + [b; 0]
/// (se::StiffeningInvariants). The tangent holds the load factors `lambda` fixed (their own variation
/// is left out) and is otherwise exact (symmetric in xi). Needs e.has_stiffening(). Writes the
/// potential to *energy when given.
void elastic_force_stiffened(const AicElement& e, const AicKinematics& kin, TangentModel tangent,
                             const StiffeningLoads& lambda, Eigen::VectorXd& f, Eigen::MatrixXd* Kt, AicWorkspace& ws,
                             double* energy = nullptr, MatrixAxes axes = MatrixAxes::World);

/// Rotate between world components and body-axis components: y = Rhat^T x (to_body) or Rhat x.
Eigen::VectorXd to_body(const AicElement& e, const Eigen::Matrix3d& R_WB, const Eigen::Ref<const Eigen::VectorXd>& x);
Eigen::VectorXd to_world(const AicElement& e, const Eigen::Matrix3d& R_WB, const Eigen::Ref<const Eigen::VectorXd>& x);
/// A_world = Rhat A_body Rhat^T for an n x n matrix.
Eigen::MatrixXd to_world_matrix(const AicElement& e, const Eigen::Matrix3d& R_WB, const Eigen::MatrixXd& A);
/// The same three without allocation: into y, or A rotated in place.
void to_body(const AicElement& e, const Eigen::Matrix3d& R_WB, const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::VectorXd& y);
void to_world(const AicElement& e, const Eigen::Matrix3d& R_WB, const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::VectorXd& y);
void rotate_to_world(const AicElement& e, const Eigen::Matrix3d& R_WB, Eigen::MatrixXd& A);

/// Rigid-body modes Phi_rig(u) (6N x 6) for interface displacements taken from xi.
Eigen::MatrixXd rigid_modes(const AicElement& e, const Eigen::Ref<const Eigen::VectorXd>& xi);

/// Inertia of one body (formulation 2.3 simplified, 2.4 full). Inputs in world components:
/// velocities v (n: [dr_1/dt; omega_1; ...; deta/dt]) and accelerations a (n, gravity already
/// subtracted from the translational entries). Outputs: force f (n, world), and, when requested,
/// the mass matrix Mt, the velocity derivative Ct (gyroscopic/Coriolis, full inertia only) and an
/// approximate configuration derivative Kt (rotation of the inertia force with the frame), all
/// n x n in world components (body axes with MatrixAxes::Body). kinetic = 1/2 v^T M0 v.
/// Kinetic energy 1/2 w^T M_w w of the inertia model at the world velocities v (as inertia_force
/// takes them), without the force and matrices: with the full inertia only the mass pairing of the
/// invariants is read (the output samples' energies, AssemblyOptions::energies_only).
double kinetic_energy(const AicElement& e, const AicKinematics& kin, InertiaModel model,
                      const Eigen::Ref<const Eigen::VectorXd>& v, AicWorkspace& ws);

struct InertiaResult {
  Eigen::VectorXd f;
  Eigen::MatrixXd Mt, Ct, Kt;
  bool has_Ct = false;  ///< Ct was formed by the last call (InertiaMatrices::All)
  double kinetic = 0.0;
};
void inertia_force(const AicElement& e, const AicKinematics& kin, InertiaModel model,
                   const Eigen::Ref<const Eigen::VectorXd>& v, const Eigen::Ref<const Eigen::VectorXd>& a,
                   bool want_matrices, InertiaResult& out);
void inertia_force(const AicElement& e, const AicKinematics& kin, InertiaModel model,
                   const Eigen::Ref<const Eigen::VectorXd>& v, const Eigen::Ref<const Eigen::VectorXd>& a,
                   bool want_matrices, InertiaResult& out, AicWorkspace& ws);
void inertia_force(const AicElement& e, const AicKinematics& kin, InertiaModel model,
                   const Eigen::Ref<const Eigen::VectorXd>& v, const Eigen::Ref<const Eigen::VectorXd>& a,
                   InertiaMatrices matrices, InertiaResult& out, AicWorkspace& ws, MatrixAxes axes = MatrixAxes::World);

/// The full inertia evaluated by sums over the FE nodes (formulation 2.4; needs has_fe_data): the
/// reference the invariant evaluation is tested against. elastic_gyro = false leaves out the
/// gyroscopic moment quadratic in the elastic rotation rates, the one term the invariants drop.
void inertia_force_nodal(const AicElement& e, const AicKinematics& kin, const Eigen::Ref<const Eigen::VectorXd>& v,
                         const Eigen::Ref<const Eigen::VectorXd>& a, bool want_matrices, bool elastic_gyro,
                         InertiaResult& out);

/// Position of the deformed centre of mass from the frame origin, in B: p_BoCm_B + (1/m) sum m_i U_i.
Eigen::Vector3d deformed_com(const AicElement& e, const Eigen::Ref<const Eigen::VectorXd>& xi);

}  // namespace seflex::mbd
