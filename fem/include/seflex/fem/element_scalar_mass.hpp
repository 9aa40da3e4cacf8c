#pragma once
// CMASS1-4: scalar mass m between two g-set dofs (grid components in the grids' displacement
// systems, or scalar points); grounded when the second point is blank (MSC Nastran QRG CMASS1):
//   M = m [1 -1; -1 1] on (dof1, dof2), or m on dof1 alone.
#include <Eigen/Core>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

struct ScalarMassElement {
  double m = 0;                       ///< before WTMASS
  Eigen::Index dof1 = -1, dof2 = -1;  ///< g-set dofs; -1 = grounded end
};

/// Resolve a CMASS1-4; throws InputError for an undefined PMASS or point, a bad component, both
/// ends grounded or both on the same dof.
ScalarMassElement make_scalar_mass_element(const Model& model, const DofMap& dofs, const ScalarMass& s);

}  // namespace seflex::fem
