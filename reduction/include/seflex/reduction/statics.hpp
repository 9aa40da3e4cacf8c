#pragma once
// Linear statics (Nastran SOL 101): K u = p with the SPCs, RBE2s and loads the case control selects.
//
//   K_ff u_f = p_f = T^T (p_g - K_gg u_g0),   u_g = T u_f + u_g0       (fem/constraints.hpp)
//   q_g = K_gg u_g - p_g  on the constrained dofs (SPC, GRID PS, AUTOSPC): forces of single-point
//   constraint; by equilibrium their resultant is minus the applied load's.
//
// K_ff is factorised by the default sparse backend (CHOLMOD supernodal Cholesky).
#include <Eigen/Core>
#include <optional>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/reduction/case_selection.hpp"
#include "seflex/reduction/sparse_factorization.hpp"

namespace seflex::reduction {

struct StaticOptions {
  std::optional<int> subcase;  ///< default: the first subcase, else the global selections
  FactorizationBackend factorization = kDefaultFactorization;
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

/// Solve the statics of a finalized model. Throws InputError when the case control selects no
/// LOAD, names undefined sets, or when the constrained stiffness is singular (the message names a
/// grid and component of the unconstrained rigid-body motion or mechanism).
StaticSolution solve_static(const fem::Model& model, const StaticOptions& options = {});

}  // namespace seflex::reduction
