#pragma once
// Part superelements (BEGIN SUPER = n) assembled into one model.
//
// A Nastran deck may split its bulk data into the residual structure (part 0, the bulk data after
// BEGIN BULK) and parts, each with its own id spaces (parts reuse grid, element, property and material
// ids). Nastran reduces each part statically to its boundary and solves the residual; seflex merges
// the parts into one model and solves it in full, which is exact where Nastran's static reduction of a
// part is exact (statics) and more accurate where it is not (the modes of a part without generalized
// coordinates). What assemble_parts does, in order (MSC Nastran QRG: BEGIN SUPER, SELOC, SEBULK,
// SECONCT; Superelements User's Guide, "Part superelements"):
// - SELOC: the part is moved rigidly so that its points PA1-PA3 (GRID or POINT of the part) fall on
//   PB1-PB3 (GRID or POINT of the residual): the part's basic system becomes a rectangular system of
//   the assembled model (origin and axes moved), which every CP, CD and CID 0 of the part then names;
// - boundary: grids of different parts (the residual included) at one location (within the larger
//   SEBULK TOL of the two, default 1.0E-5) are one grid, unless either part is SEBULK METHOD = MANUAL;
//   SECONCT pairs are connected always (LOC = YES: checked to coincide within its TOL). A boundary grid
//   keeps the residual's id and displacement system (or those of the part with the lowest id);
// - ids: where two parts use one id (grids that are not one boundary grid, elements, properties,
//   materials, coordinate systems), every part's ids of that kind are renumbered: id + SEID * 10^k,
//   10^k the first power of ten above every id of the kind (so part 3's CQUAD4 12 becomes 3012 when the
//   largest element id is below 1000); load, SPC and method set ids are shared (case control selects
//   them in every part, as SUPER = ALL does);
// - what a part's static reduction alone uses (its ASET/OMIT/BSET, its EIGRL) is dropped, with a
//   warning; a part's PARAM holds if the residual sets the same value, else it is listed (the
//   residual's value or the default used); cards of a part seflex does not assemble (GRAV, LOAD, SPOINT, ...) are listed as
//   unsupported ("part superelement: GRAV (not assembled)": every solution refuses them), as are parts
//   of SEBULK types COLLCTR, EXTERNAL, EXTOP2 and FRFOP2, which are not assembled;
// - SEBULK MIRROR / REPEAT (with SEMPLN): the part is made first, as a part of its own, from its
//   primary's structure (mirrored through the plane, shells' and solids' connectivity reversed, vectors
//   reflected; or copied) and its own section's loads and constraints (docs/nastran-support.md);
// - SEBULK EXTOP4: the part's KAA and MAA (Part::model.external_parts, read by io from the OP4 file) on
//   its EXTRN points go to Model::external_parts at the assembled dofs (its scalar points joined by
//   SECONCT pairs, its boundary grids' rows turned into the joined grids' axes where they differ); a
//   coordinate system of the part defined as the residual's of the same id is that one.
// Errors (InputError, naming file:line, the card and the part): a SELOC, SEBULK or SECONCT naming a
// part without a BEGIN SUPER section, SELOC points collinear or undefined, a SECONCT grid missing or
// not coincident, two grids of one part meeting at one boundary point, a reference from a part's card
// to a grid, property, material or system the part does not define, an SPC or PS on a boundary grid
// whose displacement directions differ between the parts it joins.
#include <vector>

#include "seflex/fem/model.hpp"

namespace seflex::fem {

/// One BEGIN SUPER = n section as read: its cards in a Model of their own (not finalized; its
/// CardRefs index the residual's `files`).
struct Part {
  int seid = 0;
  CardRef begin;  ///< the BEGIN SUPER line
  Model model;
};

/// Merge `parts` into `residual` (not finalized yet: fem::finalize it afterwards), as described above.
/// Fills residual.parts with a summary of each. Throws InputError for the errors above.
void assemble_parts(Model& residual, std::vector<Part>& parts);

}  // namespace seflex::fem
