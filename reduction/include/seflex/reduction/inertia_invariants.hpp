#pragma once
// Inertia invariants of a reduced body: computed by the superelement library
// (superelement/inertia_invariants.hpp, docs/inertia-invariants.md); re-exported here for reduction/ and io/.
#include "seflex/superelement/superelement.hpp"

namespace seflex::reduction {

using se::compute_inertia_invariants;

}  // namespace seflex::reduction
