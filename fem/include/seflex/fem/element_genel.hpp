#pragma once
// GENEL: a general element given by its stiffness K (or flexibility Z, K = Z^-1) on the dofs UI and
// the rigid-body matrix S to the dofs UD (MSC QRG GENEL; model_elements.hpp: Genel):
//
//   K_e = [ K  -K S ; -S^T K  S^T K S ]   on (u_i, u_d), each dof in its grid's CD system.
//
// With UD and no S, S is the rigid-body map u_i = S u_d of the six UD dofs: a rigid motion q about
// the first UD grid gives u_d = H_d q and u_i = H_i q (rows of each grid's rigid map), S = H_i H_d^-1.
// K_e then has the element's rigid-body motions as null vectors. No mass.
#include <Eigen/Core>
#include <vector>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

struct GenelElement {
  std::vector<Eigen::Index> dofs;  ///< g-set dofs: UI then UD
  Eigen::MatrixXd K;               ///< on `dofs`
};

/// Resolve a GENEL of a finalized model; throws InputError naming the card for undefined points or
/// components, a singular Z, or six UD dofs that do not fix the rigid-body motion (S blank), or UD
/// scalar points with S blank.
GenelElement make_genel_element(const Model& model, const DofMap& dofs, const Genel& g);

}  // namespace seflex::fem
