#pragma once
// Single-point constraints and RBE2 rigid elements, eliminated exactly (no penalty):
//
//   u_g = T u_f + u_g0,      K_ff = T^T K_gg T,   M_ff = T^T M_gg T,
//   p_f = T^T (p_g - K_gg u_g0)   (reduce_load),   u_g = T u_f + u_g0   (expand).
//
// Dof sets (Nastran names): every g-set dof is exactly one of
// - m (Dependent): a dependent component of an RBE2 grid; its row of T expresses it through the
//   independent grid's six dofs (in the grids' CD systems): u_m = u_n + theta_n x (x_m - x_n),
//   theta_m = theta_n. Chains of RBE2s are resolved; cycles and dofs made dependent twice are errors;
// - s (Spc): GRID PS (with GRDSET applied by finalize), SPC/SPC1 of the selected set (SPCADD
//   expanded); an SPC's D value is an enforced displacement (statics), SPC1 enforces zero;
// - Fixed: the caller's extra dofs (e.g. SUPORT/boundary dofs held for fixed-interface modes),
//   held at zero;
// - AutoSpc: with `autospc`, grid components left without stiffness (Nastran PARAM AUTOSPC):
//   an f-set dof whose K_ff diagonal is <= 1e-8 of the largest diagonal among the same grid's free
//   translations (or rotations), or exactly zero; scalar points when their diagonal is zero;
// - f (Free): the rest, numbered in increasing g order (f_to_g).
// A dof both dependent and constrained is an InputError naming the cards.
#include <Eigen/SparseCore>
#include <optional>
#include <vector>

#include "seflex/fem/assembly.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

enum class DofStatus : unsigned char { Free, Dependent, Spc, Fixed, AutoSpc };

struct ConstraintOptions {
  std::optional<int> spc_set;              ///< SPC set id from case control (SPCADD expanded); none = GRID PS only
  std::vector<Eigen::Index> fixed_dofs;    ///< extra g-set dofs held at zero
  bool autospc = true;                     ///< remove dofs without stiffness (Nastran default for SOL 101/103)
};

struct ConstrainedSystem {
  Eigen::SparseMatrix<double> K_ff, M_ff;  ///< f x f, both triangles stored
  Eigen::SparseMatrix<double> T;           ///< g x f
  Eigen::VectorXd u_g0;                    ///< enforced displacements on the g-set (SPC D, spread to RBE2 dependents)
  std::vector<Eigen::Index> f_to_g;        ///< f index -> its g dof
  std::vector<Eigen::Index> g_to_f;        ///< g dof -> f index, -1 if not free
  std::vector<DofStatus> status;           ///< per g dof
  Eigen::Index n_free() const { return static_cast<Eigen::Index>(f_to_g.size()); }
};

/// Apply constraints to assembled matrices. Throws InputError for an undefined SPC set, grid or
/// component, and for conflicting constraints (a dof in two RBE2s, or dependent and constrained).
ConstrainedSystem apply_constraints(const Model& model, const GlobalMatrices& g, const ConstraintOptions& options);

/// Convenience form: SPC set and extra fixed dofs, AUTOSPC on.
ConstrainedSystem apply_constraints(const Model& model, const GlobalMatrices& g, std::optional<int> spc_set,
                                    const std::vector<Eigen::Index>& fixed_dofs = {});

/// p_f = T^T (p_g - K_gg u_g0): the f-set load including the effect of enforced displacements.
Eigen::VectorXd reduce_load(const ConstrainedSystem& c, const GlobalMatrices& g, const Eigen::VectorXd& p_g);

/// u_g = T u_f + u_g0.
Eigen::VectorXd expand(const ConstrainedSystem& c, const Eigen::VectorXd& u_f);

/// The grid components of an SPC set as g-set dofs with their enforced values (SPCADD expanded,
/// GRID PS not included). Throws InputError if the set is not defined.
std::vector<std::pair<Eigen::Index, double>> spc_set_dofs(const Model& model, const DofMap& dofs, int spc_set);

}  // namespace seflex::fem
