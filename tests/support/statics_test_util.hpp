#pragma once
// Reading a static solution by grid id and component in the solution tests.
#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex::test {

/// Displacement component c (1..6) of grid id g, in its CD system.
inline double displacement(const fem::Model& m, const solutions::StaticSolution& s, int g, int c) {
  return s.u_g[*fem::find_dof(m, s.dofs, g, c)];
}

}  // namespace seflex::test
