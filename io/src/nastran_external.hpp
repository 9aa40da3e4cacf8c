#pragma once
// The matrices of external superelements (SEBULK TYPE = EXTOP4) read from their OP4 files while a deck
// is read (fem/parts.hpp assembles them):
// - the SEBULK's UNITNO names an ASSIGN INPUTT4 = 'file', UNIT = n of the executive control; a relative
//   file name is taken from the main deck's folder. Where no file has that name, a file whose path
//   differs only in the case of letters is read if it is the only one (a warning says so: Nastran on a
//   case-insensitive file system, where such decks are made, reads it too), else it is an error;
// - KAA (required) and MAA (zero, with a warning, if absent) on the part's a-set: the points of its
//   EXTRN cards (in the part's bulk data) sorted by id (Nastran's internal order without resequencing),
//   each grid's components in ascending order, a scalar point one dof; KAA and MAA must be square of
//   that size and symmetric to 1e-6 of their largest term (the mean of the two triangles is used);
// - other matrices of the file (damping BXX, K4XX, loads PA, data recovery MUG1, ...) are not used:
//   a warning names those that are not all zero.
// Errors (InputError) name the SEBULK, the ASSIGN or the OP4 file and matrix, and what was expected.
#include <filesystem>
#include <string>
#include <vector>

#include "seflex/fem/parts.hpp"
#include "seflex/io/nastran_case_control.hpp"

namespace seflex::io::nastran {

/// Fill parts[k].model.external_parts for every SEBULK EXTOP4 of `residual`; warnings go to
/// residual.read_warnings.
void read_external_matrices(fem::Model& residual, std::vector<fem::Part>& parts, const std::vector<AssignedUnit>& units,
                            const std::filesystem::path& main_dir);

}  // namespace seflex::io::nastran
