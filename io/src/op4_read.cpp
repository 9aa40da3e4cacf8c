// Reading OUTPUT4 text matrices (op4.hpp: parse_op4).
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "seflex/common/error.hpp"
#include "seflex/io/nastran_number.hpp"
#include "seflex/io/op4.hpp"

namespace seflex::io {

namespace {

class Op4Parser {
 public:
  Op4Parser(const std::string& text, const std::string& file) : text_(text), file_(file) {}

  std::vector<Op4Matrix> run() {
    std::vector<Op4Matrix> out;
    if (text_.find('\0') != std::string::npos)
      throw InputError(file_ + ": not an OP4 text file (it holds binary data); expected an OUTPUT4 file written "
                               "FORMATTED (ASCII): seflex reads no binary OP4");
    std::string_view line;
    while (next(line)) {
      if (blank(line)) continue;
      out.push_back(matrix(line));
    }
    if (out.empty()) throw InputError(file_ + ": no matrix; expected OUTPUT4 text (a header NCOL NROW NF NTYPE NAME)");
    return out;
  }

 private:
  const std::string& text_;
  const std::string& file_;
  std::size_t pos_ = 0, line_no_ = 0;
  std::string name_;      ///< the matrix being read
  std::size_t width_ = 0;  ///< its values' width (characters)

  static bool blank(std::string_view s) { return s.find_first_not_of(" \t\r") == std::string_view::npos; }

  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    std::size_t e = text_.find('\n', pos_);
    if (e == std::string::npos) e = text_.size();
    line = std::string_view(text_).substr(pos_, e - pos_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos_ = e + 1;
    ++line_no_;
    return true;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(file_ + ":" + std::to_string(line_no_) + ": OP4" + (name_.empty() ? "" : " matrix " + name_) + ": " + what);
  }

  void need(std::string_view& line, const char* what) {
    if (!next(line)) fail(std::string("the file ends; expected ") + what);
  }

  /// Integers separated by blanks (a record of I8 fields, or one I12 string header).
  std::vector<long long> integers(std::string_view line, const char* what) {
    std::vector<long long> v;
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && line[i] == ' ') ++i;
      if (i == line.size()) break;
      std::size_t e = i;
      while (e < line.size() && line[e] != ' ') ++e;
      long long x = 0;
      const auto [p, ec] = std::from_chars(line.data() + i, line.data() + e, x);
      if (ec != std::errc() || p != line.data() + e)
        fail("got " + nastran::quote_field(line.substr(i, e - i)) + " in " + what + "; expected integers");
      v.push_back(x);
      i = e;
    }
    return v;
  }

  /// The header's fixed-width integer field k (I8).
  long long header_field(std::string_view line, std::size_t k, const char* field) {
    if (line.size() < 8 * (k + 1)) fail(std::string("a header shorter than its ") + field + " field; expected NCOL NROW NF NTYPE (4 x I8) NAME");
    const std::string_view f = line.substr(8 * k, 8);
    const std::size_t a = f.find_first_not_of(' ');
    long long x = 0;
    const auto [p, ec] = a == std::string_view::npos ? std::from_chars_result{f.data(), std::errc::invalid_argument}
                                                    : std::from_chars(f.data() + a, f.data() + f.size(), x);
    if (ec != std::errc() || p != f.data() + f.size())
      fail(std::string("header field ") + field + " got " + nastran::quote_field(f) + "; expected an integer in columns " +
           std::to_string(8 * k + 1) + "-" + std::to_string(8 * k + 8));
    return x;
  }

  Op4Matrix matrix(std::string_view header) {
    name_.clear();
    const long long ncol = header_field(header, 0, "NCOL"), nrow_signed = header_field(header, 1, "NROW");
    const long long form = header_field(header, 2, "NF"), type = header_field(header, 3, "NTYPE");
    std::string_view rest = header.substr(32);
    const std::string_view name = rest.substr(0, std::min<std::size_t>(8, rest.size()));
    const std::size_t b = name.find_first_not_of(' '), e = name.find_last_not_of(' ');
    if (b == std::string_view::npos) fail("a header without a matrix name (columns 33-40)");
    name_ = std::string(name.substr(b, e - b + 1));
    const bool bigmat = nrow_signed < 0;
    const long long nrow = bigmat ? -nrow_signed : nrow_signed;
    if (ncol <= 0 || nrow <= 0 || ncol > (1LL << 31) || nrow > (1LL << 31))
      fail("NCOL " + std::to_string(ncol) + ", NROW " + std::to_string(nrow_signed) + "; expected positive sizes");
    if (type != 1 && type != 2)
      fail("NTYPE " + std::to_string(type) + "; expected 1 or 2 (real single or double precision): seflex reads no complex OP4 matrix");
    if (static_cast<double>(ncol) * static_cast<double>(nrow) > 2e8)
      fail(std::to_string(nrow) + " x " + std::to_string(ncol) + "; expected a matrix small enough to hold dense (at most 2e8 terms)");
    // format: "1P,3E23.16" -> 3 values per line, 23 characters each
    const std::string fmt = rest.size() > 8 ? std::string(rest.substr(8)) : std::string();
    std::size_t x = fmt.find_first_of("ED", fmt.find(',') == std::string::npos ? 0 : fmt.find(',') + 1);
    std::size_t per_line = 0, width = 0;
    if (x != std::string::npos && x > 0) {
      std::size_t d = x;
      while (d > 0 && std::isdigit(static_cast<unsigned char>(fmt[d - 1]))) --d;
      per_line = static_cast<std::size_t>(std::atoi(fmt.c_str() + d));
      width = static_cast<std::size_t>(std::atoi(fmt.c_str() + x + 1));
    }
    if (per_line == 0 || width < 8 || width > 40)
      fail("format " + nastran::quote_field(fmt) + "; expected a Fortran format such as 1P,3E23.16 after the name (column 41 on)");
    width_ = width;
    Op4Matrix m;
    m.name = name_;
    m.form = static_cast<int>(form);
    m.values = Eigen::MatrixXd::Zero(nrow, ncol);
    const long long words_per_value = type == 2 ? 2 : 1;
    std::string_view line;
    for (;;) {
      need(line, "a column record ICOL IROW NW (or the end record, column NCOL + 1)");
      const std::vector<long long> rec = integers(line, "a column record");
      if (rec.size() != 3) fail("got " + nastran::quote_field(line) + "; expected a column record ICOL IROW NW (3 x I8)");
      const long long col = rec[0], irow = rec[1], nw = rec[2];
      if (col == ncol + 1) {  // the end record and its one value
        need(line, "the value of the end record");
        break;
      }
      if (col < 1 || col > ncol) fail("column " + std::to_string(col) + "; expected 1 to " + std::to_string(ncol) + " (or NCOL + 1 to end)");
      if (nw < 0) fail("NW " + std::to_string(nw) + "; expected a word count >= 0");
      if (irow > 0) {  // dense: NW values from row IROW
        values(m, col - 1, irow - 1, nw);
        continue;
      }
      if (irow != 0) fail("IROW " + std::to_string(irow) + "; expected a row >= 1 (dense) or 0 (sparse strings)");
      long long left = nw;
      while (left > 0) {
        need(line, "a string header of a sparse column");
        const std::vector<long long> h = integers(line, "a string header");
        long long L = 0, row = 0;
        if (bigmat) {
          if (h.size() != 2) fail("got " + nastran::quote_field(line) + "; expected a bigmat string header 'L+1 IROW' (2 x I8)");
          L = h[0] - 1, row = h[1];
          left -= L + 2;
        } else {
          if (h.size() != 1) fail("got " + nastran::quote_field(line) + "; expected a string header IS = (L + 1) * 65536 + IROW");
          L = (h[0] >> 16) - 1, row = h[0] - ((L + 1) << 16);
          left -= L + 1;
        }
        if (L <= 0 || L % words_per_value != 0 || row < 1)
          fail("string header " + nastran::quote_field(line) + " gives " + std::to_string(L) + " words from row " + std::to_string(row) +
               "; expected a positive multiple of " + std::to_string(words_per_value) + " words and a row >= 1");
        values(m, col - 1, row - 1, L / words_per_value);
      }
      if (left != 0) fail("the strings of column " + std::to_string(col) + " hold more words than its NW = " + std::to_string(nw));
    }
    name_.clear();
    return m;
  }

  /// n values of column c from row r, on lines of the header's width.
  void values(Op4Matrix& m, Eigen::Index c, long long r, long long n) {
    if (r + n > m.values.rows())
      fail("column " + std::to_string(c + 1) + ": " + std::to_string(n) + " values from row " + std::to_string(r + 1) +
           " pass the last row " + std::to_string(m.values.rows()) + "; expected them inside the matrix");
    const std::size_t width = width_;
    long long k = 0;
    std::string_view line;
    while (k < n) {
      need(line, "the values of a column");
      std::size_t at = 0;
      bool any = false;
      while (k < n && at + 1 < line.size()) {
        const std::string_view f = line.substr(at, width);
        at += width;
        const std::size_t a = f.find_first_not_of(' '), z = f.find_last_not_of(' ');
        if (a == std::string_view::npos) break;
        double v = 0;
        if (!nastran::parse_real(f.substr(a, z - a + 1), v))
          fail("column " + std::to_string(c + 1) + ", row " + std::to_string(r + k + 1) + ": got " + nastran::quote_field(f) +
               "; expected a real number " + std::to_string(width) + " characters wide");
        m.values(static_cast<Eigen::Index>(r + k), c) = v;
        ++k;
        any = true;
      }
      if (!any) fail("got " + nastran::quote_field(line) + "; expected " + std::to_string(n - k) + " more values of column " + std::to_string(c + 1));
    }
  }
};

}  // namespace

std::vector<Op4Matrix> parse_op4(const std::string& text, const std::string& file) {
  return Op4Parser(text, file).run();
}

std::vector<Op4Matrix> read_op4(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open the OP4 file; expected a readable file");
  std::ostringstream s;
  s << in.rdbuf();
  return parse_op4(s.str(), path.string());
}

}  // namespace seflex::io
