// seflex's reader of gmsh's MSH files (gmsh_mesh.hpp: read_msh). The layouts are those of gmsh's
// reference manual ("MSH file format"; 4.0 as in gmsh 4.0's manual, which gmsh 4.8 still reads in
// text). A text file is read record by record, one record per line as gmsh writes them (blank lines
// between records are allowed); a binary file's numbers are read in the byte order its $MeshFormat
// declares. Nothing is allocated for a count before the count is checked against the bytes left.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "seflex/common/error.hpp"
#include "seflex/io/gmsh_mesh.hpp"
#include "seflex/io/nastran_number.hpp"

namespace seflex::io::gmsh {
namespace {

enum class Version { V2, V40, V41 };

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

using nastran::quote_field;

/// "1 node", "2 nodes", "1 element of 3 ints": `what` is the plural; its first word loses its 's' for 1.
std::string plural(std::uint64_t n, std::string what) {
  const std::size_t end = std::min(what.find(' '), what.size());
  if (n == 1 && end > 0 && what[end - 1] == 's') what.erase(end - 1, 1);
  return std::to_string(n) + " " + what;
}

/// A line of the file: its text (without the end of line), number and first byte.
struct Line {
  std::string_view text;
  int number = 0;          ///< 1-based line number
  std::size_t offset = 0;  ///< of its first byte in the file
};

/// What a record or number is, for messages: "node block 3 of 18: node 7 of 40" (built only when
/// an error needs it: the readers call this for every node and element).
struct What {
  std::string_view base;       ///< e.g. "node block 3 of 18"; may be empty
  const char* item = nullptr;  ///< e.g. "node"; none: base alone
  std::uint64_t index = 0, count = 0;
  std::string str() const {
    std::string s(base);
    if (item)
      s += (s.empty() ? "" : ": ") + std::string(item) + " " + std::to_string(index + 1) +
           (count ? " of " + std::to_string(count) : "");
    return s;
  }
};

/// The node tags of $Nodes, looked up for every element node (a table when the tags are dense).
class NodeSet {
 public:
  explicit NodeSet(const std::vector<std::size_t>& tags) {
    std::size_t max_tag = 0;
    for (const std::size_t t : tags) max_tag = std::max(max_tag, t);
    dense_ = max_tag <= 4 * tags.size() + 1024;  // tags.size() is bounded by the file's size
    if (dense_) {
      present_.assign(max_tag + 1, 0);
      for (const std::size_t t : tags) {
        if (present_[t] && !duplicate_) duplicate_ = t;
        present_[t] = 1;
      }
    } else {
      sorted_ = tags;
      std::sort(sorted_.begin(), sorted_.end());
      if (const auto it = std::adjacent_find(sorted_.begin(), sorted_.end()); it != sorted_.end()) duplicate_ = *it;
    }
  }
  /// A tag that occurs twice, if any.
  const std::optional<std::size_t>& duplicate() const { return duplicate_; }
  bool contains(std::size_t tag) const {
    if (dense_) return tag < present_.size() && present_[tag];
    return std::binary_search(sorted_.begin(), sorted_.end(), tag);
  }

 private:
  bool dense_ = true;
  std::vector<char> present_;
  std::vector<std::size_t> sorted_;
  std::optional<std::size_t> duplicate_;
};

/// The elements of one type on one entity, in the order read (with their tags in format 2, where gmsh
/// orders them by tag).
struct Collected {
  const ElementType* type = nullptr;
  std::vector<std::size_t> nodes;
  std::vector<std::size_t> tags;
};

struct Entity {
  bool declared = false;            ///< in $Entities, or a $Nodes block's entity
  std::vector<int> physicals;       ///< physical tags, |tag|, unsorted
  std::map<int, Collected> blocks;  ///< by element type
};

class Reader {
 public:
  Reader(std::string_view bytes, std::string file) : s_(bytes), file_(std::move(file)) {}

  MeshData run() {
    read_format();
    Line line;
    while (next_line(line)) {
      const std::string_view t = trim(line.text);
      if (t.empty()) continue;
      if (t[0] != '$')
        fail_line(line, quote_field(t) + " is not a section header; expected a line $Name (or the end of the file)");
      const std::string name(t.substr(1));
      section_ = "$" + name;
      if (name == "PhysicalNames") {
        physical_names();
      } else if (name == "Entities") {
        entities();
      } else if (name == "Nodes") {
        nodes();
      } else if (name == "Elements") {
        elements();
      } else if (name == "PartitionedEntities") {
        fail_line(line,
                  "a partitioned mesh, which seflex does not read; expected the whole mesh in one part (save it "
                  "unpartitioned)");
      } else if (name == "ParametricNodes") {
        fail_line(line,
                  "nodes with parametric coordinates (MSH 2), which seflex does not read; expected $Nodes "
                  "(save without Mesh.SaveParametric)");
      } else if (name == "MeshFormat") {
        fail_line(line, "a second $MeshFormat; expected one mesh per file");
      } else if (name.rfind("End", 0) == 0) {
        section_.clear();
        fail_line(line, quote_field(t) + " outside its section; expected a section header");
      } else {
        skip_section(line, name);
      }
      section_.clear();
    }
    if (!nodes_read_)
      fail_at(s_.size(), "the file ends without a $Nodes section; expected a mesh: $Nodes and $Elements");
    if (!elements_read_)
      fail_at(s_.size(), "the file ends without an $Elements section; expected a mesh: $Nodes and $Elements");
    return finish();
  }

 private:
  // ---- errors -------------------------------------------------------------------------------------
  /// "FILE:LINE: $Section: " in a text file, "FILE: byte OFFSET: $Section: " in a binary one.
  std::string where(int line, std::size_t offset) const {
    std::string w = binary_ ? file_ + ": byte " + std::to_string(offset) : file_ + ":" + std::to_string(line);
    return w + ": " + (section_.empty() ? std::string() : section_ + ": ");
  }
  [[noreturn]] void fail_line(const Line& line, const std::string& message) const {
    throw InputError(where(line.number, line.offset) + message);
  }
  /// At byte `offset` of a binary file; in a text file at the line read last.
  [[noreturn]] void fail_at(std::size_t offset, const std::string& message) const {
    throw InputError(where(std::max(1, line_ - 1), offset) + message);
  }
  /// Refuses `count` items of at least `bytes_each` bytes before anything is allocated for them.
  /// `prefix` names the record holding the count ("" for the section's).
  void check_count(std::uint64_t count, std::size_t bytes_each, const std::string& what, std::size_t at, int line,
                   const std::string& prefix = "") const {
    const std::size_t left = s_.size() - pos_;
    if (count > left / bytes_each)
      throw InputError(where(line, at) + (prefix.empty() ? prefix : prefix + ": ") + plural(count, what) +
                       ", but the " + std::to_string(left) + " bytes left in the file hold at most " +
                       std::to_string(left / bytes_each) +
                       "; expected a count that matches the data (a truncated or corrupted file?)");
  }

  // ---- text ---------------------------------------------------------------------------------------
  /// The next line (without its end of line); false at the end of the file.
  bool next_line(Line& line) {
    if (pos_ >= s_.size()) return false;
    const std::size_t eol = s_.find('\n', pos_);
    const std::size_t end = eol == std::string_view::npos ? s_.size() : eol;
    line.text = s_.substr(pos_, end - pos_);
    line.number = line_;
    line.offset = pos_;
    pos_ = eol == std::string_view::npos ? s_.size() : eol + 1;
    ++line_;
    return true;
  }
  /// The next line that is not blank; `what` is what it must hold (for the message at the end of the file).
  Line record(const What& what) {
    Line line;
    while (next_line(line))
      if (!trim(line.text).empty()) return line;
    throw InputError(where(line_, s_.size()) + "the file ends; expected " + what.str());
  }
  /// The line `$End<name>` after a section's data (after blank lines, and in a binary file after the
  /// end of the line its data ends on).
  void end_of_section(const std::string& name) {
    const std::string end = "$End" + name;
    const Line line = record({end});
    if (trim(line.text) != end)
      fail_line(line, quote_field(trim(line.text)) + " where the section should end; expected " + end +
                          " after the data the section declares (a count that does not match the data?)");
  }
  /// A section seflex does not need: skipped to its $End line.
  void skip_section(const Line& header, const std::string& name) {
    const std::string end = "$End" + name;
    for (std::size_t at = pos_;;) {
      const std::size_t found = s_.find(end, at);
      if (found == std::string_view::npos)
        fail_line(header, "no line " + end + " after it; expected every section to end with its $End line");
      std::size_t eol = s_.find('\n', found);
      if (eol == std::string_view::npos) eol = s_.size();
      if ((found == 0 || s_[found - 1] == '\n') &&
          trim(s_.substr(found + end.size(), eol - found - end.size())).empty()) {
        line_ += static_cast<int>(
            std::count(s_.begin() + static_cast<long>(pos_), s_.begin() + static_cast<long>(eol), '\n'));
        pos_ = eol;
        Line rest;
        next_line(rest);
        return;
      }
      at = found + 1;
    }
  }

  /// The numbers of one text line, read in order; a message names the record and its layout.
  class Fields {
   public:
    Fields(const Reader& r, const Line& line, const What& what, const char* layout)
        : r_(r), line_(line), what_(what), layout_(layout) {}
    template <class T>
    T integer(const char* name) {
      const std::string_view t = token(name);
      std::string_view digits = t;
      if (digits.size() > 1 && digits[0] == '+') digits.remove_prefix(1);
      T v{};
      const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
      if (ec != std::errc() || end != digits.data() + digits.size())
        fail(std::string(name) + " is " + quote_field(t) + "; expected " +
             (std::is_signed_v<T> ? "an integer" : "a whole number >= 0") +
             (ec == std::errc::result_out_of_range ? " in range" : ""));
      return v;
    }
    double real(const char* name) {
      const std::string_view t = token(name);
      std::string_view digits = t;
      if (digits.size() > 1 && digits[0] == '+') digits.remove_prefix(1);
      double v = 0;
      const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
      if (ec != std::errc() || end != digits.data() + digits.size() || !std::isfinite(v))
        fail(std::string(name) + " is " + quote_field(t) + "; expected a finite real number");
      return v;
    }
    /// The rest of the line, trimmed.
    std::string_view rest() {
      const std::string_view r = trim(line_.text.substr(std::min(at_, line_.text.size())));
      at_ = line_.text.size();
      return r;
    }
    /// Refuses more on the line.
    void end() {
      skip_blanks();
      if (at_ < line_.text.size())
        fail("more on the line after " + plural(count_, "numbers") + " (" + quote_field(line_.text.substr(at_)) +
             "); expected '" + layout_ + "'");
    }
    /// Refuses `n` items of at least 2 bytes each (a number and a blank) that the line cannot hold.
    void check_count(std::uint64_t n, const char* items) {
      if (n > line_.text.size() / 2)
        fail(plural(n, items) + ", but the line has " + std::to_string(line_.text.size()) +
             " bytes; expected them on the line ('" + layout_ + "')");
    }
    [[noreturn]] void fail(const std::string& problem) const {
      const std::string w = what_.str();
      r_.fail_line(line_, (w.empty() ? std::string() : w + ": ") + problem);
    }

   private:
    void skip_blanks() {
      while (at_ < line_.text.size() && is_blank(line_.text[at_])) ++at_;
    }
    std::string_view token(const char* name) {
      skip_blanks();
      const std::size_t begin = at_;
      while (at_ < line_.text.size() && !is_blank(line_.text[at_])) ++at_;
      if (begin == at_)
        fail("the line ends after " + plural(count_, "numbers") + ", before " + name + "; expected '" + layout_ + "'");
      ++count_;
      return line_.text.substr(begin, at_ - begin);
    }
    const Reader& r_;
    Line line_;
    What what_;
    const char* layout_;
    std::size_t at_ = 0;
    std::uint64_t count_ = 0;
  };

  // ---- binary -------------------------------------------------------------------------------------
  template <class T>
  static T swapped(T v) {
    if constexpr (sizeof(T) == 4) {
      std::uint32_t u;
      std::memcpy(&u, &v, 4);
      u = __builtin_bswap32(u);
      std::memcpy(&v, &u, 4);
    } else {
      std::uint64_t u;
      std::memcpy(&u, &v, 8);
      u = __builtin_bswap64(u);
      std::memcpy(&v, &u, 8);
    }
    return v;
  }
  /// `n` numbers of type T (std::int32_t, std::uint64_t or double), in the file's byte order.
  template <class T>
  void binary(T* out, std::size_t n, const What& what) {
    if (n == 0) return;  // `out` may be the null data() of an empty vector
    if (n > (s_.size() - pos_) / sizeof(T))
      fail_at(pos_, "the file ends inside " + what.str() + " (" + plural(n, "numbers") + " of " +
                        std::to_string(sizeof(T)) + " bytes, " + std::to_string(s_.size() - pos_) +
                        " bytes left); expected the data the section declares");
    std::memcpy(out, s_.data() + pos_, n * sizeof(T));
    if (swap_)
      for (std::size_t i = 0; i < n; ++i) out[i] = swapped(out[i]);
    pos_ += n * sizeof(T);
  }
  template <class T>
  T binary(const What& what) {
    T v{};
    binary(&v, 1, what);
    return v;
  }
  /// A 64-bit count of items of at least `bytes_each` bytes, checked against the bytes left.
  std::uint64_t binary_count(const What& what, const char* items, std::size_t bytes_each) {
    const std::size_t at = pos_;
    const auto n = binary<std::uint64_t>(what);
    check_count(n, bytes_each, items, at, line_, what.str());
    return n;
  }
  void check_finite(const double* x, std::size_t at, const What& what) const {
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(x[i]))
        fail_at(at + 8 * static_cast<std::size_t>(i),
                what.str() + ": a coordinate is " + std::to_string(x[i]) + "; expected a finite real number");
  }

  // ---- $MeshFormat --------------------------------------------------------------------------------
  void read_format() {
    Line first;
    if (!next_line(first))
      fail_at(0, "the file is empty; expected a gmsh mesh (MSH format 2 or 4), whose first line is $MeshFormat");
    if (trim(first.text) != "$MeshFormat")
      fail_line(first, "the file starts with " + quote_field(first.text) +
                           "; expected a gmsh mesh (MSH format 2 or 4), whose first line is $MeshFormat (a gmsh script "
                           "must be named .geo)");
    section_ = "$MeshFormat";
    const Line line = record({"the format line 'version file-type data-size'"});
    Fields f(*this, line, {}, "version file-type data-size");
    const double version = f.real("version");
    const int file_type = f.integer<int>("file-type");
    const int data_size = f.integer<int>("data-size");
    f.end();
    if (version == 2.1 || version == 2.2) {
      version_ = Version::V2;
    } else if (version == 4.0) {
      version_ = Version::V40;
    } else if (version == 4.1) {
      version_ = Version::V41;
    } else {
      f.fail("version " + std::string(trim(line.text.substr(0, line.text.find_first_of(" \t")))) +
             ", which seflex does not read; expected 2.2, 4.1 or 4.0 (gmsh -format msh22 or msh41)");
    }
    if (file_type != 0 && file_type != 1)
      f.fail("file-type " + std::to_string(file_type) + "; expected 0 (text) or 1 (binary)");
    if (file_type == 1 && data_size != 8)
      f.fail("data-size " + std::to_string(data_size) +
             "; expected 8 in a binary file (the size of a double and of a 64-bit size_t)");
    if (file_type == 1 && version_ == Version::V40)
      f.fail(
          "a binary MSH 4.0 file, which seflex does not read (gmsh reads 4.0 as text only); expected text, or MSH 4.1 "
          "(gmsh -format msh41)");
    if (file_type == 1) {
      binary_ = true;
      if (s_.size() - pos_ < 4)
        fail_at(pos_, "the file ends before the byte-order integer; expected the integer 1 in 4 bytes");
      std::uint32_t one = 0;
      std::memcpy(&one, s_.data() + pos_, 4);
      if (one == 1u) {
        swap_ = false;
      } else if (one == 1u << 24) {
        swap_ = true;
      } else {
        fail_at(pos_, "the byte-order integer is " + quote_field(s_.substr(pos_, 4)) +
                          "; expected the integer 1, little-endian (01 00 00 00) or big-endian (00 00 00 01)");
      }
      pos_ += 4;
    }
    end_of_section("MeshFormat");
    section_.clear();
  }

  // ---- $PhysicalNames -----------------------------------------------------------------------------
  void physical_names() {
    if (names_read_) fail_at(pos_, "a second $PhysicalNames section; expected one");
    names_read_ = true;
    const Line count_line = record({"the number of physical names"});
    Fields c(*this, count_line, {"the count line"}, "numPhysicalNames");
    const auto n = c.integer<std::uint64_t>("numPhysicalNames");
    c.end();
    check_count(n, 7, "physical names", count_line.offset, count_line.number);  // '0 1 ""' and its end of line
    for (std::uint64_t i = 0; i < n; ++i) {
      const What what{{}, "physical name", i, n};
      const Line line = record(what);
      Fields f(*this, line, what, "dimension physicalTag \"name\"");
      const int dim = f.integer<int>("dimension");
      const int tag = f.integer<int>("physicalTag");
      const std::string_view name = f.rest();
      if (dim < 0 || dim > 3)
        f.fail("physical group " + std::to_string(tag) + " has dimension " + std::to_string(dim) +
               "; expected 0 (point), 1 (curve), 2 (surface) or 3 (volume)");
      if (name.size() < 2 || name.front() != '"' || name.back() != '"' ||
          name.substr(1, name.size() - 2).find('"') != std::string_view::npos)
        f.fail("the name is " + quote_field(name) + "; expected a name in double quotes");
      if (!names_.emplace(std::make_pair(dim, tag), std::string(name.substr(1, name.size() - 2))).second)
        f.fail("physical " + std::string(dimension_name(dim)) + " " + std::to_string(tag) +
               " is named twice; expected one name per group");
    }
    end_of_section("PhysicalNames");
  }

  // ---- $Entities (format 4) -----------------------------------------------------------------------
  void entities() {
    if (version_ == Version::V2) fail_at(pos_, "an $Entities section in an MSH 2 file; expected it in format 4 only");
    if (entities_read_) fail_at(pos_, "a second $Entities section; expected one");
    entities_read_ = true;
    std::uint64_t count[4] = {0, 0, 0, 0};
    const std::size_t at = pos_;
    int line = line_;
    if (binary_) {
      binary(count, 4, {"the four entity counts"});
    } else {
      const Line l = record({"the entity counts"});
      line = l.number;
      Fields f(*this, l, {"the count line"}, "numPoints numCurves numSurfaces numVolumes");
      for (auto& c : count) c = f.integer<std::uint64_t>("an entity count");
      f.end();
    }
    for (int d = 0; d < 4; ++d) {
      // at least: text 'tag x y z n' (5 numbers, 10 bytes); binary a tag, 3 or 6 doubles and 1 or 2 counts
      check_count(count[d], binary_ ? (d == 0 ? 36 : 68) : 10, std::string(dimension_name(d)) + " entities", at, line);
      for (std::uint64_t i = 0; i < count[d]; ++i) entity(d, {{}, entity_names[d], i, count[d]});
    }
    end_of_section("Entities");
  }
  static constexpr const char* entity_names[4] = {"point", "curve", "surface", "volume"};
  void entity(int dim, const What& what) {
    const int coordinates = dim == 0 && version_ == Version::V41 ? 3 : 6;  // a point's position, or a bounding box
    int tag = 0;
    std::vector<int> physicals;
    const std::size_t at = pos_;
    int line = line_;
    if (binary_) {
      tag = binary<std::int32_t>(what);
      double box[6];
      binary(box, static_cast<std::size_t>(coordinates), what);
      physicals.resize(binary_count(what, "physical tags", 4));
      binary(physicals.data(), physicals.size(), what);
      if (dim > 0) {
        std::vector<int> bounding(binary_count(what, "bounding entities", 4));
        binary(bounding.data(), bounding.size(), what);
      }
    } else {
      const Line l = record(what);
      line = l.number;
      Fields f(*this, l, what,
               dim > 0 ? "tag minX minY minZ maxX maxY maxZ numPhysicalTags physicalTag... numBounding tag..."
               : coordinates == 3 ? "pointTag X Y Z numPhysicalTags physicalTag..."
                                  : "pointTag minX minY minZ maxX maxY maxZ numPhysicalTags physicalTag...");
      tag = f.integer<int>("the entity's tag");
      for (int k = 0; k < coordinates; ++k) f.real("a coordinate");
      const auto n = f.integer<std::uint64_t>("numPhysicalTags");
      f.check_count(n, "physical tags");
      for (std::uint64_t k = 0; k < n; ++k) physicals.push_back(f.integer<int>("a physical tag"));
      if (dim > 0) {
        const auto b = f.integer<std::uint64_t>("the number of bounding entities");
        f.check_count(b, "bounding entities");
        for (std::uint64_t k = 0; k < b; ++k) f.integer<int>("a bounding entity");
      }
      f.end();
    }
    Entity& e = entities_[{dim, tag}];
    if (e.declared)
      throw InputError(where(line, at) + what.str() + ": " + dimension_name(dim) + " " + std::to_string(tag) +
                       " is declared twice; expected each entity once");
    e.declared = true;
    for (const int p : physicals) {
      if (p == std::numeric_limits<int>::min())
        throw InputError(where(line, at) + what.str() + ": physical tag " + std::to_string(p) +
                         "; expected a tag in range");
      e.physicals.push_back(std::abs(p));  // a negative tag marks a reversed entity (gmsh's convention)
    }
  }

  // ---- $Nodes -------------------------------------------------------------------------------------
  void nodes() {
    if (nodes_read_) fail_at(pos_, "a second $Nodes section; expected one");
    nodes_read_ = true;
    if (version_ == Version::V2) {
      nodes_v2();
    } else {
      nodes_v4();
    }
    node_set_.emplace(tags_);
    if (const auto& d = node_set_->duplicate())
      fail_at(pos_, "node " + std::to_string(*d) + " is defined twice; expected each node tag once");
    end_of_section("Nodes");
  }
  void nodes_v2() {
    const Line count_line = record({"the number of nodes"});
    Fields c(*this, count_line, {"the count line"}, "number-of-nodes");
    const auto n = c.integer<std::uint64_t>("number-of-nodes");
    c.end();
    check_count(n, binary_ ? 28 : 8, "nodes", count_line.offset, count_line.number);  // binary: an int and 3 doubles
    tags_.resize(n);
    coords_.resize(3 * n);
    for (std::uint64_t i = 0; i < n; ++i) {
      const What what{{}, "node", i, n};
      if (binary_) {
        const std::size_t at = pos_;
        const std::int32_t tag = binary<std::int32_t>(what);
        if (tag < 0) fail_at(at, what.str() + ": node-number " + std::to_string(tag) + "; expected a node number >= 0");
        tags_[i] = static_cast<std::size_t>(tag);
        binary(&coords_[3 * i], 3, what);
        check_finite(&coords_[3 * i], at + 4, what);
      } else {
        Fields f(*this, record(what), what, "node-number x y z");
        tags_[i] = f.integer<std::uint64_t>("node-number");
        for (int k = 0; k < 3; ++k) coords_[3 * i + k] = f.real("a coordinate");
        f.end();
      }
    }
  }
  /// The header of a format 4 $Nodes or $Elements: the number of blocks and of nodes or elements.
  std::pair<std::uint64_t, std::uint64_t> counts_v4(const char* items, std::size_t block_bytes,
                                                    std::size_t item_bytes) {
    std::uint64_t head[4] = {0, 0, 0, 0};
    const std::size_t at = pos_;
    int line = line_;
    const std::string plural_items = std::string(items) + "s";
    if (binary_) {
      binary(head, 4, {"the section's four counts"});
    } else {
      const bool v41 = version_ == Version::V41;
      const Line l = record({"the section's counts"});
      line = l.number;
      Fields f(*this, l, {"the count line"},
               items[0] == 'n'
                   ? (v41 ? "numEntityBlocks numNodes minNodeTag maxNodeTag" : "numEntityBlocks numNodes")
                   : (v41 ? "numEntityBlocks numElements minElementTag maxElementTag" : "numEntityBlocks numElements"));
      for (int k = 0; k < (v41 ? 4 : 2); ++k)
        head[k] = f.integer<std::uint64_t>(k == 0 ? "numEntityBlocks" : k == 1 ? "the count" : "a tag");
      f.end();
    }
    check_count(head[0], block_bytes, std::string(items) + " blocks", at, line);
    check_count(head[1], item_bytes, plural_items, at, line);
    return {head[0], head[1]};
  }
  /// A format 4 block header: entity dimension and tag, the third number, the count.
  struct BlockHead {
    int dim = 0, tag = 0, third = 0;
    std::uint64_t count = 0;
    std::size_t at = 0;
  };
  BlockHead block_head(const What& what, const char* layout41, const char* layout40, const char* third,
                       const char* count) {
    BlockHead h;
    h.at = pos_;
    if (binary_) {
      std::int32_t head[3];
      binary(head, 3, what);
      h.dim = head[0], h.tag = head[1], h.third = head[2];
      h.count = binary<std::uint64_t>(what);
    } else {
      const bool v41 = version_ == Version::V41;
      const Line l = record(what);
      h.at = l.offset;
      Fields f(*this, l, what, v41 ? layout41 : layout40);
      if (v41) {
        h.dim = f.integer<int>("entityDim");
        h.tag = f.integer<int>("entityTag");
      } else {
        h.tag = f.integer<int>("entityTag");
        h.dim = f.integer<int>("entityDim");
      }
      h.third = f.integer<int>(third);
      h.count = f.integer<std::uint64_t>(count);
      f.end();
    }
    if (h.dim < 0 || h.dim > 3)
      fail_at(h.at, what.str() + ": entity dimension " + std::to_string(h.dim) + "; expected 0, 1, 2 or 3");
    return h;
  }
  void nodes_v4() {
    const auto [blocks, total] = counts_v4("node", binary_ ? 20 : 8, binary_ ? 32 : 8);  // a tag and x y z at least
    tags_.reserve(total);
    coords_.reserve(3 * total);
    std::vector<double> x;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      const std::string block = "node block " + std::to_string(b + 1) + " of " + std::to_string(blocks);
      const BlockHead h = block_head({block}, "entityDim entityTag parametric numNodesInBlock",
                                     "entityTag entityDim parametric numNodes", "parametric", "numNodesInBlock");
      if (h.third != 0 && h.third != 1)
        fail_at(h.at, block + ": parametric is " + std::to_string(h.third) + "; expected 0 or 1");
      const std::uint64_t n = h.count;
      if (n > total - tags_.size())
        fail_at(h.at, block + " holds " + plural(n, "nodes") + ", but the section declares " + std::to_string(total) +
                          " in all, " + std::to_string(tags_.size()) +
                          " of them in the blocks before; expected the blocks to hold the section's count");
      entities_[{h.dim, h.tag}].declared = true;
      const std::size_t per_node = 3 + (h.third ? static_cast<std::size_t>(h.dim) : 0);  // x y z and u, v, w
      const std::size_t first = tags_.size();
      if (binary_) {
        tags_.resize(first + n);
        binary(tags_.data() + first, n, {block, "node tag"});
        check_count(n, 8 * per_node, "nodes' coordinates", pos_, line_, block);
        x.resize(n * per_node);
        const std::size_t x_at = pos_;
        binary(x.data(), x.size(), {block, "coordinates"});
        for (std::size_t i = 0; i < n; ++i) {
          const double* p = &x[i * per_node];
          check_finite(p, x_at + 8 * i * per_node, {block, "node", i, n});
          coords_.insert(coords_.end(), p, p + 3);
        }
      } else {
        if (version_ == Version::V41)
          for (std::uint64_t i = 0; i < n; ++i) {
            const What what{block, "node tag", i, n};
            Fields f(*this, record(what), what, "nodeTag");
            tags_.push_back(f.integer<std::uint64_t>("nodeTag"));
            f.end();
          }
        for (std::uint64_t i = 0; i < n; ++i) {
          const What what{block, "node", i, n};
          const bool v40 = version_ == Version::V40;
          Fields f(*this, record(what), what, v40 ? "nodeTag x y z [u v w]" : "x y z [u v w]");
          if (v40) tags_.push_back(f.integer<std::uint64_t>("nodeTag"));
          for (std::size_t k = 0; k < per_node; ++k) {
            const double v = f.real(k < 3 ? "a coordinate" : "a parametric coordinate");
            if (k < 3) coords_.push_back(v);
          }
          f.end();
        }
      }
    }
    if (tags_.size() != total)
      fail_at(pos_, "the blocks hold " + plural(tags_.size(), "nodes") + ", but the section declares " +
                        std::to_string(total) + "; expected the blocks to hold the section's count");
  }

  // ---- $Elements ----------------------------------------------------------------------------------
  void elements() {
    if (elements_read_) fail_at(pos_, "a second $Elements section; expected one");
    if (!nodes_read_) fail_at(pos_, "the elements come before $Nodes; expected $Nodes first");
    elements_read_ = true;
    if (version_ == Version::V2) {
      elements_v2();
    } else {
      elements_v4();
    }
    end_of_section("Elements");
  }
  const ElementType& element_type(int type, std::size_t at, int line, const What& what) const {
    const ElementType* t = find_element_type(type);
    if (!t)
      throw InputError(
          where(line, at) + what.str() + ": element type " + std::to_string(type) +
          ", which seflex does not read; expected a gmsh element type with a fixed number of nodes (1 = 2-node line, "
          "2 = 3-node triangle, 3 = 4-node quadrangle, 15 = point, ...: gmsh reference manual, MSH file format)");
    return *t;
  }
  std::string unknown_node(std::uint64_t element, std::uint64_t node) const {
    return "element " + std::to_string(element) + " refers to node " + std::to_string(node) +
           ", which is not in $Nodes; expected the tag of a node the file defines";
  }
  void elements_v4() {
    const auto [blocks, total] = counts_v4("element", binary_ ? 20 : 8, binary_ ? 16 : 4);  // a tag and a node at least
    std::uint64_t read = 0;
    std::vector<std::uint64_t> data;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      const std::string block = "element block " + std::to_string(b + 1) + " of " + std::to_string(blocks);
      const BlockHead h =
          block_head({block}, "entityDim entityTag elementType numElementsInBlock",
                     "entityTag entityDim elementType numElements", "elementType", "numElementsInBlock");
      const int head_line = binary_ ? line_ : line_ - 1;
      const ElementType& t = element_type(h.third, h.at, head_line, {block});
      if (h.dim != t.dim)
        throw InputError(where(head_line, h.at) + block + ": '" + std::string(t.name) + "' elements (dimension " +
                         std::to_string(t.dim) + ") on a " + dimension_name(h.dim) + " (dimension " +
                         std::to_string(h.dim) + "); expected elements of the entity's dimension");
      const auto it = entities_.find({h.dim, h.tag});
      if (it == entities_.end() || !it->second.declared)
        throw InputError(
            where(head_line, h.at) + block + ": " + dimension_name(h.dim) + " " + std::to_string(h.tag) +
            " is neither in $Entities nor the entity of a node block; expected the entity its nodes are on");
      const std::uint64_t n = h.count;
      if (n > total - read)
        throw InputError(where(head_line, h.at) + block + " holds " + plural(n, "elements") +
                         ", but the section declares " + std::to_string(total) + " in all, " + std::to_string(read) +
                         " of them in the blocks before; expected the blocks to hold the section's count");
      read += n;
      Collected& c = it->second.blocks[h.third];
      c.type = &t;
      const std::size_t per = static_cast<std::size_t>(t.nodes);
      check_count(n, binary_ ? 8 * (per + 1) : 2 * (per + 1), "elements of " + std::to_string(per) + " nodes", h.at,
                  head_line, block);
      const std::size_t first = c.nodes.size();
      c.nodes.resize(first + n * per);
      std::size_t* out = c.nodes.data() + first;
      if (binary_) {
        const std::size_t data_at = pos_;
        data.resize(n * (per + 1));
        binary(data.data(), data.size(), {block, "element data"});
        for (std::size_t e = 0; e < n; ++e)
          for (std::size_t k = 0; k < per; ++k) {
            const std::uint64_t node = data[e * (per + 1) + 1 + k];
            if (!node_set_->contains(node))
              fail_at(data_at + 8 * (e * (per + 1) + 1 + k), block + ": " + unknown_node(data[e * (per + 1)], node));
            *out++ = node;
          }
      } else {
        for (std::uint64_t e = 0; e < n; ++e) {
          const What what{block, "element", e, n};
          Fields f(*this, record(what), what, "elementTag nodeTag...");
          const auto element = f.integer<std::uint64_t>("elementTag");
          for (std::size_t k = 0; k < per; ++k) {
            const auto node = f.integer<std::uint64_t>("a node tag");
            if (!node_set_->contains(node)) f.fail(unknown_node(element, node));
            *out++ = node;
          }
          f.end();
        }
      }
    }
    if (read != total)
      fail_at(pos_, "the blocks hold " + plural(read, "elements") + ", but the section declares " +
                        std::to_string(total) + "; expected the blocks to hold the section's count");
  }

  /// Format 2: one element with its tags (physical group, elementary entity, partitions...).
  void element_v2(std::uint64_t number, const ElementType& t, const std::int64_t* tags, std::size_t ntags,
                  const std::size_t* nodes, std::size_t at, int line, const What& what) {
    const std::int64_t physical = ntags > 0 ? tags[0] : 0, elementary = ntags > 1 ? tags[1] : 0;
    if (elementary < 0 || elementary > std::numeric_limits<int>::max())
      throw InputError(where(line, at) + what.str() + ": elementary tag " + std::to_string(elementary) +
                       "; expected the tag (>= 0) of the element's entity");
    if (physical < -std::numeric_limits<int>::max() || physical > std::numeric_limits<int>::max())
      throw InputError(where(line, at) + what.str() + ": physical tag " + std::to_string(physical) +
                       "; expected a tag in range");
    const int group = static_cast<int>(std::abs(physical));
    // The entity and block of the element before, looked up again only when they change.
    if (!last_ || last_key_ != std::make_tuple(t.dim, static_cast<int>(elementary), t.type)) {
      last_entity_ = &entities_[{t.dim, static_cast<int>(elementary)}];
      Collected& b = last_entity_->blocks[t.type];
      b.type = &t;
      last_key_ = std::make_tuple(t.dim, static_cast<int>(elementary), t.type);
      if (&b != last_) last_group_ = -1;  // no copy of an element of another block
      last_ = &b;
    }
    Entity& e = *last_entity_;
    if (group != 0 && std::find(e.physicals.begin(), e.physicals.end(), group) == e.physicals.end())
      e.physicals.push_back(group);
    Collected& c = *last_;
    const std::size_t per = static_cast<std::size_t>(t.nodes);
    // gmsh writes an element once for each physical group of its entity, the copies one after the
    // other with the next numbers: the same element in another group, not a new one.
    const bool copy = last_group_ >= 0 && group != last_group_ && !c.tags.empty() && number == c.tags.back() + 1 &&
                      std::equal(nodes, nodes + per, c.nodes.end() - static_cast<long>(per));
    last_group_ = group;
    if (copy) {
      c.tags.back() = number;  // a third copy follows this one's number
      return;
    }
    c.tags.push_back(number);
    c.nodes.insert(c.nodes.end(), nodes, nodes + per);
  }
  void elements_v2() {
    const Line count_line = record({"the number of elements"});
    Fields c(*this, count_line, {"the count line"}, "number-of-elements");
    const auto total = c.integer<std::uint64_t>("number-of-elements");
    c.end();
    check_count(total, 8, "elements", count_line.offset,
                count_line.number);  // text 'n t 0 v', binary a number and a node
    std::vector<std::int64_t> tags;
    std::vector<std::size_t> nodes;
    if (!binary_) {
      for (std::uint64_t i = 0; i < total; ++i) {
        const What what{{}, "element", i, total};
        const Line line = record(what);
        Fields f(*this, line, what, "elm-number elm-type number-of-tags tag... node-number...");
        const auto number = f.integer<std::uint64_t>("elm-number");
        const ElementType& t = element_type(f.integer<int>("elm-type"), line.offset, line.number, what);
        const auto ntags = f.integer<std::uint64_t>("number-of-tags");
        f.check_count(ntags, "tags");
        tags.resize(ntags);
        for (auto& tag : tags) tag = f.integer<std::int64_t>("a tag");
        nodes.resize(static_cast<std::size_t>(t.nodes));
        for (auto& node : nodes) {
          node = f.integer<std::uint64_t>("a node-number");
          if (!node_set_->contains(node)) f.fail(unknown_node(number, node));
        }
        f.end();
        element_v2(number, t, tags.data(), tags.size(), nodes.data(), line.offset, line.number, what);
      }
      return;
    }
    std::uint64_t read = 0;
    std::vector<std::int32_t> data;
    for (std::uint64_t block = 0; read < total; ++block) {
      const What what{{}, "element block", block, 0};
      const std::size_t at = pos_;
      std::int32_t head[3];  // elm-type num-elm-follow num-tags
      binary(head, 3, what);
      const ElementType& t = element_type(head[0], at, line_, what);
      if (head[1] <= 0 || static_cast<std::uint64_t>(head[1]) > total - read)
        fail_at(at, what.str() + " holds " + std::to_string(head[1]) + " elements, but the section declares " +
                        std::to_string(total) + " in all, " + std::to_string(read) +
                        " of them in the blocks before; expected 1 to " + std::to_string(total - read));
      if (head[2] < 0)
        fail_at(at, what.str() + ": num-tags is " + std::to_string(head[2]) + "; expected a number of tags >= 0");
      const std::size_t per = 1 + static_cast<std::size_t>(head[2]) + static_cast<std::size_t>(t.nodes);
      const auto n = static_cast<std::size_t>(head[1]);
      if (n > (s_.size() - pos_) / (4 * per))  // (the message is built only when needed: a block per element)
        check_count(n, 4 * per, "elements of " + std::to_string(per) + " ints", at, line_, what.str());
      data.resize(per * n);
      const std::size_t data_at = pos_;
      binary(data.data(), data.size(), what);
      tags.resize(static_cast<std::size_t>(head[2]));
      nodes.resize(static_cast<std::size_t>(t.nodes));
      for (std::size_t e = 0; e < n; ++e) {
        const std::int32_t* d = &data[e * per];
        const std::size_t e_at = data_at + 4 * e * per;
        if (d[0] < 0) fail_at(e_at, what.str() + ": elm-number " + std::to_string(d[0]) + "; expected a number >= 0");
        for (std::size_t k = 0; k < tags.size(); ++k) tags[k] = d[1 + k];
        for (std::size_t k = 0; k < nodes.size(); ++k) {
          const std::int32_t node = d[1 + tags.size() + k];
          if (node < 0 || !node_set_->contains(static_cast<std::size_t>(node)))
            fail_at(
                e_at + 4 * (1 + tags.size() + k),
                what.str() + ": " + unknown_node(static_cast<std::uint64_t>(d[0]), static_cast<std::uint64_t>(node)));
          nodes[k] = static_cast<std::size_t>(node);
        }
        element_v2(static_cast<std::uint64_t>(d[0]), t, tags.data(), tags.size(), nodes.data(), e_at, line_, what);
      }
      read += n;
    }
  }

  // ---- the mesh -----------------------------------------------------------------------------------
  MeshData finish() {
    MeshData m;
    m.file = file_;
    if (version_ == Version::V2) order_by_element_number();
    // physical group (dim, tag) -> its entities, ascending (as gmsh's GModel::getPhysicalGroups)
    std::map<std::pair<int, int>, std::vector<int>> groups;
    std::map<std::pair<int, int>, std::size_t> uses;  // entity -> groups holding it
    for (auto& [key, e] : entities_) {
      std::sort(e.physicals.begin(), e.physicals.end());
      e.physicals.erase(std::unique(e.physicals.begin(), e.physicals.end()), e.physicals.end());
      for (const int p : e.physicals) groups[{key.first, p}].push_back(key.second);
      uses[key] = e.physicals.size();
      for (const auto& [type, c] : e.blocks)
        m.total_elements += c.nodes.size() / static_cast<std::size_t>(c.type->nodes);
    }
    for (auto& [key, ents] : groups) {
      PhysicalGroup g;
      g.dim = key.first;
      g.tag = key.second;
      if (const auto it = names_.find(key); it != names_.end()) g.name = it->second;
      g.entities = std::move(ents);
      for (const int tag : g.entities) {
        Entity& e = entities_.at({g.dim, tag});
        const bool last_use = --uses.at({g.dim, tag}) == 0;
        for (auto& [type, c] : e.blocks) {
          if (c.nodes.empty()) continue;
          ElementBlock b;
          b.type = type;
          b.type_name = std::string(c.type->name);
          b.dim = c.type->dim;
          b.order = c.type->order;
          b.nodes_per_element = c.type->nodes;
          b.entity_tag = tag;
          if (last_use) {
            b.nodes = std::move(c.nodes);
          } else {
            b.nodes = c.nodes;
          }
          g.blocks.push_back(std::move(b));
        }
      }
      m.groups.push_back(std::move(g));
    }
    m.node_tags = std::move(tags_);
    m.coords = std::move(coords_);
    return m;
  }
  /// gmsh keeps the elements of a format 2 file by number: each entity's elements of a type in
  /// ascending order (the file's order when it is so already, as gmsh writes them).
  void order_by_element_number() {
    for (auto& [key, e] : entities_)
      for (auto& block : e.blocks) {
        Collected& c = block.second;  // not a structured binding: clang 14 cannot capture one
        if (std::is_sorted(c.tags.begin(), c.tags.end())) continue;
        const std::size_t per = static_cast<std::size_t>(c.type->nodes);
        std::vector<std::size_t> order(c.tags.size());
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t b) { return c.tags[a] < c.tags[b]; });
        std::vector<std::size_t> nodes;
        nodes.reserve(c.nodes.size());
        for (const std::size_t k : order)
          nodes.insert(nodes.end(), c.nodes.begin() + static_cast<long>(k * per),
                       c.nodes.begin() + static_cast<long>((k + 1) * per));
        c.nodes = std::move(nodes);
      }
  }

  std::string_view s_;
  std::string file_;
  std::size_t pos_ = 0;
  int line_ = 1;  ///< the number of the line at pos_
  std::string section_;
  Version version_ = Version::V41;
  bool binary_ = false, swap_ = false;
  bool names_read_ = false, entities_read_ = false, nodes_read_ = false, elements_read_ = false;
  std::map<std::pair<int, int>, std::string> names_;
  std::map<std::pair<int, int>, Entity> entities_;
  std::vector<std::size_t> tags_;
  std::vector<double> coords_;
  std::optional<NodeSet> node_set_;
  // format 2: the entity and block of the element before (key: dimension, entity, type), its group
  Entity* last_entity_ = nullptr;
  Collected* last_ = nullptr;
  std::tuple<int, int, int> last_key_;
  int last_group_ = -1;
};

}  // namespace

MeshData read_msh_bytes(std::string_view bytes, const std::string& file) { return Reader(bytes, file).run(); }

MeshData read_msh(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(file + ": cannot be opened; expected a readable gmsh .msh file");
  std::string bytes;
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if (size > 0) {
    bytes.resize(static_cast<std::size_t>(size));
    in.read(bytes.data(), size);
    if (in.gcount() != size)
      throw InputError(file + ": could not be read to its end; expected a readable gmsh .msh file");
  }
  return read_msh_bytes(bytes, file);
}

}  // namespace seflex::io::gmsh
