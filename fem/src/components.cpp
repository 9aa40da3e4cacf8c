#include "seflex/fem/components.hpp"

namespace seflex::fem {

std::string component_string(ComponentMask mask) {
  std::string s;
  for (int c = 1; c <= 6; ++c)
    if (has_component(mask, c)) s += static_cast<char>('0' + c);
  return s;
}

}  // namespace seflex::fem
