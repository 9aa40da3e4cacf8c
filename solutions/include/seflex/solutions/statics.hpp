#pragma once
// Linear statics (Nastran SOL 101): K u = p with the SPCs, MPCs, rigid elements and loads the case
// control selects, for one subcase (solve_static) or every subcase (solve_statics).
//
//   K_ff u_f = p_f = T^T (p_g - K_gg u_g0),   u_g = T u_f + u_g0       (fem/constraints.hpp)
//   q_g = K_gg u_g - p_g  on the constrained dofs (SPC, GRID PS, AUTOSPC, SUPORT): forces of
//   single-point constraint; by equilibrium their resultant is minus the applied load's.
//
// p_g is the load of the subcase's LOAD set plus the thermal load of its TEMPERATURE(LOAD) set
// (fem/loads.hpp; GRAV and RFORCE through the assembled mass matrix). A subcase without either is
// solved with zero load (its enforced displacements, SPC D, drive it).
// SUPORT dofs, and those of the SUPORT1 set the subcase selects (case control SUPORT1 = SID), are
// held at zero, as Nastran's SOL 101 does without inertia relief (PARAM INREL).
// ASET/OMIT need nothing: static condensation is exact in statics. Subcases that share their SPC,
// MPC and SUPORT1 sets share one factorisation of K_ff. K_ff is factorised by the default sparse backend (CHOLMOD
// supernodal Cholesky).
//
// Before anything is assembled, check_card_usage(Statics) must find nothing Refused (a selected
// load set with a card seflex does not apply, an element it does not model, ...): InputError.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/solutions/case_selection.hpp"
#include "seflex/linalg/sparse_factorization.hpp"

namespace seflex::solutions {

struct StaticOptions {
  std::optional<int> subcase;  ///< solve_static: default the first subcase; solve_statics: default all
  linalg::FactorizationBackend factorization = linalg::kDefaultFactorization;
  bool ignore_unknown_cards = false;  ///< solve without the cards seflex does not know (check_card_usage)
};

struct StaticSolution {
  CaseSelection selection;
  fem::DofMap dofs;
  Eigen::VectorXd u_g;  ///< displacements (g-set, each grid's CD system)
  Eigen::VectorXd p_g;  ///< applied loads (g-set)
  Eigen::VectorXd q_g;  ///< forces of single-point constraint (zero on unconstrained dofs)
  Eigen::Index n_free = 0;
  double backward_error = 0;  ///< ||K_ff u_f - p_f|| / (||K_ff||_1 ||u_f|| + ||p_f||): ~1e-16 for a stable solve
};

/// Solve the statics of one subcase of a finalized model. Throws InputError when a card the
/// subcase needs is not supported or not defined, or the deck has cards seflex does not know and
/// ignore_unknown_cards is not set (check_card_usage), when no dof is free (require_free_dofs: no
/// element, or every dof constrained), or when the constrained
/// stiffness is singular (the message names a grid and component of the unconstrained rigid-body
/// motion or mechanism).
StaticSolution solve_static(const fem::Model& model, const StaticOptions& options = {});

/// Solve every subcase (or options.subcase only), in the order of the deck; as solve_static.
std::vector<StaticSolution> solve_statics(const fem::Model& model, const StaticOptions& options = {});

}  // namespace seflex::solutions
