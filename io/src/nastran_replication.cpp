// Bulk Data replication rows ('=', '==', '*x', '=n'): see nastran_replication.hpp.
#include "nastran_replication.hpp"

#include <charconv>
#include <limits>

#include "seflex/common/error.hpp"
#include "seflex/io/nastran_cards.hpp"
#include "seflex/io/nastran_number.hpp"

namespace seflex::io::nastran {
namespace {

/// "*x" or "*(x)" added to the field `old` of the card before, as field text.
std::string increment(std::string_view f, std::string_view old, const std::string& what) {
  std::string_view x = f.substr(1);
  if (x.size() >= 2 && x.front() == '(' && x.back() == ')') x = x.substr(1, x.size() - 2);
  const FieldKind kx = classify(x);
  // A blank field is incremented from 0 (MSC's test deck dbxdra7 gives its grids' CD so).
  if (old.empty()) old = kx == FieldKind::Real ? std::string_view("0.") : std::string_view("0");
  const FieldKind ko = classify(old);
  if (kx != FieldKind::Integer && kx != FieldKind::Real)
    throw InputError(what + ": got " + quote_field(f) + "; expected an increment *x or *(x) with x a number");
  if (ko == FieldKind::Integer && kx == FieldKind::Integer) {
    int a = 0, b = 0;
    parse_int(old, a);
    parse_int(x, b);
    const long long sum = static_cast<long long>(a) + b;
    if (sum > std::numeric_limits<int>::max() || sum < std::numeric_limits<int>::min())
      throw InputError(what + ": " + quote_field(old) + " + " + quote_field(x) + " overflows; expected an integer");
    return std::to_string(sum);
  }
  if (ko != FieldKind::Real)
    throw InputError(what + ": " + quote_field(f) + " increments " + quote_field(old) + "; expected an integer increment of an integer field or an increment of a real field");
  double a = 0.0, b = 0.0;
  parse_real(old, a);
  if (kx == FieldKind::Integer) {
    int bi = 0;
    parse_int(x, bi);
    b = bi;
  } else {
    parse_real(x, b);
  }
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, a + b);
  std::string s(buf, r.ptr);
  const std::size_t e = s.find('e');
  if (e != std::string::npos) s[e] = 'E';
  if (s.find('.') == std::string::npos) s.insert(e == std::string::npos ? s.size() : e, ".");
  return s;
}

}  // namespace

void replicate_fields(const Card& previous, const Card& pattern, const std::string& where,
                      std::vector<std::string>& out) {
  out.clear();
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    const std::string_view f = pattern.raw(i);
    const std::string field = "field " + std::to_string(i % 8 + 2) + (i >= 8 ? " of continuation " + std::to_string(i / 8) : std::string());
    if (f.empty()) {
      out.emplace_back();
    } else if (f == "=") {
      out.emplace_back(previous.raw(i));
    } else if (f == "==") {
      for (std::size_t j = i; j < previous.size(); ++j) out.emplace_back(previous.raw(j));
      break;
    } else if (f[0] == '*') {
      out.push_back(increment(f, previous.raw(i), where + ": replication of " + previous.label() + ", " + field));
    } else if (f.find('=') != std::string_view::npos) {
      throw InputError(where + ": replication of " + previous.label() + ", " + field + ": got " + quote_field(f) +
                       "; expected '=' or '==' alone in a field");
    } else {
      out.emplace_back(f);
    }
  }
  while (!out.empty() && out.back().empty()) out.pop_back();
  if (out.empty()) throw InputError(where + ": replication of " + previous.label() + " gives a card with no fields; expected data");
}

int replication_count(std::string_view field1, const std::string_view* fields, std::size_t n_fields,
                      const std::string& where) {
  std::string_view count_text = field1.substr(1);
  if (count_text.size() >= 2 && count_text.front() == '(' && count_text.back() == ')')
    count_text = count_text.substr(1, count_text.size() - 2);
  int count = 0;
  if (!parse_int(count_text, count) || count < 1 || count > kMaxThru)
    throw InputError(where + ": replication " + quote_field(field1) + ": expected '=' or a repeat count '=n' or '=(n)' with 1 <= n <= " +
                     std::to_string(kMaxThru) + " in field 1");
  for (std::size_t k = 0; k < n_fields; ++k)
    if (!fields[k].empty())
      throw InputError(where + ": replication " + quote_field(field1) + ": field " + std::to_string(k + 2) + " is " +
                       quote_field(fields[k]) + "; expected nothing after a repeat count");
  return count;
}

}  // namespace seflex::io::nastran
