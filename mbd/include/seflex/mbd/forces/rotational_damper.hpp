#pragma once
// Linear rotational damper on one hinge angle: tau = -c phidot.
#include <string>

#include "seflex/mbd/forces/hinge_force.hpp"

namespace seflex::mbd {

struct RotationalDamper {
  HingeIndex hinge;
  double c = 0.0;  ///< [N m s / rad], >= 0
};

void validate(const RotationalDamper& d, const std::string& name);
void evaluate(const RotationalDamper& d, const HingeValues& h, HingeForceResult& r);  // r resized and overwritten (no allocation once sized)

}  // namespace seflex::mbd
