#pragma once
// Rigid-body mass properties of a model, the way Nastran's grid point weight generator (GPWG,
// PARAM GRDPNT) computes them: M0 = D^T M D, with M the assembled mass matrix (default lumped or
// coupled as PARAM COUPMASS says, CONM2 offsets and inertias, NSM) and D the rigid-body modes about
// the reference point.
//
// Computed element by element (D_e^T M_e D_e summed), without assembling M.
// WTMASS: the MSC/NX convention is that GPWG prints mass in the deck's input units, i.e. PARAM WTMASS
// is NOT applied ("WTMASS ... does not affect ... mass properties calculated by the Grid Point
// Weight Generator", Autodesk Nastran Reference Guide, PARAM WTMASS). So M0, mass and inertias here
// are those of the deck's numbers; multiply by `wtmass` for the mass the analysis uses.
#include <Eigen/Core>
#include <optional>

#include "seflex/fem/model.hpp"

namespace seflex::fem {

struct MassProperties {
  double wtmass = 1.0;                           ///< PARAM WTMASS in effect
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();  ///< reference point (basic); GRDPNT grid or origin
  int reference_grid = 0;                        ///< 0 = basic origin
  Eigen::Matrix<double, 6, 6> M0 = Eigen::Matrix<double, 6, 6>::Zero();  ///< rigid-body mass about reference, basic axes (WTMASS not applied)
  double mass = 0.0;                             ///< total mass, in the deck's mass units (divided by WTMASS, as GPWG prints)
  Eigen::Vector3d cg = Eigen::Vector3d::Zero();  ///< centre of gravity in basic
  Eigen::Matrix3d I_cg = Eigen::Matrix3d::Zero();///< inertia tensor about the CG, basic axes (I11 = sum m(y^2+z^2))
  Eigen::Vector3d principal_moments = Eigen::Vector3d::Zero();
  Eigen::Matrix3d principal_axes = Eigen::Matrix3d::Identity();  ///< columns, basic
};

/// Mass properties of a finalized model. reference_grid overrides PARAM GRDPNT when given.
MassProperties mass_properties(const Model& model, std::optional<int> reference_grid = std::nullopt);

}  // namespace seflex::fem
