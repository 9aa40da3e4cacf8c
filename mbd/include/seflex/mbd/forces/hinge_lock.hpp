#pragma once
// Latching lock on a hinge angle (solar-array.md "Hinge springs and locks"): inactive until the
// angle first reaches phi_lock (from the side it starts on); from that instant (located by the
// integrator, not merely noticed at the end of a step) it adds
//   tau = -k_lock (phi - phi_lock) - c_lock phidot
// in both directions, for good. The latch state lives in State::locks.
#include <string>

#include "seflex/mbd/forces/hinge_force.hpp"

namespace seflex::mbd {

struct HingeLock {
  HingeIndex hinge;
  double phi_lock = 0.0;  ///< [rad]
  double k_lock = 0.0;    ///< [N m / rad], > 0
  double c_lock = 0.0;    ///< [N m s / rad], >= 0 (optional lock damping)
};

void validate(const HingeLock& l, const std::string& name);
void evaluate(const HingeLock& l, const HingeValues& h, bool latched, HingeForceResult& r);  // r resized and overwritten (no allocation once sized)

}  // namespace seflex::mbd
