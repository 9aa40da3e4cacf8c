#pragma once
// Turning a breakdown of the f-set factorisation into a user-facing error naming the grid.
#include <string>

#include "seflex/fem/constraints.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/linalg/sparse_factorization.hpp"
#include "seflex/solutions/card_usage.hpp"

namespace seflex::solutions {

/// InputError "<deck>: <what>: ... at grid G component C ... <advice>" for a FactorizationError whose
/// column is an f-set index of `c`.
[[noreturn]] void throw_singular_dof(const fem::Model& model, const fem::GlobalMatrices& g,
                                     const fem::ConstrainedSystem& c, const linalg::FactorizationError& e,
                                     const std::string& what, const std::string& advice);

/// InputError "<deck>: <solution> has nothing to solve: no free dof (<why>)" when the constraints
/// leave no free dof: the model has no GRID or SPOINT; it has no element with stiffness (every dof
/// removed by AUTOSPC; the cards seflex does not know that --ignore-unknown left out are named); or,
/// but in statics, every dof is constrained (how many by SPC, AUTOSPC, MPC and rigid elements,
/// SUPORT). Statics of a structure whose every dof the SPCs hold runs: its SPC forces are the answer
/// (fixed-end forces, a clamped plate's thermal force), as in Nastran.
void require_free_dofs(const fem::Model& model, const fem::GlobalMatrices& g, const fem::ConstrainedSystem& c,
                       Solution solution);

}  // namespace seflex::solutions
