#pragma once
// A body's state at one instant of a run as a Nastran static subcase of its own deck: its interface
// displacements (the elastic coordinates q_b of the superelement, body axes = the deck's basic axes, turned
// to each interface grid's displacement axes by the nodal triad) as SPC1 + SPCD bulk data. Added to the
// body's deck with a subcase `SPC = SID` and `LOAD = SID`, any Nastran-class solver (`seflex static`)
// recovers the full-field displacements and element results of the constraint-mode part of the body's
// deformation (docs/stresses.md: what it leaves out, the fixed-interface modes' share).
#include <Eigen/Core>
#include <filesystem>
#include <string>

#include "seflex/superelement/superelement.hpp"

namespace seflex::io {

/// Write the bulk-data fragment (SPC1 and large-field SPCD cards, set `sid`) for the elastic
/// coordinates xi (size body.size(); only the 6N interface entries are used) to `path`, with a comment
/// naming `what` (body and instant) and the case control to add. Throws InputError naming the file
/// if it cannot be written.
void write_interface_subcase(const std::filesystem::path& path, const se::Superelement& body,
                             const Eigen::Ref<const Eigen::VectorXd>& xi, int sid, const std::string& what);

}  // namespace seflex::io
