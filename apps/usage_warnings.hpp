#pragma once
// Printing what solutions::check_card_usage found, the same way in every command:
//
//   const auto usage = solutions::check_card_usage(model, solutions::Solution::Statics, cases);
//   seflex::app::print_card_usage(model, usage);   // "warning: ..." lines on stderr
//   solutions::require_usable(model, usage);       // InputError (exit 3) if a needed card is unsupported
//
// One line per card and reason: "warning: CARD: N cards, first at file:line: reason". Approximated
// entries say "warning (approximation)"; Caution entries (the deck is computed as written, with a
// consequence to check: J = 0, thick plates, RFORCE's unit) "warning". Refused entries are not printed here: require_usable
// turns the first into the command's error message (seflex info lists them all).
#include <cstdio>
#include <string>

#include "seflex/fem/model.hpp"
#include "seflex/solutions/card_usage.hpp"

namespace seflex::app {

/// Print what the reader chose and says so (Model::read_warnings: an INCLUDE found in two places) on
/// stderr, one "warning: " line each (flushed). Returns how many.
inline std::size_t print_read_warnings(const fem::Model& model) {
  for (const std::string& w : model.read_warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  std::fflush(stderr);
  return model.read_warnings.size();
}

/// Print the reader's warnings, then the Unused and Approximated entries of `usage` on stderr
/// (flushed). Returns how many lines.
inline std::size_t print_card_usage(const fem::Model& model, const solutions::CardUsage& usage) {
  std::size_t n = print_read_warnings(model);
  for (const solutions::CardUse& u : usage.uses) {
    if (u.kind == solutions::CardUse::Kind::Refused) continue;
    const char* prefix = u.kind == solutions::CardUse::Kind::Approximated ? "warning (approximation)" : "warning";
    std::fprintf(stderr, "%s: %s\n", prefix, solutions::describe(model, u).c_str());
    ++n;
  }
  std::fflush(stderr);
  return n;
}

/// print_card_usage, then require_usable: the usual start of a command that runs a solution.
inline void check_and_print_card_usage(const fem::Model& model, const solutions::CardUsage& usage) {
  print_card_usage(model, usage);
  solutions::require_usable(model, usage);
}

}  // namespace seflex::app
