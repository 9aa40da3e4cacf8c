#pragma once
// Turning a breakdown of the f-set factorisation into a user-facing error naming the grid.
#include <string>

#include "seflex/fem/constraints.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/linalg/sparse_factorization.hpp"

namespace seflex::solutions {

/// InputError "<deck>: <what>: ... at grid G component C ... <advice>" for a FactorizationError whose
/// column is an f-set index of `c`.
[[noreturn]] void throw_singular_dof(const fem::Model& model, const fem::GlobalMatrices& g,
                                     const fem::ConstrainedSystem& c, const linalg::FactorizationError& e,
                                     const std::string& what, const std::string& advice);

}  // namespace seflex::solutions
