#pragma once
// Bulk Data replication rows (MSC Nastran QRG, "Format of Bulk Data Entries", replication; pyNastran
// reads them the same way). A line with '=' in field 1 makes a card of the card before it, field by
// field: '=' copies the field, '==' copies it and every field after it, '*x' or '*(x)' adds x to it
// (an integer to an integer field, a real or an integer to a real field, either to a blank field as
// to 0), a blank field stays blank and any other text replaces it; fields after the last one of the
// '=' line are left out. A line '=n' or '=(n)' repeats the last replication n times, each from the
// card made before. The deck reader (nastran_deck.cpp) reads the lines and parses the cards made.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "seflex/io/nastran_card.hpp"

namespace seflex::io::nastran {

/// The fields of the card that the '=' line `pattern` (its data fields, continuations included)
/// makes of the card `previous`, into `out` (cleared first; trailing blank fields dropped).
/// Throws InputError starting with `where` for a bad increment, a '=' inside other text, or a card
/// with no fields left.
void replicate_fields(const Card& previous, const Card& pattern, const std::string& where,
                      std::vector<std::string>& out);

/// The repeat count n (1 <= n <= kMaxThru) of a '=n' or '=(n)' line, whose field 1 is `field1`
/// and whose n_fields data fields `fields` must be blank. Throws InputError starting with `where`.
int replication_count(std::string_view field1, const std::string_view* fields, std::size_t n_fields,
                      const std::string& where);

}  // namespace seflex::io::nastran
