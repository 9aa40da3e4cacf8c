#pragma once
// Which case-control selections a single-solution command (seflex static, seflex modes) runs with.
#include <optional>
#include <string>

#include "seflex/fem/model.hpp"

namespace seflex::reduction {

struct CaseSelection {
  int subcase_id = 0;  ///< 0: the global (above any SUBCASE) selections
  std::string label;
  std::optional<int> spc, load, method;
};

/// The subcase `subcase` if given (InputError naming the deck if it does not exist), otherwise the
/// first SUBCASE, otherwise the global selections. As in Nastran, a selection a subcase does not
/// make is inherited from the global level.
CaseSelection select_case(const fem::Model& model, std::optional<int> subcase = std::nullopt);

}  // namespace seflex::reduction
