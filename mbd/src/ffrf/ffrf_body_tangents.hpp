#pragma once
// Analytic tangents of the FFRF-LM body forces (ffrf_body_tangents.cpp): the pieces body_force
// (ffrf_body.cpp) calls after its evaluation, whose intermediates in BodyForce::Scratch they read.
#include <Eigen/Core>

#include "bodies/aic_inertia_detail.hpp"
#include "ffrf/ffrf_detail.hpp"

namespace seflex::mbd::detail {

using Scratch = BodyForce::Scratch;

/// w.Cw (nb x nb) and w.Kz (nb x k): the body-axis inertia force's derivatives w.r.t. the body-axis
/// velocities and the modal coordinates, by the FE node sums, after their evaluation (w.N, U, Ud,
/// MXdd).
void nodal_inertia_tangents(const FfrfBody& b, const AicElement& e, bool elastic_gyro, Scratch& w);
/// The same from the inertia invariants, after inertia_projections at the same state (pr, ws).
void invariant_inertia_tangents(const FfrfBody& b, const AicElement& e, const InertiaProjections& pr, Scratch& w,
                                AicWorkspace& ws);
/// w.Cw of a rigid body's wrench in body axes (mass m, centre of mass c and inertia I in B, spin Om).
void rigid_tangents(double m, const Eigen::Vector3d& c, const Eigen::Matrix3d& I, const Eigen::Vector3d& Om, Scratch& w);
/// out.K, out.C (world) from the body-axis w.Mw, w.Cw, w.Kz, force w.fw (frame rows), velocities w.v and
/// accelerations w.ab, at the frame rotation R.
void tangents_to_world(const Eigen::Matrix3d& R, int k, Scratch& w, BodyForce& out);

}  // namespace seflex::mbd::detail
