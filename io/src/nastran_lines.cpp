#include "seflex/io/nastran_lines.hpp"

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>

#include "seflex/common/error.hpp"
#include "seflex/io/nastran_card.hpp"
#include "seflex/io/nastran_number.hpp"

namespace seflex::io::nastran {

std::string load_text(const std::filesystem::path& path, const std::string& from) {
  auto fail = [&](const std::string& why) {
    throw InputError((from.empty() ? std::string() : from + ": ") + "cannot read " + path.string() + " (" + why + ")");
  };
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail("it is a directory; expected a file");
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    fail("not a regular file (a device or pipe?); expected a file");
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) fail(std::strerror(errno));
  std::string text;
  char buf[1 << 16];
  std::size_t n = 0;
  if (std::fseek(f.get(), 0, SEEK_END) == 0) {
    const long size = std::ftell(f.get());
    if (size > 0) text.reserve(static_cast<std::size_t>(size));
    std::rewind(f.get());
  }
  while ((n = std::fread(buf, 1, sizeof buf, f.get())) > 0) text.append(buf, n);
  if (std::ferror(f.get())) fail(std::strerror(errno));
  if (text.find('\t') != std::string::npos) expand_tabs(text);
  return text;
}

void expand_tabs(std::string& text) {
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  std::size_t col = 0;
  for (const char c : text) {
    if (c == '\t') {
      const std::size_t next = (col / 8 + 1) * 8;
      out.append(next - col, ' ');
      col = next;
    } else {
      out += c;
      col = (c == '\n') ? 0 : col + 1;
    }
  }
  text.swap(out);
}

namespace {
enum class ByteClass : std::uint8_t { Text, Dollar, Comma, Control };
constexpr auto kByteClass = [] {
  std::array<ByteClass, 256> t{};
  for (int c = 0; c < 0x20; ++c) t[c] = ByteClass::Control;
  t[0x7f] = ByteClass::Control;
  t['$'] = ByteClass::Dollar;
  t[','] = ByteClass::Comma;
  return t;
}();
}  // namespace

bool LineCursor::next(Line& line) {
  if (has_pushed_) {
    has_pushed_ = false;
    line = pushed_;
    return true;
  }
  if (pos_ >= text_.size()) return false;
  const char* begin = text_.data() + pos_;
  const std::size_t rest = text_.size() - pos_;
  const void* nl = std::memchr(begin, '\n', rest);
  std::size_t len = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - begin) : rest;
  pos_ += len + (nl ? 1 : 0);
  ++number_;
  if (len > 0 && begin[len - 1] == '\r') --len;
  last_raw_ = std::string_view(begin, len);
  if (len > kMaxLineLength)
    throw InputError(location(*file_name_, number_) + ": line is " + std::to_string(len) +
                     " characters long; expected at most " + std::to_string(kMaxLineLength) +
                     " (Nastran lines have 80 columns; is this a text file?)");
  bool comma = false;
  std::size_t end = len;
  for (std::size_t i = 0; i < len; ++i) {
    // Eight bytes at a time while none of them is a control character, '$' or ',' (most lines of a
    // fixed-format deck): the exact any-byte tests of Anderson's "Bit Twiddling Hacks" (haszero,
    // hasless), 5 % of `seflex info` on a 1M-element deck.
    while (i + 8 <= len) {
      std::uint64_t w;
      std::memcpy(&w, begin + i, 8);
      constexpr std::uint64_t ones = 0x0101010101010101ull, highs = 0x8080808080808080ull;
      auto has_zero = [&](std::uint64_t v) { return ((v - ones) & ~v & highs) != 0; };
      // Once a comma was seen (a free-field line), further commas change nothing: only '$' and
      // control characters stop the fast path.
      const bool special = ((w - 0x20 * ones) & ~w & highs) != 0 || has_zero(w ^ (0x7f * ones)) ||
                           has_zero(w ^ (0x24 * ones)) || (!comma && has_zero(w ^ (0x2c * ones)));
      if (special) break;
      i += 8;
    }
    if (i >= len) break;
    const auto c = static_cast<unsigned char>(begin[i]);
    const ByteClass k = kByteClass[c];
    if (k == ByteClass::Text) continue;
    if (k == ByteClass::Dollar) {
      end = i;
      break;
    }
    if (k == ByteClass::Comma) {
      comma = true;
    } else {
      const char* what = c == 0 ? "a NUL byte" : c == '\r' ? "a carriage return" : "a control character";
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", c);
      throw InputError(location(*file_name_, number_) + ", column " + std::to_string(i + 1) + ": " + what + " (" +
                       hex + "); expected text (is this a binary file?)");
    }
  }
  while (end > 0 && begin[end - 1] == ' ') --end;
  line.text = std::string_view(begin, end);
  line.number = number_;
  line.free = comma;
  return true;
}

std::string_view trim(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && s[b] == ' ') ++b;
  while (e > b && s[e - 1] == ' ') --e;
  return s.substr(b, e - b);
}

std::string upper(std::string_view s) {
  std::string u(s);
  for (char& c : u)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return u;
}

namespace {
inline std::string_view column_field(std::string_view line, std::size_t begin, std::size_t width) {
  if (begin >= line.size()) return {};
  return trim(line.substr(begin, width));
}
}  // namespace

void split_fixed(std::string_view line, std::size_t n, std::string_view& field1, std::string_view* data,
                 std::string_view& field10) {
  if (line.size() > 80) line = line.substr(0, 80);
  field1 = column_field(line, 0, 8);
  const std::size_t width = 64 / n;
  for (std::size_t k = 0; k < n; ++k) data[k] = column_field(line, 8 + k * width, width);
  field10 = column_field(line, 72, 8);
}

std::size_t split_free(std::string_view line, std::string_view* out, std::size_t cap) {
  std::size_t count = 0, start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::string_view f = trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (count < cap) out[count] = f;
    ++count;
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return count;
}

}  // namespace seflex::io::nastran
