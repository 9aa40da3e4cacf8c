// Case-control selection of the subcases a solution runs (case_selection.hpp).
#include "seflex/solutions/case_selection.hpp"

#include <cstdlib>

#include "seflex/common/error.hpp"

namespace seflex::solutions {
namespace {

CaseSelection from(const fem::CaseControl& cc, const fem::Subcase* chosen) {
  CaseSelection sel;
  sel.spc = cc.global.spc;
  sel.load = cc.global.load;
  sel.method = cc.global.method;
  sel.mpc = cc.global.mpc;
  sel.temperature = cc.global.temperature;
  sel.label = cc.global.label;
  sel.other = cc.global.other;
  if (chosen != nullptr) {  // the reader already completed subcases with the global selections
    sel.subcase_id = chosen->id;
    sel.ref = chosen->ref;
    if (chosen->spc) sel.spc = chosen->spc;
    if (chosen->load) sel.load = chosen->load;
    if (chosen->method) sel.method = chosen->method;
    if (chosen->mpc) sel.mpc = chosen->mpc;
    if (chosen->temperature) sel.temperature = chosen->temperature;
    if (!chosen->label.empty()) sel.label = chosen->label;
    if (!chosen->other.empty()) sel.other = chosen->other;
  }
  // SUPORT1 = SID (an integer; anything else stays in `other`, which card usage refuses)
  for (auto it = sel.other.begin(); it != sel.other.end(); ++it) {
    if (it->name != "SUPORT1") continue;
    char* end = nullptr;
    const long sid = std::strtol(it->value.c_str(), &end, 10);
    while (end && (*end == ' ' || *end == '\t')) ++end;
    if (end == it->value.c_str() || (end && *end != '\0') || sid <= 0 || sid > 99999999) continue;
    sel.suport1 = static_cast<int>(sid);
    sel.other.erase(it);
    break;
  }
  return sel;
}

const fem::Subcase* find(const fem::Model& model, int subcase) {
  for (const fem::Subcase& s : model.case_control.subcases)
    if (s.id == subcase) return &s;
  if (subcase != 0)
    throw InputError(SourceRef{model.files.empty() ? std::string() : model.files.front(), 0},
                     "case control: SUBCASE " + std::to_string(subcase) + " is not defined");
  return nullptr;
}

}  // namespace

CaseSelection select_case(const fem::Model& model, std::optional<int> subcase) {
  const fem::CaseControl& cc = model.case_control;
  const fem::Subcase* chosen = nullptr;
  if (subcase)
    chosen = find(model, *subcase);
  else if (!cc.subcases.empty())
    chosen = &cc.subcases.front();
  return from(cc, chosen);
}

std::vector<CaseSelection> select_cases(const fem::Model& model, std::optional<int> subcase) {
  const fem::CaseControl& cc = model.case_control;
  if (subcase) return {from(cc, find(model, *subcase))};
  if (cc.subcases.empty()) return {from(cc, nullptr)};
  std::vector<CaseSelection> out;
  for (const fem::Subcase& s : cc.subcases) out.push_back(from(cc, &s));
  return out;
}

std::string case_name(const CaseSelection& c) {
  return c.subcase_id ? "SUBCASE " + std::to_string(c.subcase_id) : std::string("the global case control");
}

}  // namespace seflex::solutions
