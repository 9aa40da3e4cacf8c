// Inertia invariants (docs/inertia-invariants.md). Work in progress: filled by the lead.
#include "seflex/reduction/inertia_invariants.hpp"

#include "seflex/common/error.hpp"

namespace seflex::reduction {

se::InertiaInvariants compute_inertia_invariants(const se::Superelement& body) {
  if (body.recovery.size() == 0 || body.M_fe.size() == 0)
    throw InputError("superelement '" + body.name + "': inertia invariants need the recovery matrix and the FE mass");
  return {};
}

}  // namespace seflex::reduction
