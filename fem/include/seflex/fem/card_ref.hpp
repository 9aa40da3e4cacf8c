#pragma once
#include <cstdint>

namespace seflex::fem {

/// Source of a card: index into Model::files, 1-based line of the card's first line.
struct CardRef {
  std::uint32_t file = 0;
  std::uint32_t line = 0;
};

}  // namespace seflex::fem
