#include "seflex/io/nastran_number.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace seflex::io::nastran {
namespace {

inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool is_alpha(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

/// Split a real into mantissa and exponent and rebuild it as "mantissa e exponent" in `buf` (which
/// std::from_chars reads). Returns the length written, 0 if `s` is not a Nastran real.
std::size_t normalise_real(std::string_view s, char* buf, std::size_t cap) {
  std::size_t i = 0, n = s.size(), out = 0;
  if (n == 0 || n + 2 > cap) return 0;
  if (s[0] == '+' || s[0] == '-') {
    if (s[0] == '-') buf[out++] = '-';
    ++i;
  }
  std::size_t digits = 0;
  bool point = false;
  for (; i < n; ++i) {
    const char c = s[i];
    if (is_digit(c)) {
      ++digits;
      buf[out++] = c;
    } else if (c == '.' && !point) {
      point = true;
      buf[out++] = c;
    } else {
      break;
    }
  }
  if (digits == 0) return 0;
  if (i == n) return point ? out : 0;  // "12" is an integer, not a real
  // exponent: [EeDd][+-]?digits or [+-]digits
  const char c = s[i];
  if (c == 'E' || c == 'e' || c == 'D' || c == 'd') {
    ++i;
  } else if (c != '+' && c != '-') {
    return 0;
  }
  buf[out++] = 'e';
  if (i < n && (s[i] == '+' || s[i] == '-')) {
    if (s[i] == '-') buf[out++] = '-';
    ++i;
  }
  std::size_t exp_digits = 0;
  for (; i < n && is_digit(s[i]); ++i, ++exp_digits) buf[out++] = s[i];
  if (exp_digits == 0 || i != n) return 0;
  return out;
}

}  // namespace

FieldKind classify(std::string_view f) {
  if (f.empty()) return FieldKind::Blank;
  if (is_alpha(f[0])) return FieldKind::Text;
  int i = 0;
  if (parse_int(f, i)) return FieldKind::Integer;
  double x = 0;
  if (parse_real(f, x)) return FieldKind::Real;
  // an integer too large for int is still an integer to the user; report it as invalid with the text
  return FieldKind::Invalid;
}

bool parse_int(std::string_view f, int& value) {
  if (f.empty()) return false;
  const char* b = f.data();
  const char* e = b + f.size();
  if (*b == '+') {
    ++b;
    if (b == e || !is_digit(*b)) return false;
  } else if (*b == '-') {
    if (b + 1 == e || !is_digit(b[1])) return false;
  } else if (!is_digit(*b)) {
    return false;
  }
  auto [p, ec] = std::from_chars(b, e, value);
  return ec == std::errc() && p == e;
}

bool parse_real(std::string_view f, double& value) {
  char buf[80];
  const std::size_t len = normalise_real(f, buf, sizeof buf);
  if (len == 0) return false;
  auto [p, ec] = std::from_chars(buf, buf + len, value, std::chars_format::general);
  if (ec != std::errc() || p != buf + len) return false;
  return std::isfinite(value);
}

std::string quote_field(std::string_view f) {
  constexpr std::size_t kMax = 40;
  std::string s = "'";
  for (std::size_t i = 0; i < f.size() && i < kMax; ++i) {
    const auto c = static_cast<unsigned char>(f[i]);
    if (c >= 0x20 && c < 0x7f) {
      s += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      s += hex;
    }
  }
  if (f.size() > kMax) s += "...";
  s += "'";
  return s;
}

}  // namespace seflex::io::nastran
