#pragma once
// Linear rotational damper on one hinge angle: tau = -c phidot.
#include <string>

#include "seflex/mbd/hinge_force.hpp"

namespace seflex::mbd {

struct RotationalDamper {
  HingeIndex hinge;
  double c = 0.0;  ///< [N m s / rad], >= 0
};

void validate(const RotationalDamper& d, const std::string& name);
HingeForceResult evaluate(const RotationalDamper& d, const HingeValues& h);

}  // namespace seflex::mbd
