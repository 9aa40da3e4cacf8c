#pragma once
// An FE model reduced to the absolute-interface-coordinate superelement (se::Superelement,
// formulation.md sections 1.2-1.3 and 2.4-2.5): Craig-Bampton on all six dofs of N interface
// grids plus m fixed-interface modes, with everything the multibody side needs.
//
//   q = [u_1 theta_1 ... u_N theta_N eta_1 ... eta_m]   (n = 6N + m), body axes = basic axes,
//   origin at the frame node f.
//
// Steps (the model is read, never changed):
//  1. K, M of the g-set (fem::assemble; DMIG K2GG/M2GG included), constraints of the case control
//     (SPC and MPC sets of the first subcase) and rigid elements (RBE2, RBAR, RBE3) eliminated
//     exactly (fem::apply_constraints, AUTOSPC as PARAM AUTOSPC says, default on). Cards the
//     reduction needs and seflex does not model refuse the deck (check_card_usage, CraigBampton).
//  2. Every interface grid must keep its six dofs free (not SPC'd, not dependent, not removed by
//     AUTOSPC); the boundary set is their 6N f-dofs. The reference grid of an RBE3 is dependent (a
//     weighted average of its independent grids): a unit motion of it alone does not define a
//     constraint mode, so it is refused as an interface node unless UM makes it independent; the
//     dependent grids of an RBE2/RBAR are refused too (their independent grid is the interface).
//  3. Craig-Bampton (craig_bampton.hpp). Constraint-mode columns are then expressed in basic
//     components, so q is in body axes even for grids with a CD system (interface triads R_BN = I).
//  4. Recovery to every grid's 6 dofs in basic (RBE2 dependents and SPC'd dofs through T):
//     recovery = A_g T [Psi Phi], A_g the grids' CD axes; Phi_f = the frame node's 6 rows.
//  5. M_fe = A_g M_gg A_g^T on the grid dofs (WTMASS applied: recovery^T M_fe recovery = M).
//  6. Mass properties (mass, CG from f, inertia about the CG, basic axes) from D^T M_gg D with D
//     the rigid-body modes about f: the mass the analysis uses (WTMASS applied, DMIG included).
//  7. Truncation report with the rigid motions about f (craig_bampton.hpp, truncation_report).
// Frame node: options.frame_node, or by default the grid with six free dofs, not an interface
// node, nearest the centre of mass (ties: the lower id). The yoke uses 2 and the panel 112.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/reduction/craig_bampton.hpp"
#include "seflex/superelement/stress_modes.hpp"
#include "seflex/superelement/superelement.hpp"

namespace seflex::reduction {

/// Cards that name an interface (boundary) set.
enum class InterfaceCards : unsigned char { Aset, Bset, Suport };

/// Interface grids named by ASET/ASET1, BSET/BSET1 or SUPORT cards, in order of first appearance.
/// Each entry must name all six components of a GRID (a superelement interface node carries six
/// dofs); throws InputError naming the card otherwise, or when there is no such card.
std::vector<int> interface_nodes_from_cards(const fem::Model& model, InterfaceCards cards);

/// Interface grids of a named node set (Model::node_sets, e.g. a gmsh physical group). Throws
/// InputError listing the available names if there is none of that name.
std::vector<int> interface_nodes_from_set(const fem::Model& model, const std::string& name);

struct SuperelementOptions {
  std::vector<int> interface_ids;  ///< grid ids, in the order of q
  unsigned interface_cards = 0;    ///< InterfaceFrom bits (card_usage.hpp): the cards interface_ids came from
  std::optional<int> frame_node;   ///< default: see above
  CraigBamptonOptions modes;       ///< fixed-interface modes (count or frequency limit)
  std::string name;                ///< body name
  bool full_mesh = true;           ///< keep recovery, M_fe and cells (animation, recovery); the invariants are always computed
  /// Compute the geometric-stiffness invariants (stiffening.hpp; with either backend: the partitioned
  /// `basis` below solves the inertia load cases on its factor, CraigBamptonOptions::interior_loads).
  bool stiffening = true;
  bool ignore_unknown_cards = false;  ///< reduce without the cards seflex does not know (check_card_usage)
  /// Stress modes (se::StressModes, format 1.4; reduce_to_superelement's `stress`): the element results
  /// (fem/element_results.hpp) of these element ids per basis vector; an empty list: every element with
  /// results. Unset: none.
  std::optional<std::vector<int>> stress_elements;
  /// The distributed backend's partitioned assembly (parallel/, `reduce --backend slepc`): when both
  /// are set, step 1 takes the g-set matrices from `assemble` (M whole; K only as far as
  /// apply_constraints needs it: each grid's diagonal block, enough when no dof is dependent) and
  /// step 3 the basis from `basis` (on the partitioned K and M `assemble` made), instead of
  /// fem::assemble and craig_bampton. Both are collective: every rank runs reduce_to_superelement.
  std::function<fem::GlobalMatrices(const fem::ConstraintOptions&)> assemble;
  std::function<CraigBamptonBasis(const std::vector<Eigen::Index>& boundary, const CraigBamptonOptions&)> basis;
  /// Distributed reduce: the 12 + 6N projections of the geometric-stiffness invariants shared out
  /// (case k on rank k mod ranks, stiffening.hpp), then `sum_stiffening` adds every rank's matrices
  /// (each `count` doubles) up on every rank, in place. Collective: every rank calls it once, with
  /// failed_here = its share threw; then it sums nothing and throws on the ranks that did not fail
  /// (the failing rank rethrows its own error). Unset: every case on this process.
  int stiffening_rank = 0, stiffening_ranks = 1;
  std::function<void(const std::vector<double*>& matrices, std::size_t count, bool failed_here)> sum_stiffening;
};

/// What was done, for the summary of `seflex reduce` and the benchmark.
struct SuperelementInfo {
  CraigBamptonStats stats;
  bool frame_chosen = false;        ///< the frame node was chosen by the default rule
  int spc_set = 0;                  ///< SPC set applied (0 = none)
  int mpc_set = 0;                  ///< MPC set applied (0 = none)
  Eigen::Index autospc_dofs = 0;    ///< dofs removed by AUTOSPC
  Eigen::Index dependent_dofs = 0;  ///< dependent dofs (rigid elements, RBE3, MPC) eliminated
  double seconds_stiffening = 0;    ///< the geometric-stiffness invariants (0 when not computed)
  /// Stress modes: the selected elements' cards without element results (and unknown ids), with counts.
  std::vector<std::pair<std::string, int>> stress_missing;
};

/// Reduce a finalized model. Fills every field of se::Superelement, of the provenance the version and
/// the warnings about the deck's cards (source_warnings), but not what only a reader of the files
/// knows: source_file, source_hash and created (io::record_source, seflex/io/provenance.hpp, fills
/// them as `seflex reduce` does). Throws InputError for a bad interface or
/// frame node (naming the node and why: missing, a scalar point, SPC'd, an RBE2 dependent,
/// without stiffness in a component, listed twice) and for an interior the interface does not hold
/// (a part connected to no interface node, or a mechanism: names a grid and component).
/// With options.stress_elements and `stress`, the stress modes (se::StressModes) of those elements
/// are computed into *stress (empty when none of them has element results).
se::Superelement reduce_to_superelement(const fem::Model& model, const SuperelementOptions& options,
                                        SuperelementInfo* info = nullptr, se::StressModes* stress = nullptr);

/// The rigid-body modes of the interface (6N x 6) for unit translations along and rotations about
/// the basic axes through the frame origin: rows of node j = [I, -skew(x_j); 0, I] (formulation.md
/// section 1.4, Phi_rig at u = 0).
Eigen::MatrixXd interface_rigid_modes(const se::Superelement& body);

/// Lowest `count` eigenvalues of the free-free reduced model (K, M of the superelement), ascending.
Eigen::VectorXd reduced_eigenvalues(const se::Superelement& body, int count);

/// Lowest `count` eigenvalues of the full FE model with the constraints `reduce_to_superelement`
/// applies (case-control SPC and MPC, rigid elements, AUTOSPC), for comparison with the reduced model.
Eigen::VectorXd full_model_eigenvalues(const fem::Model& model, int count,
                                       linalg::EigenBackend backend = linalg::EigenBackend::Spectra);

}  // namespace seflex::reduction
