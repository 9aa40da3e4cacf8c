#pragma once
// Nastran component masks: bit (c-1) for component c = 1..6 (T1 T2 T3 R1 R2 R3).
#include <string>

#include "seflex/fem/model.hpp"

namespace seflex::fem {

/// "123456"-style text of a mask ("" for 0).
std::string component_string(ComponentMask mask);

inline bool has_component(ComponentMask mask, int c) { return c >= 1 && c <= 6 && (mask >> (c - 1)) & 1u; }

}  // namespace seflex::fem
