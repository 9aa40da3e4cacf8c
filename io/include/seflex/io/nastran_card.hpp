#pragma once
// One bulk-data entry (a card and its continuation lines) as a flat list of data fields, with typed
// accessors that throw InputError naming file:line, card, id, field number and field name.
//
// Field numbering: data field i (0-based) is Nastran field (i % 8) + 2 of logical line i / 8, the
// numbering of the MSC Nastran Quick Reference Guide (field 1 holds the name or the continuation
// marker, field 10 the continuation marker). A large-field line holds 4 data fields, so two of them
// make one logical line. Field texts are views into the file buffers, trimmed of blanks.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "seflex/fem/model.hpp"
#include "seflex/io/nastran_number.hpp"

namespace seflex::io::nastran {

class Card {
 public:
  /// Start a new card named `name` (upper case, at most 8 characters) at `line` of file `file`.
  void reset(std::string_view name, const std::string* file_name, std::uint32_t file, std::uint32_t line);
  /// Append `n` data fields of physical line `line`; pads to a multiple of n first, so a large-field
  /// half line (n = 4) and a small-field or free-field line (n = 8) land on Nastran's field numbers.
  void append(const std::string_view* fields, std::size_t n, std::uint32_t line);

  std::string_view name() const { return {name_, name_len_}; }
  std::size_t size() const { return fields_.size(); }
  fem::CardRef ref() const { return {file_, line_}; }
  std::uint32_t line_of(std::size_t i) const;

  /// Trimmed text of data field i; empty if blank or past the end.
  std::string_view raw(std::size_t i) const { return i < fields_.size() ? fields_[i] : std::string_view(); }
  bool blank(std::size_t i) const { return raw(i).empty(); }
  FieldKind kind(std::size_t i) const { return classify(raw(i)); }
  /// Index one past the last non-blank field.
  std::size_t used() const;

  // Typed accessors; `what` is the field's name in the QRG ("PID"). Required fields throw if blank.
  int integer(std::size_t i, const char* what) const;
  int integer_or(std::size_t i, const char* what, int fallback) const;
  /// Integer > 0 (ids).
  int id(std::size_t i, const char* what) const;
  int id_or(std::size_t i, const char* what, int fallback) const;
  double real(std::size_t i, const char* what) const;
  double real_or(std::size_t i, const char* what, double fallback) const;
  /// Character field, upper-cased; blank gives `fallback`.
  std::string text_or(std::size_t i, const char* what, std::string_view fallback) const;
  /// Component list such as "123456" or "12 456" (embedded blanks allowed, no repeats), as a mask.
  /// With allow_zero, "0" (a scalar point) gives 0. Blank gives 0 if allow_blank, else throws.
  fem::ComponentMask components(std::size_t i, const char* what, bool allow_blank, bool allow_zero = false) const;

  /// Throw InputError "file:line: NAME id, field N (what): problem".
  [[noreturn]] void fail(std::size_t i, const char* what, const std::string& problem) const;
  /// Throw InputError "file:line: NAME id: problem" (a problem of the whole card).
  [[noreturn]] void fail_card(const std::string& problem) const;
  /// "got '1.5' (a real)" / "blank" - the usual first half of a problem text.
  std::string got(std::size_t i) const;

  /// "NAME id" (id = field 2 text) for messages.
  std::string label() const;

 private:
  int checked_integer(std::size_t i, const char* what, bool positive, bool blank_ok) const;
  double checked_real(std::size_t i, const char* what, bool blank_ok) const;

  char name_[16] = {};
  std::size_t name_len_ = 0;
  const std::string* file_name_ = nullptr;
  std::uint32_t file_ = 0, line_ = 0;
  std::vector<std::string_view> fields_;
  std::vector<std::uint32_t> lines_;
};

/// "file:line" of a location in the deck.
std::string location(const std::string& file, std::uint32_t line);

}  // namespace seflex::io::nastran
