#pragma once
// Turn a freshly read Model into a consistent one (owner: the Nastran/gmsh readers' author).
// Blank-field defaults that depend on other cards (GRDSET, BAROR, BEAMOR, PID = EID) and the MAT1
// rule for a blank E, G or NU are applied by the reader, which alone knows which fields were blank.
#include <string>

#include "seflex/common/error.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

/// Resolve and check a model read from user files:
/// - build the id -> index maps and reject duplicate ids (grids and scalar points share one id
///   space, so do all elements incl. CONM2, RBE2, RBAR and RBE3, and all properties; SPCADD,
///   MPCADD, LOAD and EIGR/EIGRL ids must be unique and distinct from the sets they combine);
/// - resolve every coordinate system (CORD2x chains through RID, CORD1x through grids) and every
///   GRID's basic position;
/// - check every reference of the structure: grids, scalar points, properties (of the right kind),
///   materials, coordinate systems of elements, rigid elements, ASET/OMIT/BSET/SUPORT entries, and
///   the PARAM values seflex uses (WTMASS > 0, GRDPNT a grid, COUPMASS, K6ROT);
/// - check components: 1-6 on grids, 0 on scalar points.
/// Cards that belong to a set the case control selects (SPC, MPC, FORCE, MOMENT, LOAD, EIGR/EIGRL,
/// DMIG) are checked when a solution selects them, and solutions::check_card_usage warns about the
/// problems of the unselected ones: as Nastran, a deck is not refused for a set it does not use.
/// Throws InputError naming file:line, card, id, field and what was expected. Idempotent.
void finalize(Model& model);

/// Resolve coordinate systems and grid basic positions (part of finalize; needs grid_index and
/// coord_index). Throws InputError for undefined or circular references and degenerate systems.
void resolve_coordinates(Model& model);

/// The source location of a card, for messages ("deck.bdf:57").
SourceRef where(const Model& model, const CardRef& ref);

/// Axes (columns, in basic) of the displacement coordinate system `cd` at basic point x
/// (cylindrical and spherical axes depend on the point: radial, tangential, axial / radial, polar,
/// azimuthal; on the axis the angle 0 is used). cd = 0 gives the identity.
Eigen::Matrix3d displacement_axes(const Model& model, int cd, const Eigen::Vector3d& x_basic);

/// Transform a point given in system `cid` to basic (cylindrical: R, THETA deg, Z; spherical: R,
/// THETA deg from the z axis, PHI deg).
Eigen::Vector3d to_basic(const Model& model, int cid, const Eigen::Vector3d& x);

/// Value of PARAM name (first value) as a number, or `fallback` if absent. The first PARAM of a
/// name counts (finalize rejects two with different values). Throws InputError if not a number.
double param_number(const Model& model, const std::string& name, double fallback);

/// Value of a numeric PARAM seflex reads (WTMASS, COUPMASS, K6ROT, GRDPNT, CK2, CM2, CBMIN3, CBMIN4T),
/// or its default if absent: the QRG's default (MYSTRAN's for CBMIN3/CBMIN4T). Demands a known name.
double param_number(const Model& model, const std::string& name);

/// Whether `p`, a parameter seflex reads, has the value seflex assumes when the parameter is absent
/// (the numeric defaults above; AUTOSPC YES). False for a parameter seflex does not read.
/// Throws InputError for a numeric parameter whose value is not a number.
bool param_at_default(const Model& model, const Param& p);

/// Whether PARAM QUAD4TYP MIN4T asks for MYSTRAN's plate elements (assembly.hpp: mystran_plate).
/// Throws InputError naming the card for QUAD4TYP MIN4 (Tessler's MIN4 quad, not available) or any
/// other value than MIN4T.
bool mystran_plate_elements(const Model& model);

}  // namespace seflex::fem
