#pragma once
// The force elements on hinge angles, as one closed set (std::variant) evaluated by one visitor.
#include <string>
#include <variant>

#include "seflex/mbd/forces/cable_loop.hpp"
#include "seflex/mbd/forces/hinge_lock.hpp"
#include "seflex/mbd/forces/rotational_damper.hpp"
#include "seflex/mbd/forces/torsion_spring.hpp"

namespace seflex::mbd {

using ForceElement = std::variant<TorsionSpring, HingeLock, CableLoop, RotationalDamper>;

struct NamedForceElement {
  std::string name;
  ForceElement element;
};

/// Evaluate any force element; `latched` matters for locks only.
HingeForceResult evaluate(const ForceElement& fe, const HingeValues& h, bool latched);
/// Same, into `out` (its storage reused: no allocation once sized).
void evaluate(const ForceElement& fe, const HingeValues& h, bool latched, HingeForceResult& out);

/// "spring", "lock", "cable", "damper".
const char* kind_name(const ForceElement& fe);

}  // namespace seflex::mbd
