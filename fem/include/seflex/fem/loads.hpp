#pragma once
// Static load vectors on the g-set.
//
// FORCE  SID G CID F N1 N2 N3:  force  F (N1, N2, N3) in system CID (axes at the grid) on G's T1-T3;
// MOMENT SID G CID M N1 N2 N3:  moment M (N1, N2, N3) on G's R1-R3;
// both rotated to the grid's displacement (CD) system.
// LOAD   SID S S1 L1 S2 L2 ...:  S * sum_i S_i * (FORCE/MOMENT set L_i).
#include <Eigen/Core>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

/// Load vector (size dofs.size()) of load set `sid`: a LOAD combination if one has this SID,
/// otherwise the FORCE/MOMENT cards with this SID. Throws InputError if nothing has this SID, if a
/// LOAD references an undefined set, or a card references an undefined grid or system.
Eigen::VectorXd load_vector(const Model& model, const DofMap& dofs, int sid);

}  // namespace seflex::fem
