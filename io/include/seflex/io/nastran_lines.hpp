#pragma once
// Physical lines of a Nastran input file and their fields.
// - Files are read whole into memory; tabs are expanded to 8-column stops on loading.
// - A line ends at LF; a CR before the LF is dropped (CRLF files). '$' starts a comment to the end of
//   the line. Control characters (NUL, other bytes below 0x20) outside comments are an error, as is a
//   line longer than kMaxLineLength characters.
// - A line with a comma before its comment is free-field; otherwise it is fixed-field: field 1 in
//   columns 1-8, data fields of 8 (small field) or 16 (large field) columns up to column 72, field 10
//   in columns 73-80, and anything beyond column 80 ignored (as Nastran does).
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace seflex::io::nastran {

inline constexpr std::size_t kMaxLineLength = 65536;

/// The whole content of a file with tabs expanded. Throws InputError "<from>: cannot read <path> (...)".
std::string load_text(const std::filesystem::path& path, const std::string& from);

/// Expand tabs to 8-column stops, line by line.
void expand_tabs(std::string& text);

struct Line {
  std::string_view text;      ///< without comment and line end; trailing blanks removed
  std::uint32_t number = 0;   ///< 1-based
  bool free = false;          ///< has a comma: free-field
  bool blank() const { return text.empty(); }
};

/// Iterates the lines of one file's text; one line of push-back for look-ahead.
class LineCursor {
 public:
  LineCursor(std::string_view text, const std::string* file_name) : text_(text), file_name_(file_name) {}
  /// Next line (comments and blank lines included as blank lines); false at the end of the text.
  bool next(Line& line);
  /// Make `line` the next one next() returns.
  void push_back(const Line& line) {
    pushed_ = line;
    has_pushed_ = true;
  }
  /// Raw text of the line that next() last returned, comment included (INCLUDE file names, TITLE).
  std::string_view last_raw() const { return last_raw_; }
  const std::string& file_name() const { return *file_name_; }

 private:
  std::string_view text_;
  const std::string* file_name_;
  std::size_t pos_ = 0;
  std::uint32_t number_ = 0;
  Line pushed_;
  bool has_pushed_ = false;
  std::string_view last_raw_;
};

/// Fixed-format line: field 1, `n` data fields (8 small field, 4 large field) and field 10, trimmed.
void split_fixed(std::string_view line, std::size_t n, std::string_view& field1, std::string_view* data,
                 std::string_view& field10);

/// Free-field line split at commas, trimmed. Writes at most `cap` fields (field 1 first) and returns
/// how many the line has (which may exceed cap).
std::size_t split_free(std::string_view line, std::string_view* out, std::size_t cap);

/// s without leading and trailing blanks.
std::string_view trim(std::string_view s);

/// Upper-case copy of s (ASCII).
std::string upper(std::string_view s);

}  // namespace seflex::io::nastran
