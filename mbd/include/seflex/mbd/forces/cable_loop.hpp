#pragma once
// Closed cable loop synchronising two hinge lines (solar-array.md "Synchronisation cables"): two
// tension-only cables of stiffness k and preload T0 over a pulley of radius r_a on hinge line a and
// r_b on hinge line b. With phi_a, phi_b the mean angles of the hinges listed for each line,
//   e  = r_a phi_a - r_b phi_b                  (cable elongation; 0 when synchronous)
//   T1 = max(0, T0 + k e),  T2 = max(0, T0 - k e),  N = T1 - T2
//   tau on each hinge of line a = -N r_a / n_a,  on each hinge of line b = +N r_b / n_b
// (without preload the pair is one linear spring on e). Energy: elastic energy of both cables
// relative to the synchronous state.
#include <string>
#include <vector>

#include "seflex/mbd/forces/hinge_force.hpp"

namespace seflex::mbd {

struct CableLoop {
  std::vector<HingeIndex> hinges_a, hinges_b;
  double r_a = 0.0, r_b = 0.0;  ///< pulley radii [m], > 0
  double k = 0.0;               ///< cable stiffness [N/m], > 0
  double preload = 0.0;         ///< T0 [N], >= 0
};

void validate(const CableLoop& c, const std::string& name);
void evaluate(const CableLoop& c, const HingeValues& h, HingeForceResult& r);  // r resized and overwritten (no allocation once sized)

}  // namespace seflex::mbd
