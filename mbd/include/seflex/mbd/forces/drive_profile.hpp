#pragma once
// Prescribed hinge motions (drives) used by scenes and tests.
#include "seflex/mbd/model.hpp"

namespace seflex::mbd {

/// Hub angle of the spin-up drive of Simo and Vu-Quoc (1986): rate w [rad/s] ramped over T [s] with
/// phi = w/T (t^2/2 + (cos(2 pi t/T) - 1)/(2 pi/T)^2) for t < T, then w (t - T/2); the rate and the
/// acceleration are its exact derivatives (continuous at t = T).
DriveValue spin_up_drive(double rate, double ramp_time, double t);

}  // namespace seflex::mbd
