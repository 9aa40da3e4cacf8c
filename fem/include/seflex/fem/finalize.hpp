#pragma once
// Turn a freshly read Model into a consistent one (owner: the Nastran/gmsh readers' author).
#include <string>

#include "seflex/common/error.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

/// Resolve and check a model read from user files:
/// - apply GRDSET and BAROR/BEAMOR defaults; complete MAT1 (E, G, nu) by Nastran's rule;
/// - build the id -> index maps and reject duplicate ids;
/// - resolve every coordinate system (CORD2x chains through RID, CORD1x through grids) and every
///   GRID's basic position;
/// - check every reference: grids, properties, materials, coordinate systems, SPC/LOAD/SPCADD
///   sets named by the case control.
/// Throws InputError naming file:line, card, id, field and what was expected. Idempotent.
void finalize(Model& model);

/// The source location of a card, for messages ("deck.bdf:57").
SourceRef where(const Model& model, const CardRef& ref);

/// Axes (columns, in basic) of the displacement coordinate system `cd` at basic point x
/// (cylindrical and spherical axes depend on the point). cd = 0 gives the identity.
Eigen::Matrix3d displacement_axes(const Model& model, int cd, const Eigen::Vector3d& x_basic);

/// Transform a point given in system `cid` to basic.
Eigen::Vector3d to_basic(const Model& model, int cid, const Eigen::Vector3d& x);

/// Value of PARAM name (first field) as a number, or `fallback` if absent.
double param_number(const Model& model, const std::string& name, double fallback);

}  // namespace seflex::fem
