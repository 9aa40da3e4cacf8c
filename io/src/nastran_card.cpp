#include "seflex/io/nastran_card.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "seflex/common/error.hpp"

namespace seflex::io::nastran {

std::string location(const std::string& file, std::uint32_t line) {
  return line > 0 ? file + ":" + std::to_string(line) : file;
}

void Card::reset(std::string_view name, const std::string* file_name, std::uint32_t file, std::uint32_t line) {
  name_len_ = std::min(name.size(), sizeof(name_) - 1);
  std::memcpy(name_, name.data(), name_len_);
  file_name_ = file_name;
  file_ = file;
  line_ = line;
  fields_.clear();
  lines_.clear();
}

void Card::append(const std::string_view* fields, std::size_t n, std::uint32_t line) {
  const std::size_t padded = (fields_.size() + n - 1) / n * n;
  fields_.resize(padded);
  lines_.resize(padded, lines_.empty() ? line : lines_.back());
  fields_.insert(fields_.end(), fields, fields + n);
  lines_.insert(lines_.end(), n, line);
}

std::uint32_t Card::line_of(std::size_t i) const {
  if (lines_.empty()) return line_;
  return i < lines_.size() ? lines_[i] : lines_.back();
}

std::size_t Card::used() const {
  std::size_t n = fields_.size();
  while (n > 0 && fields_[n - 1].empty()) --n;
  return n;
}

std::string Card::label() const {
  std::string s(name());
  if (!raw(0).empty()) {
    s += ' ';
    s.append(raw(0).substr(0, 40));
  }
  return s;
}

void Card::fail(std::size_t i, const char* what, const std::string& problem) const {
  const std::string file = file_name_ ? *file_name_ : std::string("<deck>");
  std::string msg = location(file, line_of(i)) + ": " + label() + ", field " + std::to_string(i % 8 + 2) + " (" +
                    what + ")";
  if (i >= fields_.size() && i >= 8) msg += " of continuation " + std::to_string(i / 8) + " (missing)";
  throw InputError(msg + ": " + problem);
}

void Card::fail_card(const std::string& problem) const {
  const std::string file = file_name_ ? *file_name_ : std::string("<deck>");
  throw InputError(location(file, line_) + ": " + label() + ": " + problem);
}

std::string Card::got(std::size_t i) const {
  const std::string_view f = raw(i);
  switch (classify(f)) {
    case FieldKind::Blank: return "blank";
    case FieldKind::Integer: return "got integer " + quote_field(f);
    case FieldKind::Real: return "got real " + quote_field(f);
    case FieldKind::Text: return "got text " + quote_field(f);
    case FieldKind::Invalid: break;
  }
  return "got " + quote_field(f) + ", which is not a number";
}

int Card::checked_integer(std::size_t i, const char* what, bool positive, bool blank_ok) const {
  int v = 0;
  if (!parse_int(raw(i), v) || (positive && v <= 0))
    fail(i, what, got(i) + (positive ? "; expected an integer > 0" : "; expected an integer") + (blank_ok ? " or blank" : ""));
  return v;
}

double Card::checked_real(std::size_t i, const char* what, bool blank_ok) const {
  double v = 0;
  if (!parse_real(raw(i), v))
    fail(i, what, got(i) + "; expected a real number (with a decimal point)" + (blank_ok ? " or blank" : ""));
  return v;
}

int Card::integer(std::size_t i, const char* what) const { return checked_integer(i, what, false, false); }
int Card::integer_or(std::size_t i, const char* what, int fallback) const {
  return blank(i) ? fallback : checked_integer(i, what, false, true);
}
int Card::id(std::size_t i, const char* what) const { return checked_integer(i, what, true, false); }
int Card::id_or(std::size_t i, const char* what, int fallback) const {
  return blank(i) ? fallback : checked_integer(i, what, true, true);
}
double Card::real(std::size_t i, const char* what) const { return checked_real(i, what, false); }
double Card::real_or(std::size_t i, const char* what, double fallback) const {
  return blank(i) ? fallback : checked_real(i, what, true);
}

std::string Card::text_or(std::size_t i, const char* what, std::string_view fallback) const {
  const std::string_view f = raw(i);
  if (f.empty()) return std::string(fallback);
  if (classify(f) != FieldKind::Text) fail(i, what, got(i) + "; expected a character value");
  std::string s(f);
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

fem::ComponentMask Card::components(std::size_t i, const char* what, bool allow_blank, bool allow_zero) const {
  const std::string_view f = raw(i);
  const char* expected = allow_zero ? "; expected component numbers 1-6 (e.g. 123456), or 0 for a scalar point"
                                    : "; expected component numbers 1-6 without repeats (e.g. 123456)";
  if (f.empty()) {
    if (allow_blank) return 0;
    fail(i, what, std::string("blank") + expected);
  }
  if (allow_zero && f == "0") return 0;
  fem::ComponentMask mask = 0;
  for (const char c : f) {
    if (c == ' ') continue;
    if (c < '1' || c > '6') fail(i, what, got(i) + expected);
    const auto bit = static_cast<fem::ComponentMask>(1u << (c - '1'));
    if (mask & bit) fail(i, what, got(i) + " (component " + std::string(1, c) + " repeated)" + expected);
    mask |= bit;
  }
  return mask;
}

}  // namespace seflex::io::nastran
