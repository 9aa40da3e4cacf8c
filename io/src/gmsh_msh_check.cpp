#include "gmsh_msh_check.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <string_view>
#include <vector>

#include "seflex/common/error.hpp"
#include "seflex/io/nastran_number.hpp"

namespace seflex::io::gmsh {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::size_t count_tokens(std::string_view s) {
  std::size_t n = 0;
  bool in = false;
  for (const char c : s) {
    const bool sp = is_space(c);
    if (!sp && !in) ++n;
    in = !sp;
  }
  return n;
}

/// Reads a section body: ASCII tokens and lines (with line numbers), or binary numbers.
class Cursor {
 public:
  /// `swap`: binary numbers are big-endian (libgmsh swaps their bytes when the file's endianness int
  /// after the format line is not 1).
  Cursor(std::string_view body, int first_line, bool swap = false) : s_(body), line_(first_line), swap_(swap) {}

  int line() const { return line_; }
  /// The line of the last token() read.
  int token_line() const { return token_line_; }
  std::size_t remaining_bytes() const { return s_.size() - pos_; }
  /// Tokens from here to the end of the section (counted once, then kept up to date).
  std::size_t remaining_tokens() {
    if (!tokens_known_) {
      tokens_ = count_tokens(s_.substr(pos_));
      tokens_known_ = true;
    }
    return tokens_;
  }

  /// The next whitespace-separated token (empty at the end); counts the lines it passes.
  std::string_view token() {
    while (pos_ < s_.size() && is_space(s_[pos_])) advance();
    token_line_ = line_;
    const std::size_t start = pos_;
    while (pos_ < s_.size() && !is_space(s_[pos_])) ++pos_;
    if (pos_ > start && tokens_known_) --tokens_;
    return s_.substr(start, pos_ - start);
  }

  /// The rest of the current line (without its newline); moves to the next line.
  std::string_view rest_of_line() {
    const std::size_t start = pos_;
    const std::size_t eol = s_.find('\n', pos_);
    const std::size_t end = eol == std::string_view::npos ? s_.size() : eol;
    pos_ = end;
    tokens_known_ = false;
    if (pos_ < s_.size()) advance();
    return s_.substr(start, end - start);
  }

  /// What C's fgets(buf, size) reads: through the next newline, but at most size - 1 bytes (the rest
  /// of a longer line is left for the next read, as libgmsh leaves it).
  std::string_view fgets(std::size_t size) {
    const std::size_t start = pos_;
    while (pos_ < s_.size() && pos_ - start < size - 1) {
      const bool eol = s_[pos_] == '\n';
      advance();
      if (eol) break;
    }
    tokens_known_ = false;
    return s_.substr(start, pos_ - start);
  }

  /// An unsigned number of `width` bytes (4 or 8), little-endian unless swapped; false at the end of
  /// the section.
  bool binary(std::size_t width, std::uint64_t& value) {
    if (remaining_bytes() < width) return false;
    value = 0;
    for (std::size_t k = 0; k < width; ++k)
      value |= static_cast<std::uint64_t>(static_cast<unsigned char>(s_[pos_ + k])) << (8 * (swap_ ? width - 1 - k : k));
    pos_ += width;
    tokens_known_ = false;
    return true;
  }
  void skip_bytes(std::size_t n) {
    pos_ += std::min(n, remaining_bytes());
    tokens_known_ = false;
  }

 private:
  void advance() {
    if (s_[pos_] == '\n') ++line_;
    ++pos_;
  }
  std::string_view s_;
  std::size_t pos_ = 0;
  int line_;
  bool swap_ = false;
  int token_line_ = 0;
  std::size_t tokens_ = 0;
  bool tokens_known_ = false;
};

/// An ASCII integer; none if `t` is not one (gmsh then reports the syntax itself).
std::optional<long long> integer(std::string_view t) {
  t = trimmed(t);
  long long v = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size()) return std::nullopt;
  return v;
}

/// The integer `t` starts with, as libgmsh's scanf("%d") reads one (leading white space, a sign, digits;
/// what follows is left): a count line "1 1 1 1" is 1, a physical group "5 13"name"" is 5 and 13. None if
/// `t` starts with something else.
std::optional<long long> leading_integer(std::string_view t) {
  t = trimmed(t);
  const bool plus = !t.empty() && t[0] == '+';
  long long v = 0;
  const char* first = t.data() + (plus ? 1 : 0);
  const auto [end, ec] = std::from_chars(first, t.data() + t.size(), v);
  if (ec != std::errc() || end == first) return std::nullopt;
  return v;
}

/// Nodes of a gmsh element type (gmsh reference manual, "MSH file format version 2", elm-type 1-31 and
/// 92, 93; format 4 numbers its types the same way); 0 for another number.
int msh2_nodes_per_element(long long type) {
  static constexpr int kNodes[32] = {0, 2, 3, 4, 4, 8, 6, 5, 3, 6, 9, 10, 27, 18, 14, 1,
                                     8, 20, 15, 13, 9, 10, 12, 15, 15, 21, 4, 5, 6, 20, 35, 56};
  if (type >= 1 && type <= 31) return kNodes[type];
  if (type == 92) return 64;
  if (type == 93) return 125;
  return 0;
}

class Checker {
 public:
  Checker(std::string_view bytes, const std::string& file) : bytes_(bytes), file_(file) {}

  // A section's body runs to the next line that starts with '$' (where gmsh, too, looks for the next
  // keyword): a damaged or missing $End line must not hide the sections after it. Binary bodies run to
  // their $End line, as a '$' after a newline may be data there.
  void run() {
    std::size_t pos = 0;
    int line = 1;
    while (pos < bytes_.size()) {
      const std::size_t eol = std::min(bytes_.find('\n', pos), bytes_.size());
      std::string_view text = bytes_.substr(pos, eol - pos);
      if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
      if (text.size() > 1 && text[0] == '$' && text.rfind("$End", 0) != 0) {
        const std::string name(text.substr(1));
        const std::size_t body_begin = std::min(eol + 1, bytes_.size());
        std::size_t end = std::string_view::npos;
        if (binary_ && has_binary_data(name)) end = bytes_.find("\n$End" + name, eol);
        if (end == std::string_view::npos) end = bytes_.find("\n$", eol);
        const std::size_t body_end = end == std::string_view::npos ? bytes_.size() : end + 1;
        section(name, bytes_.substr(body_begin, body_end - body_begin), line);
        std::size_t next = body_end;
        if (binary_ && byte_order_end_ && name.compare(0, 10, "MeshFormat") == 0) next = after_byte_order();
        line += static_cast<int>(std::count(bytes_.begin() + static_cast<long>(pos), bytes_.begin() + static_cast<long>(next), '\n'));
        pos = next;
        continue;
      }
      pos = eol + 1;
      ++line;
    }
  }

 private:
  [[noreturn]] void too_many(int line, const std::string& section, std::uint64_t count, const std::string& what,
                             std::uint64_t most) const {
    throw InputError(SourceRef{file_, line},
                     "$" + section + ": " + std::to_string(count) + " " + what + ", but the rest of the section holds at most " +
                         std::to_string(most) + "; expected a count that matches the data (a truncated or corrupted .msh file?)");
  }
  /// Refuse `count` items of at least `unit` tokens/bytes each in `available` (no count: gmsh's error).
  void bound(int line, const std::string& section, std::optional<long long> count, const std::string& what,
             std::uint64_t unit, std::uint64_t available) const {
    if (!count) return;
    if (*count < 0)
      throw InputError(SourceRef{file_, line}, "$" + section + ": " + std::to_string(*count) + " " + what +
                                                   "; expected a count >= 0");
    if (static_cast<std::uint64_t>(*count) > available / unit)
      too_many(line, section, static_cast<std::uint64_t>(*count), what, available / unit);
  }
  /// A binary section that ends before the data it declares: gmsh does not stop at the section's end
  /// but reads on into the next sections and takes their bytes for counts (fuzz_gmsh: a byte inserted
  /// in $Entities made it allocate 2^50 bytes), so the check must not stop there either.
  [[noreturn]] void ends_early(int line, const std::string& section, const std::string& inside) const {
    throw InputError(SourceRef{file_, line}, "$" + section + ": the section ends inside " + inside +
                                                 "; expected the data of everything it declares (a truncated or corrupted .msh file?)");
  }
  /// An element block of a type the node table does not know. The walk cannot go past it: the block's
  /// size depends on gmsh's own node count for the type, and gmsh reads the next block's header from
  /// wherever that leaves it (fuzz_gmsh: a binary MSH 2 file whose walk stopped at an unknown type made
  /// libgmsh allocate 12.9 GB for a later block). seflex models use first-order lines, triangles and
  /// quadrangles, all in the table.
  [[noreturn]] void unknown_type(int line, long long type, const std::string& block) const {
    throw InputError(SourceRef{file_, line}, "$Elements: " + block + " has element type " + std::to_string(type) +
                                                 ", which seflex does not read; expected a type of the gmsh reference manual "
                                                 "(1-31, 92, 93; seflex models use 2-node lines, 3-node triangles and "
                                                 "4-node quadrangles)");
  }
  /// Where libgmsh reads on after a binary $MeshFormat: it read the byte-order int after the format
  /// line, and those 4 bytes are data even when they read "$Nod" (CI's fuzz_gmsh: taken for a section
  /// header, whose binary body ran to "$EndNodes" and hid $Entities and $Nodes from the check). Format
  /// 4 then reads lines to one whose characters after the first are "EndMeshFormat"; format 2 looks
  /// for the next section from right after the int (GModelIO_MSH4.cpp, GModelIO_MSH2.cpp).
  std::size_t after_byte_order() const {
    const std::size_t from = *byte_order_end_;
    if (!v4_) return from;
    for (std::size_t start = from; start < bytes_.size();) {
      const std::size_t eol = std::min(bytes_.find('\n', start), bytes_.size());
      if (eol - start >= 14 && bytes_.compare(start + 1, 13, "EndMeshFormat") == 0) return std::min(eol + 1, bytes_.size());
      start = eol + 1;
    }
    return bytes_.size();
  }
  /// Sections whose data a binary file holds in binary (where a '$' after a newline may be data). The
  /// others, $PhysicalNames among them, are text in a binary file too: their body ends at the next line
  /// that starts with '$', as libgmsh's format 2 reader looks for the next section there (CI's
  /// fuzz_gmsh: a $PhysicalNames body run to a distant "$EndPhysicalNames" hid the $Elements that
  /// libgmsh read, and it allocated 2.16 GB).
  static bool has_binary_data(const std::string& name) {
    for (const char* k : {"Nodes", "Elements", "Entities", "PartitionedEntities", "Periodic", "GhostElements", "Parametrizations",
                          "NodeData", "ElementData", "ElementNodeData"})
      if (name.compare(0, std::char_traits<char>::length(k), k) == 0) return true;
    return false;
  }
  /// Format 4: libgmsh keeps every node (element) of the section in an array of the section's declared
  /// count and fills it block by block without looking at that count (GModelIO_MSH4.cpp: vertexCache,
  /// elementCache), so the blocks must not hold more than it (fuzz_gmsh: 2 nodes in a section that
  /// declared 0 overran the heap, and ASan saw the damage at the next delete).
  void within_total(int line, const std::string& section, std::uint64_t& sum, std::uint64_t n, std::uint64_t total,
                    const std::string& what, std::uint64_t block) const {
    sum += n;
    if (sum > total)
      throw InputError(SourceRef{file_, line}, "$" + section + ": " + (block == 1 ? std::string("block 1 holds ") : "blocks 1 to " + std::to_string(block) + " hold ") + std::to_string(sum) +
                                                   " " + what + ", but the section declares " + std::to_string(total) +
                                                   "; expected the blocks to hold the section's count");
  }
  /// The same for a binary count (unsigned).
  void bound_u(int line, const std::string& section, std::uint64_t count, const std::string& what, std::uint64_t unit,
               std::uint64_t available) const {
    if (count > available / unit) too_many(line, section, count, what, available / unit);
  }

  // gmsh recognises a section by the first letters of its line ("$MeshFormat"Nodes" is $MeshFormat,
  // "$Nodes2" is $Nodes: strncmp with the keyword's length), so the check does too (fuzz_gmsh: a first
  // line "$MeshFormat"Nodes" left the whole file unchecked, and libgmsh asked for 2 GB).
  void section(const std::string& name, std::string_view body, int header_line) {
    Cursor c(body, header_line + 1, swap_);
    const auto is = [&](std::string_view keyword) { return name.compare(0, keyword.size(), keyword) == 0; };
    if (is("MeshFormat")) {
      const std::string_view v = c.token();
      const std::string_view type = c.token();
      const std::string_view size = c.token();
      known_ = !v.empty();
      v4_ = !v.empty() && v[0] >= '4' && v[0] <= '9';
      // libgmsh reads the version as a double and uses the 4.0 layout below 4.1 (gmsh writes 4.0 as "4");
      // from_chars, as the locale must not make "4.1" 4
      double version = 0;
      std::from_chars(v.data(), v.data() + v.size(), version);
      v40_ = v4_ && version >= 4 && version < 4.1;
      binary_ = leading_integer(type).value_or(0) != 0;  // gmsh: any file-type but 0 is binary
      // The width of a binary count: 4.1 says it (data-size, sizeof(size_t)); 4.0's counts are unsigned
      // longs, 8 bytes, and its data-size is "currently unused" (gmsh 4.0 wrote sizeof(double) there).
      size_t_ = !v40_ && leading_integer(size) == 4 ? 4 : 8;
      // libgmsh reads the format line with fgets (at most 1,023 bytes) and then, in a binary file, the
      // int 1 in the file's byte order: any other value makes it swap the bytes of every binary number.
      // Those 4 bytes are read wherever they are, a "$..." line included (CI's fuzz_gmsh: "$Nod" there
      // made gmsh read the counts byte-swapped, and allocate 2^58 bytes for what the check had bounded).
      swap_ = false;
      byte_order_end_.reset();
      if (binary_) {
        const std::size_t start = static_cast<std::size_t>(body.data() - bytes_.data());
        const std::size_t at = start + std::min(body.find('\n'), std::size_t{1022}) + 1;
        std::uint64_t one = 0;
        Cursor marker(bytes_.substr(std::min(at, bytes_.size())), header_line + 2);
        if (marker.binary(4, one)) {
          swap_ = one != 1;
          byte_order_end_ = at + 4;
        }
      }
      return;
    }
    if (!known_) return;  // no $MeshFormat yet: gmsh's error to report
    if (is("PhysicalNames") && v4_) return physical_names(c);
    if (is("Entities") && v4_) return binary_ ? entities_binary(c, header_line) : entities_ascii(c);
    if (is("Nodes")) return binary_ ? nodes_binary(c, header_line) : nodes_ascii(c);
    if (is("Elements")) return binary_ ? elements_binary(c, header_line) : elements_ascii(c);
    for (const char* data_section : {"NodeData", "ElementData", "ElementNodeData"})
      if (is(data_section)) return data(data_section, c, header_line);
  }

  // Format 4: the count, then per physical group "dim tag "name"" (ASCII in binary files too), read as
  // gmsh does: two integers by fscanf("%d %d"), each to its first non-digit, then the rest of the line.
  // libgmsh 4.8 crashes (SEGV in GModel::setPhysicalName; fuzz_gmsh) on a dimension outside 0-3 in
  // formats 4.0 and 4.1; its format 2 reader takes such a line without harm (and a damaged format 2
  // section is gmsh's to report). (fuzz_gmsh, CI: "5 13\"in..." is dimension 5 and tag 13 to gmsh.)
  // The lines are read as libgmsh reads them (GModelIO_MSH4.cpp): the count by fgets into 1,024 bytes
  // and sscanf, the rest of that line ignored; each name by fgets into 256 bytes, so the rest of a
  // longer line is where the next "dim tag" is read. (fuzz_gmsh, a random seed: the count line
  // '110 "hi..."' made the check read '"hi...' as the first group's dimension and stop, while gmsh went
  // on to dimension 5 on the next line and crashed.)
  void physical_names(Cursor& c) {
    const std::optional<long long> n = leading_integer(c.fgets(1024));
    if (!n) return;  // gmsh's syntax error to report
    for (long long k = 0; k < *n; ++k) {
      const std::string_view dim_text = c.token();
      if (dim_text.empty()) return;  // the section ends early: gmsh's error
      const int line = c.token_line();
      const std::optional<long long> dim = leading_integer(dim_text);
      const std::optional<long long> tag = leading_integer(c.token());
      if (!dim || !tag) return;  // gmsh's syntax error
      if (*dim < 0 || *dim > 3)
        throw InputError(SourceRef{file_, line}, "$PhysicalNames: physical group " + std::to_string(*tag) + " has dimension " +
                                                     std::to_string(*dim) + "; expected 0 (point), 1 (curve), 2 (surface) or 3 (volume)");
      c.fgets(256);  // its name
    }
  }

  // Format 4: numPoints numCurves numSurfaces numVolumes, then per entity: tag, its box (points of
  // 4.1: X Y Z), numPhysicalTags and the tags, and (curves and up) numBounding and the tags.
  void entities_ascii(Cursor& c) {
    std::optional<long long> count[4];
    for (auto& n : count) n = leading_integer(c.token());
    const int line = c.token_line();
    for (int dim = 0; dim < 4; ++dim) {
      bound(line, "Entities", count[dim], "entities of dimension " + std::to_string(dim), 5, c.remaining_tokens());
      if (!count[dim]) return;
    }
    for (int dim = 0; dim < 4; ++dim)
      for (long long e = 0; e < *count[dim]; ++e) {
        const int doubles = dim == 0 && !v40_ ? 3 : 6;
        for (int k = 0; k < 1 + doubles; ++k) c.token();
        for (int list = 0; list < (dim == 0 ? 1 : 2); ++list) {
          const std::optional<long long> n = leading_integer(c.token());
          if (!n) return;
          bound(c.token_line(), "Entities", n, list == 0 ? "physical tags of an entity" : "bounding entities of an entity", 1,
                c.remaining_tokens());
          for (long long k = 0; k < *n; ++k) c.token();
        }
      }
  }

  void entities_binary(Cursor& c, int line) {
    std::uint64_t count[4] = {};
    for (auto& n : count)
      if (!c.binary(size_t_, n)) ends_early(line, "Entities", "its four entity counts");
    for (int dim = 0; dim < 4; ++dim)
      bound_u(line, "Entities", count[dim], "entities of dimension " + std::to_string(dim), 4 + 24 + size_t_,
              c.remaining_bytes());
    for (int dim = 0; dim < 4; ++dim)
      for (std::uint64_t e = 0; e < count[dim]; ++e) {
        const auto entity = [&] {
          return "entity " + std::to_string(e + 1) + " of the " + std::to_string(count[dim]) + " of dimension " + std::to_string(dim);
        };
        const std::size_t tag_and_box = 4 + 8 * (dim == 0 && !v40_ ? 3 : 6);
        if (c.remaining_bytes() < tag_and_box) ends_early(line, "Entities", entity());
        c.skip_bytes(tag_and_box);
        for (int list = 0; list < (dim == 0 ? 1 : 2); ++list) {
          std::uint64_t n = 0;
          if (!c.binary(size_t_, n)) ends_early(line, "Entities", entity());
          bound_u(line, "Entities", n, list == 0 ? "physical tags of an entity" : "bounding entities of an entity", 4,
                  c.remaining_bytes());
          c.skip_bytes(static_cast<std::size_t>(4 * n));
        }
      }
  }

  void nodes_ascii(Cursor& c) {
    if (!v4_) {  // N, then N lines "tag x y z"
      const std::optional<long long> n = leading_integer(c.token());
      bound(c.token_line(), "Nodes", n, "nodes", 4, c.remaining_tokens());
      if (!n) return;
      node_tags_.clear();
      for (long long k = 0; k < *n; ++k) {
        if (const std::optional<long long> tag = leading_integer(c.token())) node_tags_.push_back(*tag);
        for (int x = 0; x < 3; ++x) c.token();
      }
      std::sort(node_tags_.begin(), node_tags_.end());
      nodes_known_ = true;
      return;
    }
    // 4.1: numEntityBlocks numNodes minNodeTag maxNodeTag; each block: entityDim entityTag parametric
    // numNodesInBlock, then the block's node tags, then their coordinates x y z [u [v [w]]].
    // 4.0: numEntityBlocks numNodes; each block: tagEntity dimEntity parametric numNodes, then per node
    // its tag and coordinates x y z [u [v [w]]]. Either way a node is 4 numbers and, if the block is
    // parametric, one more per dimension of its entity (libgmsh: `if(parametric) n += entityDim`).
    const std::optional<long long> blocks = leading_integer(c.token());
    const int line = c.token_line();
    const std::optional<long long> total = leading_integer(c.token());
    if (!v40_) {
      c.token();  // minNodeTag
      c.token();  // maxNodeTag
    }
    bound(line, "Nodes", blocks, "node blocks", 4, c.remaining_tokens());
    bound(line, "Nodes", total, "nodes", 4, c.remaining_tokens());
    std::uint64_t sum = 0;
    for (long long b = 0; blocks && b < *blocks; ++b) {
      const std::optional<long long> first = leading_integer(c.token());
      const std::optional<long long> second = leading_integer(c.token());
      const long long dim = (v40_ ? second : first).value_or(0);
      const long long parametric = leading_integer(c.token()).value_or(0);
      const std::optional<long long> n = leading_integer(c.token());
      if (!n) return;
      const long long per_node = 4 + (parametric != 0 && dim > 0 && dim <= 3 ? dim : 0);
      bound(c.token_line(), "Nodes", n, "nodes in a block", static_cast<std::uint64_t>(per_node), c.remaining_tokens());
      if (total && *total >= 0) within_total(c.token_line(), "Nodes", sum, static_cast<std::uint64_t>(*n), static_cast<std::uint64_t>(*total), "nodes", static_cast<std::uint64_t>(b + 1));
      for (long long k = 0; k < *n * per_node; ++k) c.token();
    }
  }

  void nodes_binary(Cursor& c, int line) {
    if (!v4_) {  // "N\n", then N records of int tag + 3 doubles
      const int at = c.line();
      const std::optional<long long> n = leading_integer(c.rest_of_line());
      bound(at, "Nodes", n, "nodes", 28, c.remaining_bytes());
      return;
    }
    // 4.1: numEntityBlocks numNodes minNodeTag maxNodeTag (size_t); each block: entityDim entityTag
    // parametric (int) numNodesInBlock (size_t), then the block's node tags (size_t), then their
    // coordinates (double). 4.0: numEntityBlocks numNodes (unsigned long); each block: tagEntity
    // dimEntity parametric (int) numNodes (unsigned long), then per node its tag (int) and coordinates
    // (double). libgmsh (4.1 and later) refuses a binary 4.0 file at $MeshFormat, but only after this
    // check, which must not refuse it first with a count read from the wrong place.
    std::uint64_t blocks = 0, total = 0, min_tag = 0, max_tag = 0;
    if (!c.binary(size_t_, blocks) || !c.binary(size_t_, total)) return;
    if (!v40_ && (!c.binary(size_t_, min_tag) || !c.binary(size_t_, max_tag))) return;
    const std::uint64_t tag_bytes = v40_ ? 4 : size_t_;
    bound_u(line, "Nodes", blocks, "node blocks", 12 + size_t_, c.remaining_bytes());
    bound_u(line, "Nodes", total, "nodes", tag_bytes + 24, c.remaining_bytes());
    std::uint64_t sum = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      std::uint64_t first = 0, second = 0, parametric = 0, n = 0;
      if (!c.binary(4, first) || !c.binary(4, second) || !c.binary(4, parametric) || !c.binary(size_t_, n)) return;
      const std::uint64_t dim = v40_ ? second : first;
      const std::uint64_t per_node = tag_bytes + 8 * (3 + (parametric != 0 && dim <= 3 ? dim : 0));
      bound_u(line, "Nodes", n, "nodes in a block", per_node, c.remaining_bytes());
      within_total(line, "Nodes", sum, n, total, "nodes", b + 1);
      c.skip_bytes(static_cast<std::size_t>(n * per_node));
    }
  }

  void elements_ascii(Cursor& c) {
    if (!v4_) {  // N, then N lines "tag type ntags tags... nodes..."
      const std::optional<long long> n = leading_integer(c.token());
      bound(c.token_line(), "Elements", n, "elements", 4, c.remaining_tokens());
      if (n) elements_v2_lines(c, *n);
      return;
    }
    const std::optional<long long> blocks = leading_integer(c.token());
    const int line = c.token_line();
    const std::optional<long long> total = leading_integer(c.token());
    bound(line, "Elements", blocks, "element blocks", 4, c.remaining_tokens() + 2);
    bound(line, "Elements", total, "elements", 2, c.remaining_tokens() + 2);
    if (!blocks) return;
    if (!v40_) {
      c.token();  // minElementTag
      c.token();  // maxElementTag
    }
    // Each block: entityDim entityTag (4.0: tagEntity dimEntity) elementType numElementsInBlock, then per
    // element its tag and nodes.
    std::uint64_t sum = 0;
    for (long long b = 0; b < *blocks; ++b) {
      c.token();
      c.token();
      const int type_line = c.token_line();
      const std::optional<long long> type = leading_integer(c.token());
      const std::optional<long long> n = leading_integer(c.token());
      if (!type || !n) return;  // gmsh reports the syntax itself
      const int nodes = msh2_nodes_per_element(*type);
      if (nodes == 0) unknown_type(type_line, *type, "element block " + std::to_string(b + 1));
      const std::uint64_t per = 1 + static_cast<std::uint64_t>(nodes);
      bound(c.token_line(), "Elements", n, "elements in a block", per, c.remaining_tokens());
      if (total && *total >= 0) within_total(c.token_line(), "Elements", sum, static_cast<std::uint64_t>(*n), static_cast<std::uint64_t>(*total), "elements", static_cast<std::uint64_t>(b + 1));
      for (long long k = 0; k < *n * static_cast<long long>(per); ++k) c.token();
    }
  }

  // Format 2, text: one element per line, "tag type ntags tag... node...". libgmsh reads these numbers
  // across line ends and asserts (aborting the process) on a node it does not know, so each line must
  // hold exactly 3 + ntags + the type's node count numbers, and every node must be in $Nodes (a file
  // from fuzz_gmsh: a missing tag count shifted the rest of the section).
  void elements_v2_lines(Cursor& c, long long n) {
    c.rest_of_line();  // the count's line
    std::vector<long long> v;
    for (long long k = 0; k < n; ++k) {
      const int line = c.line();
      const std::string_view text = c.rest_of_line();
      v.clear();
      Cursor t(text, line);
      for (std::string_view tok = t.token(); !tok.empty(); tok = t.token()) {
        const std::optional<long long> x = integer(tok);
        if (!x) throw InputError(SourceRef{file_, line}, "$Elements: '" + std::string(tok) + "' is not an integer; expected an element line 'tag type ntags tags... nodes...'");
        v.push_back(*x);
      }
      const int nodes = v.size() >= 2 ? msh2_nodes_per_element(v[1]) : 0;
      if (v.size() >= 2 && nodes == 0)
        throw InputError(SourceRef{file_, line}, "$Elements: element " + std::to_string(v[0]) + " has type " +
                                                     std::to_string(v[1]) + ", which is not a gmsh MSH 2 element type");
      const long long expected = v.size() >= 3 && v[2] >= 0 ? 3 + v[2] + nodes : -1;
      if (expected != static_cast<long long>(v.size()))
        throw InputError(SourceRef{file_, line}, "$Elements: the line holds " + std::to_string(v.size()) +
                                                     " numbers; expected 'tag type ntags', ntags tags and the type's " +
                                                     std::to_string(nodes) + " nodes");
      if (!nodes_known_) continue;
      for (std::size_t j = v.size() - static_cast<std::size_t>(nodes); j < v.size(); ++j)
        if (!std::binary_search(node_tags_.begin(), node_tags_.end(), v[j]))
          throw InputError(SourceRef{file_, line}, "$Elements: element " + std::to_string(v[0]) + " refers to node " +
                                                       std::to_string(v[j]) + ", which is not in $Nodes");
    }
  }

  // Format 2, binary: after the count line, blocks of one element type until the count is reached, each
  // a header of three ints (elm-type, num-elm-follow, num-tags) and then per element its number, tags
  // and nodes (ints). libgmsh allocates one element's ints, 1 + num-tags + nodes, before it reads the
  // block or looks at the type (GModelIO_MSH2.cpp; fuzz_gmsh: text bytes read as num-tags asked for
  // 4.66 GB), so the tag count must leave room for one element, and the block for all of them.
  void elements_v2_binary_blocks(Cursor& c, int line, std::uint64_t total) {
    std::uint64_t seen = 0;
    for (int block = 1; seen < total; ++block) {
      std::uint64_t type = 0, n = 0, ntags = 0;
      if (!c.binary(4, type) || !c.binary(4, n) || !c.binary(4, ntags))
        ends_early(line, "Elements", "the header of element block " + std::to_string(block));
      // ints read as unsigned: a negative count or tag count is above 2^31, which no file holds. (The
      // message is made only for a refusal: gmsh writes one block per element.)
      const std::uint64_t room = c.remaining_bytes();
      const auto what = [&] { return " in element block " + std::to_string(block) + " (type " + std::to_string(type) + ")"; };
      if (ntags > room / 4) too_many(line, "Elements", ntags, "tags per element" + what(), room / 4);
      const int nodes = msh2_nodes_per_element(static_cast<long long>(type));
      if (nodes == 0) unknown_type(line, static_cast<long long>(type), "element block " + std::to_string(block));
      const std::uint64_t per = 4 * (1 + ntags + static_cast<std::uint64_t>(nodes));
      if (n > room / per) too_many(line, "Elements", n, "elements" + what(), room / per);
      c.skip_bytes(static_cast<std::size_t>(n * per));
      seen += n;
    }
  }

  void elements_binary(Cursor& c, int line) {
    if (!v4_) {
      const int at = c.line();
      const std::optional<long long> n = leading_integer(c.rest_of_line());
      bound(at, "Elements", n, "elements", 8, c.remaining_bytes());
      if (n) elements_v2_binary_blocks(c, at, static_cast<std::uint64_t>(*n));
      return;
    }
    // 4.1: numEntityBlocks numElements minElementTag maxElementTag (size_t); each block: entityDim
    // entityTag elementType (int) numElementsInBlock (size_t), then per element its tag and nodes (size_t
    // each): libgmsh allocates the block's data before reading it. 4.0: numEntityBlocks numElements
    // (unsigned long); each block: tagEntity dimEntity typeEle (int) numElements (unsigned long), then
    // per element its tag and nodes (int each).
    std::uint64_t blocks = 0, total = 0, tag = 0;
    if (!c.binary(size_t_, blocks) || !c.binary(size_t_, total)) ends_early(line, "Elements", "its counts");
    const std::uint64_t tag_bytes = v40_ ? 4 : size_t_;
    bound_u(line, "Elements", blocks, "element blocks", 12 + size_t_, c.remaining_bytes());
    bound_u(line, "Elements", total, "elements", 2 * tag_bytes, c.remaining_bytes());
    if (!v40_ && (!c.binary(size_t_, tag) || !c.binary(size_t_, tag)))  // 4.1: min and max element tags
      ends_early(line, "Elements", "its counts");
    std::uint64_t sum = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      std::uint64_t first = 0, second = 0, type = 0, n = 0;
      if (!c.binary(4, first) || !c.binary(4, second) || !c.binary(4, type) || !c.binary(size_t_, n))
        ends_early(line, "Elements", "the header of element block " + std::to_string(b + 1) + " of " + std::to_string(blocks));
      const int nodes = msh2_nodes_per_element(static_cast<long long>(type));
      if (nodes == 0) unknown_type(line, static_cast<long long>(type), "element block " + std::to_string(b + 1) + " of " + std::to_string(blocks));
      const std::uint64_t per = tag_bytes * (1 + static_cast<std::uint64_t>(nodes));
      bound_u(line, "Elements", n, "elements in a block", per, c.remaining_bytes());
      within_total(line, "Elements", sum, n, total, "elements", b + 1);
      c.skip_bytes(static_cast<std::size_t>(n * per));
    }
  }

  // String tags, real tags, integer tags (time step, components, entities[, partition]), then one
  // record per entity: its tag and the values.
  void data(const std::string& name, Cursor& c, int header_line) {
    long long components = 1;
    std::optional<long long> entities;
    int entities_line = header_line;
    for (int kind = 0; kind < 3; ++kind) {
      const int line = c.line();
      const std::optional<long long> n = leading_integer(c.rest_of_line());
      if (!n || *n < 0) return;  // gmsh's syntax error to report
      bound(line, name, n, "tags", 1, c.remaining_tokens());
      for (long long k = 0; k < *n; ++k) {
        const int tline = c.line();
        const std::string_view t = c.rest_of_line();
        if (kind == 2 && k == 1) components = std::max(1LL, leading_integer(t).value_or(1));
        if (kind == 2 && k == 2) {
          entities = leading_integer(t);
          entities_line = tline;
        }
      }
    }
    if (binary_)
      bound(entities_line, name, entities, "entities", 4 + 8 * static_cast<std::uint64_t>(std::min(components, 1LL << 20)),
            c.remaining_bytes());
    else
      bound(entities_line, name, entities, "entities", 1 + static_cast<std::uint64_t>(std::min(components, 1LL << 20)),
            c.remaining_tokens());
  }

  std::string_view bytes_;
  const std::string& file_;
  bool known_ = false, v4_ = false, v40_ = false, binary_ = false, swap_ = false;
  std::optional<std::size_t> byte_order_end_;  ///< where the byte-order int of a binary file ends
  std::size_t size_t_ = 8;
  std::vector<long long> node_tags_;  ///< format 2, text: the tags of $Nodes, sorted
  bool nodes_known_ = false;
};

}  // namespace

void check_msh_counts(const std::filesystem::path& path, const std::string& file) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(file + ": cannot open it; expected a readable gmsh .msh file");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // gmsh chooses its reader by the first line, whatever the file's name: "$MeshFormat" (and a few
  // legacy keywords) a mesh, "$PostFormat"/"$View" a post-processing view, anything else a .geo
  // script - a language that runs shell commands (SystemCall), writes files and exits the process
  // (found by fuzz_gmsh: a damaged first line made gmsh parse the mesh as a script). MSH 2 and 4
  // files start with $MeshFormat.
  std::string_view first(bytes);
  first = first.substr(0, std::min(first.find('\n'), first.size()));
  if (!first.empty() && first.back() == '\r') first.remove_suffix(1);
  if (first.rfind("$MeshFormat", 0) != 0)
    throw InputError(SourceRef{file, 1},
                     (bytes.empty() ? std::string("the file is empty") : "the file starts with " + nastran::quote_field(first)) +
                         "; expected a gmsh mesh (MSH format 2 or 4), whose first line is $MeshFormat (gmsh would read "
                         "any other file as a .geo script; a script must be named .geo)");
  Checker(bytes, file).run();
}

}  // namespace seflex::io::gmsh
