#pragma once
// Inertia invariants of a reduced body (superelement/inertia_invariants.hpp, docs/inertia-invariants.md),
// computed from its recovery matrix, FE node positions and FE mass.
#include "seflex/superelement/superelement.hpp"

namespace seflex::reduction {

/// Compute the inertia invariants of `body` from body.recovery, body.p_BoI_B and body.M_fe.
/// Throws InputError when the body has no recovery matrix or no FE mass (the invariants need both).
se::InertiaInvariants compute_inertia_invariants(const se::Superelement& body);

}  // namespace seflex::reduction
