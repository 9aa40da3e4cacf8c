#pragma once
// CELAS1 / CELAS2 (grids or scalar points), CELAS3 / CELAS4 (scalar points): scalar spring k between two g-set dofs (grid components in the grids'
// displacement systems, or scalar points); grounded when the second point is blank:
//   K = k [1 -1; -1 1] on (dof1, dof2), or k on dof1 alone.
#include <Eigen/Core>
#include <string>
#include <utility>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

struct SpringElement {
  double k = 0;
  Eigen::Index dof1 = -1, dof2 = -1;  ///< g-set dofs; -1 = grounded end
};

/// Resolve a CELAS1/CELAS3 (PELAS) or CELAS2/CELAS4; throws InputError for undefined points, bad components,
/// a spring with both ends grounded, or both ends on the same dof.
SpringElement make_spring_element(const Model& model, const DofMap& dofs, const Spring& s);

/// The two dofs of a scalar element (CELAS1-4, CMASS1-4) from its ends (G, C) or scalar points;
/// a blank end is grounded (-1, second). Throws InputError naming the card and field for an
/// unknown point or component, two blank ends, or both ends on one dof.
std::pair<Eigen::Index, Eigen::Index> scalar_element_dofs(const Model& model, const DofMap& dofs, const CardRef& ref,
                                                          const std::string& card, int id, bool scalar_points, int g1,
                                                          int c1, int g2, int c2);

}  // namespace seflex::fem
