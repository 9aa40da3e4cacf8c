#pragma once
// CONM2 rotary inertia that only the shells' drilling penalty holds (see drilling_inertia.cpp).
#include <cstddef>

#include "seflex/fem/model.hpp"

namespace seflex::solutions::detail {

struct DrillingInertia {
  std::size_t count = 0;  ///< CONM2s concerned
  fem::CardRef first;     ///< the first of them (deck order)
  int first_grid = 0;
  double first_inertia = 0;  ///< its inertia about the shell normal (basic units)
};

/// CONM2s (CID 0 or -1) on grids that only coplanar CQUAD4/CTRIA3 reach (no bar, rod, spring, rigid
/// element, RBE3 or MPC), with a non-zero rotary inertia n^T I n about the shells' normal n. That
/// rotation has no stiffness of its own in a flat shell: only the drilling penalty (PARAM K6ROT)
/// holds it, so the inertia gives spurious low modes (the demo panel: 43-62 Hz with K6ROT = 100).
DrillingInertia drilling_inertia(const fem::Model& model);

}  // namespace seflex::solutions::detail
