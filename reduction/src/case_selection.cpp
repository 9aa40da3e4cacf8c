// Case-control selection of the subcase a solution runs (case_selection.hpp).
#include "seflex/reduction/case_selection.hpp"

#include "seflex/common/error.hpp"

namespace seflex::reduction {

CaseSelection select_case(const fem::Model& model, std::optional<int> subcase) {
  const fem::CaseControl& cc = model.case_control;
  const fem::Subcase* chosen = nullptr;
  if (subcase) {
    for (const fem::Subcase& s : cc.subcases)
      if (s.id == *subcase) chosen = &s;
    if (chosen == nullptr && *subcase != 0)
      throw InputError(SourceRef{model.files.empty() ? std::string() : model.files.front(), 0},
                       "case control: SUBCASE " + std::to_string(*subcase) + " is not defined");
  } else if (!cc.subcases.empty()) {
    chosen = &cc.subcases.front();
  }
  CaseSelection sel;
  sel.spc = cc.global.spc;
  sel.load = cc.global.load;
  sel.method = cc.global.method;
  sel.label = cc.global.label;
  if (chosen != nullptr) {
    sel.subcase_id = chosen->id;
    if (chosen->spc) sel.spc = chosen->spc;
    if (chosen->load) sel.load = chosen->load;
    if (chosen->method) sel.method = chosen->method;
    if (!chosen->label.empty()) sel.label = chosen->label;
  }
  return sel;
}

}  // namespace seflex::reduction
