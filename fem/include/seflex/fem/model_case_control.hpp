#pragma once
// Part of model.hpp (the FE model as data; conventions there), kept apart to keep headers short:
// eigenvalue methods (EIGRL/EIGR), PARAM and what seflex keeps of the executive and case control.
// No parsing and no numerics here.
#include <optional>
#include <string>
#include <vector>

#include "seflex/fem/card_ref.hpp"

namespace seflex::fem {

/// EIGRL (Lanczos) or EIGR (other methods; seflex honours F1, F2, ND and NORM of both).
struct EigenMethod {
  int sid = 0;
  bool is_eigr = false;
  bool is_eigb = false;             ///< EIGB: a buckling method (f1, f2 = L1, L2: a range of load factors)
  std::string method = "LAN";
  std::optional<double> f1, f2;     ///< frequency range (Hz); EIGRL V1/V2
  std::optional<int> nd;            ///< number of roots
  std::string norm = "MASS";        ///< MASS, MAX or POINT
  int norm_grid = 0, norm_component = 0;
  CardRef ref;
};

/// "EIGRL", "EIGR" or "EIGB": the card an eigenvalue method was read from, for messages.
inline const char* method_card(const EigenMethod& e) { return e.is_eigb ? "EIGB" : e.is_eigr ? "EIGR" : "EIGRL"; }

struct Param {
  std::string name;
  std::vector<std::string> values;  ///< raw field text after the name
  CardRef ref;
};

// ---------------------------------------------------------------------------------------------
// Executive and case control (what seflex keeps of it)
/// A case-control command that selects analysis input seflex does not use (TEMPERATURE(INIT),
/// DLOAD, DEFORM, SUPORT1, ...): kept so that a solution that would need it can refuse the deck.
struct CaseCommand {
  std::string name;                 ///< upper case, with its describer: "TEMPERATURE(LOAD)", "DLOAD"
  std::string value;                ///< the text after '='
  CardRef ref;
};

struct Subcase {
  int id = 0;                       ///< 0 = the global (above any SUBCASE) selections
  std::string label;
  std::optional<int> spc, load, method, mpc;
  std::optional<int> temperature;   ///< TEMPERATURE(LOAD), (BOTH) or bare: the thermal load set
  std::vector<std::string> k2gg, m2gg;
  std::vector<CaseCommand> other;   ///< selections seflex does not use (global ones are inherited)
  CardRef ref;                      ///< the SUBCASE line (file 0, line 0 for the global level)
};

struct CaseControl {
  std::optional<std::string> sol;   ///< e.g. "103", "SEMODES", "3"
  std::string title, subtitle;
  Subcase global;
  std::vector<Subcase> subcases;
};

}  // namespace seflex::fem
