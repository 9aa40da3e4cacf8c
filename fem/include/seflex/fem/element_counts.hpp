#pragma once
// The elements of a model counted by card name, for reports (`seflex info`, `seflex convert`).
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "seflex/fem/model.hpp"

namespace seflex::fem {

/// (card name, count) for every element kind with at least one element, in a fixed order (line
/// elements, shells, masses and springs, rigid elements, solids, others); scalar elements grouped
/// ("CELAS3/CELAS4", "CMASS1-4").
std::vector<std::pair<std::string, std::size_t>> element_counts(const Model& model);

/// The sum of element_counts (rigid elements included).
std::size_t element_count(const Model& model);

}  // namespace seflex::fem
