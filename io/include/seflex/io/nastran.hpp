#pragma once
// Nastran input decks -> fem::Model.
//
//   fem::Model model = seflex::io::read_nastran("wing.bdf");
//
// Reads the executive control (SOL), the case control (SPC, LOAD, METHOD, MPC, K2GG/M2GG, TITLE,
// SUBTITLE, LABEL, SUBCASE, PARAM) and the bulk data: small-field, large-field and free-field cards
// mixed, continuations, INCLUDE, ENDDATA. A file without BEGIN BULK is read as bulk data only.
// Cards seflex does not support are listed in Model::unsupported (count and first file:line), never
// dropped silently. docs/nastran-support.md lists every card, field and convention.
//
// Errors (unreadable or missing files, malformed fields, duplicate ids, references to missing grids,
// properties, materials or coordinate systems, INCLUDE cycles, binary data) throw seflex::InputError
// whose message starts with "file:line: CARD id, field N (NAME): ".
#include <filesystem>
#include <string>
#include <string_view>

#include "seflex/fem/model.hpp"

namespace seflex::io {

struct NastranReadOptions {
  /// Run fem::finalize on the model (ids, references, coordinate systems). Off only to inspect the
  /// raw cards.
  bool finalize = true;
  /// If set, receives the main file's text (tabs expanded) after reading, so that a caller who also
  /// scans it (io::read_model: `$seflex` directives) need not load it again.
  std::string* main_text = nullptr;
};

/// Read the deck at `path` (and the files it includes, relative to the including file).
fem::Model read_nastran(const std::filesystem::path& path, const NastranReadOptions& options = {});

/// Read deck text held in memory; `name` is used in messages and INCLUDEs are relative to `dir`.
fem::Model read_nastran_text(std::string_view text, const std::string& name = "<text>",
                             const std::filesystem::path& dir = {}, const NastranReadOptions& options = {});

}  // namespace seflex::io
