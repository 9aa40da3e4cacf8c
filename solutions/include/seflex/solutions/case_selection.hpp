#pragma once
// Which case-control selections a solution runs with.
//
// As in Nastran, a selection a subcase does not make is inherited from the global level (above any
// SUBCASE). Statics runs every subcase (select_cases); normal modes and the Craig-Bampton reduction
// run one (select_case: the one asked for, else the first SUBCASE, else the global selections).
#include <optional>
#include <string>
#include <vector>

#include "seflex/fem/model.hpp"

namespace seflex::solutions {

struct CaseSelection {
  int subcase_id = 0;  ///< 0: the global (above any SUBCASE) selections
  std::string label;
  std::optional<int> spc, load, method, mpc;
  std::optional<int> temperature;       ///< TEMPERATURE(LOAD) (or BOTH): thermal load set
  std::optional<int> suport1;           ///< SUPORT1: the SUPORT1 set whose supports statics holds
  std::vector<fem::CaseCommand> other;  ///< selections seflex does not use (fem::Subcase::other)
  fem::CardRef ref;                     ///< the SUBCASE line (line 0: the global level)
};

/// The subcase `subcase` if given (InputError naming the deck if it does not exist), otherwise the
/// first SUBCASE, otherwise the global selections.
CaseSelection select_case(const fem::Model& model, std::optional<int> subcase = std::nullopt);

/// The subcase `subcase` if given, otherwise every SUBCASE in the order of the deck, otherwise the
/// global selections (one case).
std::vector<CaseSelection> select_cases(const fem::Model& model, std::optional<int> subcase = std::nullopt);

/// "SUBCASE 3" or "the global case control" (subcase id 0), for messages.
std::string case_name(const CaseSelection& c);

}  // namespace seflex::solutions
