#pragma once
// Single-point constraints, multipoint constraints (MPC/MPCADD selected by case control) and the
// rigid and interpolation elements RBE2, RBAR, RBE3, eliminated exactly (no penalty):
//
//   u_g = T u_f + u_g0,      K_ff = T^T K_gg T,   M_ff = T^T M_gg T,
//   p_f = T^T (p_g - K_gg u_g0)   (reduce_load),   u_g = T u_f + u_g0   (expand).
//
// Dof sets (Nastran names): every g-set dof is exactly one of
// - m (Dependent): a dependent dof of an RBE2, RBAR, RBE3 or MPC equation, u_m = G_mn u_n (the
//   grids' CD components). RBE2/RBAR: rigid-body relations, u_m = u_n + theta_n x (x_m - x_n),
//   theta_m = theta_n (RBAR: the six independent components CNA/CNB fix the rigid motion); RBE3: the
//   weighted least-squares average of the independent grids' motions (UM redefines the dependent
//   set); MPC: the first dof of each equation. Chains (a dependent dof's terms being dependent
//   themselves) are resolved; a closed loop of dependencies, a dof made dependent by two cards, and a
//   dependent dof that is also constrained (GRID PS, SPC, a held dof) are InputErrors naming both
//   cards (Nastran's rule that the m-set and s-set do not overlap);
// - s (Spc): GRID PS (with GRDSET applied by finalize), SPC/SPC1 of the selected set (SPCADD
//   expanded); an SPC's D value is an enforced displacement (statics), SPC1 enforces zero;
// - Fixed: the caller's extra dofs (e.g. SUPORT/boundary dofs held for fixed-interface modes),
//   held at zero;
// - AutoSpc: with `autospc`, grid components left without stiffness (Nastran PARAM AUTOSPC): for
//   each grid, the 3 x 3 block of K_ff (= T^T K_gg T) of its free translations (and of its free
//   rotations) is decomposed; each eigenvector whose eigenvalue is <= 1e-8 of the block's largest
//   diagonal is a singular direction, and the free component with the largest share in it (not
//   already taken) is removed, as Nastran's AUTOSPC does in the grid's CD system; scalar points
//   when their diagonal is zero. Dofs in `no_autospc` are neither removed nor part of the blocks;
//   with AUTOSPC off, the dofs an external superelement (Model::external_parts) lists with a zero
//   row of KAA are still removed where nothing else gives them stiffness (as MSC did in its se_test_n11
//   run; no documented rule found: constraints.cpp);
// - f (Free): the rest, numbered in increasing g order (f_to_g).
#include <Eigen/SparseCore>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "seflex/fem/assembly.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

enum class DofStatus : unsigned char { Free, Dependent, Spc, Fixed, AutoSpc };

struct ConstraintOptions {
  std::optional<int> spc_set;              ///< SPC set id from case control (SPCADD expanded); none = GRID PS only
  std::optional<int> mpc_set;              ///< MPC set id from case control (MPCADD expanded); none = rigid elements only
  std::vector<Eigen::Index> fixed_dofs;    ///< extra g-set dofs held at zero
  bool autospc = true;                     ///< remove dofs without stiffness (Nastran default for SOL 101/103)
  /// g-set dofs AUTOSPC leaves alone and treats as held when it looks for singular directions: a
  /// superelement interface, SUPORT's r-set (Nastran's PARAM AUTOSPCR defaults to NO).
  std::vector<Eigen::Index> no_autospc;
};

/// A card that makes dofs dependent (RBE2, RBAR, RBE3 by element id, MPC by set id).
struct ConstraintCard {
  const char* card = "";
  int id = 0;
  CardRef ref;
};

struct ConstrainedSystem {
  Eigen::SparseMatrix<double> K_ff, M_ff;  ///< f x f, both triangles stored
  Eigen::SparseMatrix<double> T;           ///< g x f
  Eigen::VectorXd u_g0;                    ///< enforced displacements on the g-set (SPC D, spread to RBE2 dependents)
  std::vector<Eigen::Index> f_to_g;        ///< f index -> its g dof
  std::vector<Eigen::Index> g_to_f;        ///< g dof -> f index, -1 if not free
  std::vector<DofStatus> status;           ///< per g dof
  std::vector<ConstraintCard> constraint_cards;  ///< the cards that make dofs dependent
  std::vector<std::int32_t> dependent_card;      ///< per g dof: index into constraint_cards, -1; empty if no m-set
  Eigen::Index n_free() const { return static_cast<Eigen::Index>(f_to_g.size()); }
};

/// Apply constraints to assembled matrices. Throws InputError for an undefined SPC or MPC set,
/// grid or component, an RBAR/RBE3 that does not determine its dependents, and conflicting
/// constraints (a dof dependent in two cards, or dependent and constrained; both cards named).
ConstrainedSystem apply_constraints(const Model& model, const GlobalMatrices& g, const ConstraintOptions& options);

/// Convenience form: SPC set and extra fixed dofs, AUTOSPC on.
ConstrainedSystem apply_constraints(const Model& model, const GlobalMatrices& g, std::optional<int> spc_set,
                                    const std::vector<Eigen::Index>& fixed_dofs = {});

/// p_f = T^T (p_g - K_gg u_g0): the f-set load including the effect of enforced displacements.
Eigen::VectorXd reduce_load(const ConstrainedSystem& c, const GlobalMatrices& g, const Eigen::VectorXd& p_g);

/// u_g = T u_f + u_g0.
Eigen::VectorXd expand(const ConstrainedSystem& c, const Eigen::VectorXd& u_f);

/// The grid components of an SPC set as g-set dofs with their enforced values (SPCADD expanded,
/// GRID PS not included). Grids of an SPC1 "THRU" range that do not exist are skipped (QRG SPC1:
/// they need not exist); any other undefined point is an InputError, as is an undefined set.
std::vector<std::pair<Eigen::Index, double>> spc_set_dofs(const Model& model, const DofMap& dofs, int spc_set);

/// The set ids a set `sid` stands for through SPCADD/MPCADD `combinations` (itself included;
/// nested combinations expanded, cycles ignored). `combined` (optional) tells whether a combination
/// has this SID.
std::set<int> expand_sets(int sid, const std::vector<SetCombination>& combinations, bool* combined = nullptr);

/// "RBE3 5 (deck.bdf:12)" / "MPC set 2 (deck.bdf:30)".
std::string describe(const Model& model, const ConstraintCard& card);

/// PARAM AUTOSPC: false only for NO (Nastran's default is YES in SOL 101 and 103).
bool autospc_enabled(const Model& model);

}  // namespace seflex::fem
