#pragma once
// SPCD: enforced displacements selected as a load set (MSC Nastran QRG SPCD): the subcase's LOAD =
// SID selects the SPCD cards of set SID (or, through a LOAD combination, of its sets, scaled by
// S * Si). Each SPCD component must be constrained by the subcase's SPC set; its value replaces
// the SPC's D. Statics then solves K_ff u_f = T^T (p_g - K_gg u_g0) with these values in u_g0.
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

/// The g-set dofs and enforced values of the SPCD cards of load set `sid` (LOAD combinations
/// expanded and scaled); empty if none. Throws InputError for an undefined grid or a component
/// that does not exist.
std::vector<std::pair<Eigen::Index, double>> enforced_motion_dofs(const Model& model, const DofMap& dofs, int sid);

/// Whether any SPCD card has SID `sid` (a load set made only of SPCD cards exists).
bool has_enforced_motion_set(const Model& model, int sid);

}  // namespace seflex::fem
