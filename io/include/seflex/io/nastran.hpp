#pragma once
// Nastran input decks -> fem::Model.
//
//   fem::Model model = seflex::io::read_nastran("wing.bdf");
//
// Reads the executive control (SOL), the case control (SPC, LOAD, METHOD, MPC, K2GG/M2GG, TITLE,
// SUBTITLE, LABEL, SUBCASE, PARAM) and the bulk data: small-field, large-field and free-field cards
// mixed, continuations, INCLUDE, ENDDATA. A file without BEGIN BULK is read as bulk data only.
// INCLUDE as MSC Nastran finds the file: a relative path against the main deck's folder, then the
// including file's (a warning in Model::read_warnings when both hold a different file of that name);
// `NAME:path` through a logical symbol (NastranReadOptions::symbols, else the environment variable NAME).
// Cards seflex does not support are listed in Model::unsupported (count and first file:line), never
// dropped silently. docs/nastran-support.md lists every card, field and convention.
//
// Errors (unreadable or missing files, malformed fields, duplicate ids, references to missing grids,
// properties, materials or coordinate systems, INCLUDE cycles, binary data) throw seflex::InputError
// whose message starts with "file:line: CARD id, field N (NAME): ".
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "seflex/fem/model.hpp"

namespace seflex::io {

/// A logical symbol for INCLUDE names `NAME:path` (MSC Nastran's `symbol=NAME=VALUE` keyword of rc
/// files and the command line; seflex's --symbol NAME=VALUE): NAME stands for the folder VALUE.
struct NastranSymbol {
  std::string name;
  std::string value;  ///< may use $VAR or ${VAR}: a symbol given before it, else an environment variable
};

struct NastranReadOptions {
  /// Run fem::finalize on the model (ids, references, coordinate systems). Off only to inspect the
  /// raw cards.
  bool finalize = true;
  /// If set, receives the main file's text (tabs expanded) after reading, so that a caller who also
  /// scans it (io::read_model: `$seflex` directives) need not load it again.
  std::string* main_text = nullptr;
  /// Logical symbols, in order (names compared in any case; a name given twice: the last counts). An
  /// INCLUDE `NAME:path` whose NAME is not here takes the environment variable NAME.
  std::vector<NastranSymbol> symbols;
};

/// Parse "NAME=VALUE" (a command-line --symbol argument); throws InputError naming `text` if it has no
/// '=' or NAME is not a name (letters, digits, '_').
NastranSymbol parse_nastran_symbol(const std::string& text);

/// Read the deck at `path` and the files it includes.
fem::Model read_nastran(const std::filesystem::path& path, const NastranReadOptions& options = {});

/// Read deck text held in memory; `name` is used in messages and INCLUDEs are relative to `dir`.
fem::Model read_nastran_text(std::string_view text, const std::string& name = "<text>",
                             const std::filesystem::path& dir = {}, const NastranReadOptions& options = {});

}  // namespace seflex::io
