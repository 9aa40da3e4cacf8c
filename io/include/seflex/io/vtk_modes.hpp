#pragma once
// Mode shapes for ParaView: one VTK XML unstructured grid (.vtu) of the FE mesh with every mode as
// point data.
//
// Points: every GRID at its basic position, in Model::grids order (point data "grid_id").
// Cells: CBAR/CBEAM, CROD/CONROD, CELAS1/2 between two grids, RBE2 legs (independent grid to
// each dependent grid), RBAR (GA-GB) and RBE3 legs (reference grid to each independent grid) as
// lines; CTRIA3 as triangles; CQUAD4 as quads; CONM2 as vertices. Cell data "element_id" (the card's
// id) and "element_type" (1 bar/beam, 2 rod, 3 spring, 4 RBE2, 5 CTRIA3, 6 CQUAD4, 7 CONM2, 8 RBAR,
// 9 RBE3).
// Point data per mode k (1-based, zero-padded to the width of the mode count, e.g. mode_07):
// "mode_07_displacement" (T1 T2 T3 along the basic axes) and "mode_07_rotation" (R1 R2 R3, basic
// axes, radians per unit modal amplitude), normalised as the solution was (NORM). Field data
// "eigenvalue" and "frequency_hz" (one value per mode).
// In ParaView: Warp By Vector with a mode's displacement (scale to taste), or Animation View with
// the scale factor varying as sin(2 pi t), animates the mode.
#include <filesystem>

#include "seflex/fem/model.hpp"
#include "seflex/solutions/normal_modes.hpp"

namespace seflex::io {

/// Write the modes of `modes` (computed from `model`) to `path`. Throws InputError if the file
/// exists and !overwrite, or cannot be written.
void write_mode_shapes_vtu(const std::filesystem::path& path, const fem::Model& model,
                           const solutions::NormalModes& modes, bool overwrite = false);

}  // namespace seflex::io
