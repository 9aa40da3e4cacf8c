#pragma once
// A body's state at one instant of a run as a Nastran static subcase of its own deck: its interface
// displacements (the elastic coordinates q_b of the superelement, body axes = the deck's basic axes, turned
// to each interface grid's displacement axes by the nodal triad) as SPC1 + SPCD bulk data. Added to the
// body's deck with a subcase `SPC = SID` and `LOAD = SID`, any Nastran-class solver (`seflex static`)
// recovers the full-field displacements and element results of the constraint-mode part of the body's
// deformation (docs/stresses.md: what it leaves out, the fixed-interface modes' share). With the inertia
// loads of the instant (-M a of every FE node, body axes, as FORCE/MOMENT cards in the same set) the
// solver recovers the run's full deformation too, plus the static response of the truncated modes.
#include <Eigen/Core>
#include <filesystem>
#include <string>

#include "seflex/superelement/superelement.hpp"

namespace seflex::io {

/// Write the bulk-data fragment (SPC1 and large-field SPCD cards, set `sid`) for the elastic
/// coordinates xi (size body.size(); only the 6N interface entries are used) to `path`, with a comment
/// naming `what` (body and instant) and the case control to add. Throws InputError naming the file
/// if it cannot be written. `inertia_loads` (optional, 6 n_fe in body axes = the deck's basic axes,
/// node-major in body.fe_node_ids' order): the nodal loads written as FORCE/MOMENT cards (CID 0) at every
/// grid that is not an interface grid (there the SPCD holds).
void write_interface_subcase(const std::filesystem::path& path, const se::Superelement& body,
                             const Eigen::Ref<const Eigen::VectorXd>& xi, int sid, const std::string& what,
                             const Eigen::VectorXd* inertia_loads = nullptr);

}  // namespace seflex::io
