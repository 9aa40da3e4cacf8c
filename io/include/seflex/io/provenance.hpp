#pragma once
// The provenance of a superelement that only a reader of files knows. reduce_to_superelement fills
// the rest (seflex_version, source_warnings); `seflex reduce` calls record_source, so a library
// caller that reads the same deck, reduces it with the same options and calls record_source with the
// same path writes the same .se file, byte for byte, except `created` (the time of the call).
#include <string>

#include "seflex/fem/model.hpp"
#include "seflex/superelement/superelement.hpp"

namespace seflex::io {

/// The current time as ISO-8601 UTC, e.g. "2026-12-06T22:40:00Z" (always 20 characters).
std::string iso_utc_now();

/// SHA-256 (hex) of every file the model was read from (Model::files: the deck and its INCLUDEs),
/// concatenated in reading order. Throws InputError naming a file that cannot be read again.
std::string model_source_hash(const fem::Model& model);

/// Fills s.source_file (the path as the caller names the model, e.g. as given on the command line),
/// s.source_hash (model_source_hash) and s.created (`created`, default now).
void record_source(se::Superelement& s, const fem::Model& model, const std::string& source_file,
                   const std::string& created = iso_utc_now());

}  // namespace seflex::io
