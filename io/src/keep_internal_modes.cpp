// Fewer fixed-interface modes of a superelement (superelement_file.hpp): the trailing columns of
// the Craig-Bampton basis go, from the matrices, the recovery and the invariants (their dataset table).
#include "seflex/io/superelement_file.hpp"

#include "seflex/common/error.hpp"
#include "invariant_datasets.hpp"

namespace seflex::io {

se::Superelement keep_internal_modes(const se::Superelement& s, int modes) {
  SEFLEX_DEMAND(modes >= 0 && modes <= s.num_modes, "mode count out of range");
  se::Superelement r = s;
  const Eigen::Index n = 6 * s.num_interfaces() + modes;
  r.num_modes = modes;
  r.K = s.K.topLeftCorner(n, n);
  r.M = s.M.topLeftCorner(n, n);
  r.Phi_f = s.Phi_f.leftCols(n);
  if (s.recovery.size() != 0) r.recovery = s.recovery.leftCols(n);
  r.invariants = detail::truncate_invariants(s.invariants, n);
  r.stiffening = detail::truncate_stiffening(s.stiffening, n);
  r.mode_frequencies_hz = s.mode_frequencies_hz.head(modes);
  if (modes < s.num_modes) r.truncation.first_neglected_hz = s.mode_frequencies_hz(modes);
  r.truncation.max_kept_hz = modes > 0 ? s.mode_frequencies_hz(modes - 1) : 0.0;
  return r;
}

}  // namespace seflex::io
