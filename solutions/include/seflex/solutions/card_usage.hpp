#pragma once
// Which cards a solution uses: the one place that decides, per solution and subcase, whether each
// card of a model is
//   - used and supported  (nothing to say),
//   - used but not supported (Refused: the solution cannot give the answer the deck asks for; a
//     solution must not run: require_usable throws InputError naming the card, file:line and why),
//   - not used by this solution (Unused: an unselected LOAD/SPC/MPC/EIGR set, output, optimisation
//     or aero cards, loads in normal modes ...: a warning, as Nastran runs such decks), or
//   - a card seflex does not know (no row in the card table): Refused by every solution, as MSC
//     Nastran stops on an unknown card (require_usable lists them all, with count and first
//     file:line, and names --ignore-unknown); Unused ("ignored") when the caller asks to go on
//     without them (ignore_unknown_cards) and in seflex info, or
//   - used with an approximation seflex states (Approximated: a warning), or
//   - used as written, with a consequence a careful user wants to be told (Caution: a warning):
//     a bar without torsional stiffness (J = 0), a plate thick for its mesh, RFORCE's unit
//     (solutions/src/modelling_cautions.hpp).
//
//   auto cases = solutions::select_cases(model, subcase);
//   auto usage = solutions::check_card_usage(model, solutions::Solution::Statics, cases);
//   for (const auto& u : usage.uses) ...print a warning...     // apps/usage_warnings.hpp
//   solutions::require_usable(model, usage);                   // throws on the first Refused
//
// Every command calls it (seflex info prints the classification for the deck's SOL without
// refusing); the solution functions (solve_static, solve_normal_modes, reduce_to_superelement)
// call require_usable themselves, so that no library caller gets an answer computed without a card
// the deck needs.
//
// Which card types seflex supports, and what each is for, is one table in
// solutions/src/card_usage_table.cpp: to support a new card, parse it into the Model and flip its
// row (for a card that belongs to a load/method set, give the function that lists its set ids).
// Reference checks of the cards of unselected sets (a missing grid in an SPC set the case control
// does not select, an EIGR whose NORM = POINT grid does not exist) become warnings, as in Nastran.
//
// A new solution (e.g. buckling) calls check_card_usage with its Solution and the subcases it runs,
// prints with apps/usage_warnings.hpp, and calls require_usable before assembling. Buckling is
// classified as statics (LOAD of every case) plus METHOD: a METHOD that selects an EIGB card is
// refused while EIGB is not read into the Model; when it is, flip EIGB's row and let
// Classifier::selections() find it among the model's methods.
#include <cstdint>
#include <string>
#include <vector>

#include "seflex/fem/model.hpp"
#include "seflex/solutions/case_selection.hpp"

namespace seflex::solutions {

/// What a command does with the model.
enum class Solution : unsigned char {
  Info,          ///< seflex info: nothing is run; classification for the deck's SOL (solution_of_deck)
  Statics,       ///< SOL 101: stiffness, LOAD, SPC, MPC of every subcase run
  NormalModes,   ///< SOL 103: stiffness, mass, SPC, MPC, METHOD; ASET/OMIT (Guyan)
  Buckling,      ///< SOL 105: statics of the preload subcase + METHOD (EIGB/EIGRL) of the buckling one
  CraigBampton,  ///< seflex reduce: stiffness, mass, SPC, MPC of the first subcase; modes from the command line
  Convert,       ///< seflex convert: every card seflex models is written; the rest cannot be
};

/// The solution a deck's executive control asks for (SOL 101/1/STATICS -> Statics, 103/3/MODES ->
/// NormalModes, 105/5/BUCKLING -> Buckling), or Info when absent or another SOL.
Solution solution_of_deck(const fem::Model& model);

/// "linear statics (SOL 101)", ... for messages.
const char* solution_name(Solution s);

struct CardUse {
  enum class Kind : unsigned char { Unused, Caution, Approximated, Refused };
  Kind kind = Kind::Unused;
  std::string card;       ///< card name ("PLOAD4"), "case control TEMPERATURE(LOAD)", "PARAM"
  std::size_t count = 0;  ///< cards concerned
  fem::CardRef first;     ///< the first of them
  std::string reason;     ///< why, in a phrase ("load set 7 is not selected by any subcase run")
  bool unknown_card = false;  ///< a card seflex does not know (Refused unless ignore_unknown_cards)
};

/// Interface cards of a Craig-Bampton reduction (bit mask): those cards are used as the interface.
enum InterfaceFrom : unsigned { kInterfaceNone = 0, kInterfaceAset = 1, kInterfaceBset = 2, kInterfaceSuport = 4 };

struct CardUsage {
  Solution solution = Solution::Info;
  std::vector<CaseSelection> cases;  ///< the subcases the solution runs
  std::vector<CardUse> uses;         ///< Refused, Approximated, Caution, then Unused; in deck order within each
  bool refused() const;
  std::size_t count(CardUse::Kind kind) const;
};

/// Classify every card and case-control selection of a finalized model for `solution` run on
/// `cases`. Never throws for what it finds; `interface` names the CB interface cards;
/// `ignore_unknown_cards`: a solution goes on without the cards seflex does not know (a warning each)
/// instead of refusing the deck (the command-line option --ignore-unknown).
CardUsage check_card_usage(const fem::Model& model, Solution solution, const std::vector<CaseSelection>& cases,
                           unsigned interface = kInterfaceNone, bool ignore_unknown_cards = false);

/// Throws InputError if an entry is Refused. Cards seflex does not know first, all of them in one
/// message: "<file:line of the first>: N kinds of card seflex does not know: CARD (C cards, first at
/// file:line), ...; <solution> does not run on a deck with cards it does not know (MSC Nastran stops
/// on them too): correct or remove them, or give --ignore-unknown to run without them". Otherwise the
/// first Refused entry: "<file:line>: <card>: <reason>; <solution> cannot run without it" (and how
/// many other cards are refused). Does nothing if none is.
void require_usable(const fem::Model& model, const CardUsage& usage);

/// One line per entry: "CARD: N cards, first at file:line: reason", or for a case-control
/// selection "case control LOAD (file:line): reason" (no prefix, no newline).
std::string describe(const fem::Model& model, const CardUse& use);

}  // namespace seflex::solutions
