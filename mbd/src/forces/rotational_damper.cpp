#include "seflex/mbd/forces/rotational_damper.hpp"

#include <cmath>

#include "seflex/common/error.hpp"

namespace seflex::mbd {

void validate(const RotationalDamper& d, const std::string& name) {
  if (!(d.c >= 0.0) || !std::isfinite(d.c))
    throw InputError("damper '" + name + "': damping must be a non-negative number (N m s/rad)");
}

void evaluate(const RotationalDamper& d, const HingeValues& h, HingeForceResult& r) {
  r.resize(1);
  r.hinges[0] = d.hinge;
  r.tau[0] = -d.c * h.phidot[d.hinge.value];
  r.dtau_dphidot(0, 0) = -d.c;
  r.value = r.tau[0];
}

}  // namespace seflex::mbd
