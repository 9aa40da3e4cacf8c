// Reading a Nastran deck: files and INCLUDE, the executive / case control / bulk sections, assembling
// cards from their lines (small, large and free field; continuations), dispatching them to the card
// parsers, and the defaults that need the whole deck (GRDSET, BAROR, BEAMOR).
#include <algorithm>
#include <array>
#include <memory>
#include <unordered_map>

#include "seflex/common/error.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/fem/parts.hpp"
#include "nastran_external.hpp"
#include "seflex/io/nastran.hpp"
#include "seflex/io/nastran_card.hpp"
#include "seflex/io/nastran_cards.hpp"
#include "seflex/io/nastran_case_control.hpp"
#include "seflex/io/nastran_lines.hpp"

#include "nastran_include.hpp"
#include "nastran_replication.hpp"

namespace seflex::io {
namespace nastran {

void ReaderState::note_unsupported(std::string_view name, const fem::CardRef& ref) { unsupported.add(std::string(name), ref); }

void ReaderState::note_unsupported_member(std::string_view name, int id, const fem::CardRef& ref) {
  unsupported.add(std::string(name), ref).members.push_back({id, ref});
}

std::string ReaderState::where(const fem::CardRef& ref) const { return location(files.at(ref.file), ref.line); }

void ReaderState::note_unsupported_card(const Card& card) {
  fem::UnsupportedCard& u = unsupported.add(std::string(card.name()), card.ref());
  int sid = 0;
  if (parse_int(card.raw(0), sid)) u.members.push_back({sid, card.ref()});
}

namespace {

struct CardType {
  std::string_view name;
  CardParser parse;
};

constexpr CardType kCardTypes[] = {
    {"GRID", parse_grid},       {"GRDSET", parse_grdset},   {"CORD2R", parse_cord2},   {"CORD2C", parse_cord2},
    {"CORD2S", parse_cord2},    {"CORD1R", parse_cord1},    {"CORD1C", parse_cord1},   {"CORD1S", parse_cord1},
    {"SPOINT", parse_spoint},   {"CBAR", parse_cbar},       {"CBEAM", parse_cbeam},    {"BAROR", parse_baror},
    {"BEAMOR", parse_beamor},   {"CROD", parse_crod},       {"CONROD", parse_conrod},  {"CQUAD4", parse_cquad4},
    {"CTRIA3", parse_ctria3},   {"CONM2", parse_conm2},     {"CELAS1", parse_celas1},  {"CELAS2", parse_celas2},
    {"RBE2", parse_rbe2},       {"MAT1", parse_mat1},       {"PBAR", parse_pbar},      {"PBARL", parse_pbarl},
    {"PBEAM", parse_pbeam},     {"PBEAML", parse_pbeaml},   {"PROD", parse_prod},      {"PSHELL", parse_pshell},
    {"PELAS", parse_pelas},     {"SPC", parse_spc},         {"SPC1", parse_spc1},      {"SPCADD", parse_spcadd},
    {"ASET", parse_aset},       {"ASET1", parse_aset1},     {"BSET", parse_bset},      {"BSET1", parse_bset1},
    {"SUPORT", parse_suport},   {"SUPORT1", parse_suport1},   {"FORCE", parse_force},     {"MOMENT", parse_moment},  {"LOAD", parse_load},
    {"EIGRL", parse_eigrl},     {"EIGR", parse_eigr},       {"EIGB", parse_eigb},       {"PARAM", parse_param},    {"DMIG", parse_dmig},
    {"MPC", parse_mpc},         {"MPCADD", parse_mpcadd},   {"OMIT", parse_omit},      {"OMIT1", parse_omit1},
    {"RBAR", parse_rbar},       {"RBE3", parse_rbe3},       {"MAT2", parse_mat2},      {"MAT8", parse_mat8},
    {"PCOMP", parse_pcomp},     {"PCOMPG", parse_pcompg},   {"PLOAD2", parse_pload2},  {"GRAV", parse_grav},
    {"RFORCE", parse_rforce},   {"TEMP", parse_temp},       {"TEMPD", parse_tempd},    {"TEMPRB", parse_temprb},
    {"CBUSH", parse_cbush},     {"PBUSH", parse_pbush},     {"CELAS3", parse_celas3},  {"CELAS4", parse_celas4},
    {"CMASS1", parse_cmass1},   {"CMASS2", parse_cmass2},   {"CMASS3", parse_cmass1},  {"CMASS4", parse_cmass2},
    {"PMASS", parse_pmass},     {"CONM1", parse_conm1},     {"PLOAD1", parse_pload1},  {"SPCD", parse_spcd},
    {"CHEXA", parse_chexa},     {"CPENTA", parse_cpenta},   {"CTETRA", parse_ctetra},  {"PSOLID", parse_psolid},
    {"PLOAD4", parse_pload4},   {"MAT9", parse_mat9},       {"FORCE1", parse_force12}, {"FORCE2", parse_force12},
    {"MOMENT1", parse_force12}, {"MOMENT2", parse_force12}, {"RBE1", parse_rbe1},      {"CRIGD1", parse_crigd1},
    {"CRIGD2", parse_crigd2},   {"CRIGD3", parse_crigd3},   {"CRIGDR", parse_crigdr},  {"RROD", parse_rrod},
    {"CTUBE", parse_crod},      {"PTUBE", parse_ptube},     {"GENEL", parse_genel},    {"CSHEAR", parse_cshear},
    {"MDLPRM", parse_mdlprm},   {"PSHEAR", parse_pshear},   {"CBEND", parse_cbend},     {"PBEND", parse_pbend},    {"CQUAD8", parse_shell8},
    {"CTRIA6", parse_shell8},   {"CQUADR", parse_cquad4},   {"CTRIAR", parse_ctria3},  {"SLOAD", parse_sload},
    {"PLOAD", parse_pload},     {"CBUSH1D", parse_cbush1d}, {"PBUSH1D", parse_pbush1d}, {"TABLEM1", parse_tablem},
    {"TABLEM2", parse_tablem},  {"TABLEM3", parse_tablem},  {"TABLEM4", parse_tablem},  {"CPYRAM", parse_cpyram},
    {"POINT", parse_point},     {"SELOC", parse_seloc},     {"SEBULK", parse_sebulk},   {"SECONCT", parse_seconct},
    {"SELABEL", parse_selabel}, {"EXTRN", parse_extrn},     {"SEMPLN", parse_sempln},
};
constexpr std::size_t kNumCardTypes = sizeof(kCardTypes) / sizeof(kCardTypes[0]);

int find_card_type(std::string_view name) {
  static const std::unordered_map<std::string_view, int> index = [] {
    std::unordered_map<std::string_view, int> m;
    for (std::size_t i = 0; i < kNumCardTypes; ++i) m.emplace(kCardTypes[i].name, static_cast<int>(i));
    return m;
  }();
  const auto it = index.find(name);
  return it == index.end() ? -1 : it->second;
}

inline char ascii_upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }

/// text == word, ignoring the case of text (word is upper case).
bool equals_upper(std::string_view text, std::string_view word) {
  if (text.size() != word.size()) return false;
  for (std::size_t i = 0; i < word.size(); ++i)
    if (ascii_upper(text[i]) != word[i]) return false;
  return true;
}

bool starts_with_word(std::string_view text, std::string_view word) {
  if (text.size() < word.size()) return false;
  for (std::size_t i = 0; i < word.size(); ++i)
    if (ascii_upper(text[i]) != word[i]) return false;
  return text.size() == word.size() || text[word.size()] == ' ' || text[word.size()] == '\'' ||
         text[word.size()] == '"' || text[word.size()] == ',' || text[word.size()] == '=';
}

/// "BEGIN BULK" (any case, blanks between) on a line of its own.
bool is_begin_bulk(std::string_view text) {
  const std::string_view t = trim(text);
  if (!starts_with_word(t, "BEGIN")) return false;
  return equals_upper(trim(t.substr(5)), "BULK");
}

/// "BEGIN SUPER = n" or "BEGIN BULK SUPER = n" (any case): the bulk data of a part superelement.
bool is_begin_super(std::string_view text) {
  std::string_view t = trim(text);
  if (!starts_with_word(t, "BEGIN")) return false;
  t = trim(t.substr(5));
  if (starts_with_word(t, "BULK")) t = trim(t.substr(4));
  return starts_with_word(t, "SUPER");
}

/// Does the text have a BEGIN BULK or a CEND line? Decides whether it starts with executive control.
bool has_control_sections(std::string_view text) {
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    const std::size_t first = line.find_first_not_of(' ');
    if (first != std::string_view::npos && (line[first] == 'B' || line[first] == 'b' || line[first] == 'C' || line[first] == 'c')) {
      const std::size_t dollar = line.find('$');
      if (dollar != std::string_view::npos) line = line.substr(0, dollar);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      if (is_begin_bulk(line) || equals_upper(trim(line), "CEND")) return true;
    }
    pos = end + 1;
  }
  return false;
}

bool valid_card_name(std::string_view n) {
  if (n.empty() || n.size() > 8 || !(n[0] >= 'A' && n[0] <= 'Z')) return false;
  for (const char c : n)
    if (!((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) return false;
  return true;
}

/// A field 1 of punctuation only (no letter or digit, not '=' duplication or a continuation mark).
bool stray_mark(std::string_view f) {
  if (f.empty() || f[0] == '=' || f[0] == '+' || f[0] == '*' || f[0] == '$') return false;
  for (const char c : f)
    if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == ' ') return false;
  return true;
}

/// Do the continuation markers of field 10 of a line and field 1 of the line after it match? MSC's
/// rule (QRG, "Format of Bulk Data Entries", continuation entries): columns 2-8 of field 10 are
/// compared with columns 2-8 of the continuation's field 1; column 1 is not compared (it holds '+',
/// '*' or a blank on the continuation, anything in field 10): ` MRBRG1` (column 73 blank) is
/// continued by `+MRBRG1` or `*MRBRG1`, `CORD1` by `+ORD1` (a101x.dat). `field10` and `field1` are
/// the columns as written on a fixed-field line, the field's text on a free-field one (blanks around
/// commas are not significant: the text starts in the field's first column). Any case; blanks at
/// either end of columns 2-8 do not count; a marker that is blank in columns 2-8 matches any (field
/// 10 may be left blank). As seflex compared markers before, text counted from the first character
/// that is not blank is accepted too (a right-justified `     +C1` continued by `+C1`): only the
/// line's position makes it a continuation here, the markers are a check.
bool continuation_markers_match(std::string_view field10, std::string_view field1) {
  const auto columns_2_8 = [](std::string_view f) { return f.empty() ? std::string() : upper(trim(f.substr(1))); };
  const std::string a = columns_2_8(field10), b = columns_2_8(field1);
  return a.empty() || b.empty() || a == b || columns_2_8(trim(field10)) == columns_2_8(trim(field1));
}

/// The line, from its first character that is not blank, starts with `word` (INCLUDE and ENDDATA may
/// be indented; they are never continuations).
bool starts_with_keyword(std::string_view text, std::string_view word) {
  const std::size_t first = text.find_first_not_of(' ');
  return first != std::string_view::npos && starts_with_word(text.substr(first), word);
}

class DeckReader {
 public:
  DeckReader(fem::Model& model, const std::filesystem::path& main_dir, const std::vector<NastranSymbol>& symbols)
      : model_(model), state_(model, model.files), case_control_(model), includes_(main_dir, symbols), main_dir_(main_dir) {}

  void read_main(std::string text, const std::string& name, const std::filesystem::path& dir,
                 const std::filesystem::path& canonical) {
    section_ = has_control_sections(text) ? Section::Executive : Section::Bulk;
    Source& src = add_source(std::move(text), name, dir);
    std::vector<std::filesystem::path> stack{canonical};
    read_source(src, stack);
    if (section_ != Section::Bulk)
      throw InputError(name + ": no BEGIN BULK reached" +
                       (section_ == Section::Executive ? std::string(" (and no CEND)") : std::string()) +
                       "; expected the bulk data after BEGIN BULK");
    std::size_t cards = 0;
    for (const std::size_t c : residual_counts_) cards += c;
    for (const auto& u : model_.unsupported) cards += u.count;
    for (const auto& p : parts_) {
      for (const std::size_t c : p->counts) cards += c;
      for (const auto& u : p->part.model.unsupported) cards += u.count;
    }
    if (cards == 0)
      throw InputError(name + ": no bulk data cards" + (model_.files.size() > 1 ? " in it or its includes" : "") +
                       "; expected GRID, element and property cards (is this a Nastran deck?)");
    case_control_.finish();
    apply_defaults(model_, state_);
    add_counts(model_, residual_counts_);
    if (parts_.empty() && model_.part_locations.empty() && model_.part_bulks.empty() && model_.part_connections.empty()) return;
    std::vector<fem::Part> parts;
    for (auto& p : parts_) {
      apply_defaults(p->part.model, p->state);
      add_counts(p->part.model, p->counts);
      parts.push_back(std::move(p->part));
    }
    parts_.clear();
    st_ = &state_;
    read_external_matrices(model_, parts, case_control_.assigned_units(), main_dir_);
    fem::assemble_parts(model_, parts);
  }

  /// The main file's text (moved out: call once, after read_main).
  std::string take_main_text() { return sources_.empty() ? std::string() : std::move(sources_.front()->text); }

 private:
  enum class Section { Executive, CaseControl, Bulk };
  struct Source {
    std::string name;
    std::filesystem::path dir;
    std::string text;
    std::uint32_t index = 0;
  };

  Source& add_source(std::string text, const std::string& name, const std::filesystem::path& dir) {
    auto src = std::make_unique<Source>();
    src->name = name;
    src->dir = dir;
    src->text = std::move(text);
    src->index = static_cast<std::uint32_t>(model_.files.size());
    model_.files.push_back(name);
    sources_.push_back(std::move(src));
    return *sources_.back();
  }

  void read_source(Source& src, std::vector<std::filesystem::path>& stack) {
    LineCursor cursor(src.text, &src.name);
    Line line;
    while (!done_ && cursor.next(line)) {
      if (line.blank()) continue;
      if (skipping_ && section_ == Section::Bulk) {
        part_line(src, line);
        continue;
      }
      if (starts_with_keyword(line.text, "INCLUDE")) {
        include(src, cursor, line, stack);
        continue;
      }
      switch (section_) {
        case Section::Executive:
          if (is_begin_bulk(line.text)) {
            if (executive_statements_)
              throw InputError(location(src.name, line.number) +
                               ": BEGIN BULK before CEND; expected CEND to end the executive control");
            section_ = Section::Bulk;
          } else if (case_control_.executive_line(line, src.name, src.index)) {
            section_ = Section::CaseControl;
          } else {
            executive_statements_ = true;
          }
          break;
        case Section::CaseControl:
          if (is_begin_bulk(line.text) || is_begin_super(line.text)) {  // parts may come first (pyNastran writes them so)
            section_ = Section::Bulk;
            state_.case_control_params = model_.params.size();
            if (is_begin_super(line.text)) part_line(src, line);
          }
          else
            case_control_.case_line(line, src.name, src.index);
          break;
        case Section::Bulk: bulk_card(src, cursor, line); break;
      }
    }
  }

  /// INCLUDE 'file' (quotes optional; a quoted name may continue over lines).
  void include(const Source& src, LineCursor& cursor, const Line& line, std::vector<std::filesystem::path>& stack) {
    const std::string where = location(src.name, line.number);
    std::string_view rest = trim(trim(line.text).substr(7));
    std::string name;
    if (!rest.empty() && (rest[0] == '\'' || rest[0] == '"')) {
      const char quote = rest[0];
      rest.remove_prefix(1);
      Line more;
      while (true) {
        const std::size_t close = rest.find(quote);
        name += std::string(trim(rest.substr(0, close)));
        if (close != std::string_view::npos) {
          if (!trim(rest.substr(close + 1)).empty())
            throw InputError(where + ": INCLUDE: text " + quote_field(trim(rest.substr(close + 1))) +
                             " after the file name; expected nothing after the closing quote");
          break;
        }
        if (!cursor.next(more))
          throw InputError(where + ": INCLUDE: the file name has no closing quote; expected " + std::string(1, quote) +
                           "name" + std::string(1, quote));
        rest = more.text;
      }
    } else {
      name = std::string(rest);
      if (name.find(' ') != std::string::npos)
        throw InputError(where + ": INCLUDE: got " + quote_field(name) + "; expected one file name (quote names with blanks)");
    }
    if (name.empty()) throw InputError(where + ": INCLUDE: blank; expected a file name");
    std::replace(name.begin(), name.end(), '\\', '/');  // decks written on Windows
    if (stack.size() >= kMaxIncludeDepth)
      throw InputError(where + ": INCLUDE " + quote_field(name) + ": includes nested more than " +
                       std::to_string(kMaxIncludeDepth) + " deep; expected fewer levels (a cycle?)");
    const IncludeTarget target = includes_.resolve(name, src.dir, where + ": INCLUDE " + quote_field(name));
    const std::filesystem::path& path = target.path;
    if (!target.warning.empty()) model_.read_warnings.push_back(target.warning);
    std::error_code ec;
    std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
    if (ec) canonical = path.lexically_normal();
    for (const auto& p : stack)
      if (p == canonical) {
        std::string chain;
        for (const auto& q : stack) chain += q.filename().string() + " -> ";
        throw InputError(where + ": INCLUDE " + quote_field(name) + " is an include cycle (" + chain +
                         canonical.filename().string() + "); expected each file to be included at most once per chain");
      }
    std::string text = load_text(path, where + ": INCLUDE " + quote_field(name));
    Source& inc = add_source(std::move(text), path.lexically_normal().string(), path.parent_path());
    stack.push_back(canonical);
    read_source(inc, stack);
    stack.pop_back();
  }

  /// A BEGIN SUPER = n line (or BEGIN BULK SUPER = n): the cards after it, up to the next BEGIN
  /// SUPER, BEGIN BULK (the residual's bulk data, when the parts come first) or ENDDATA, are part n's,
  /// read into a model of their own (fem::assemble_parts merges them). A mass section (BEGIN SUPER = n
  /// MASSID = m, for MASSSET) is skipped and listed. While skipping_, every line comes here.
  void part_line(const Source& src, const Line& line) {
    const std::string_view t = trim(line.text);
    if (!is_begin_super(t) && !is_begin_bulk(t) && !starts_with_word(t, "ENDDATA")) return;  // a line of a skipped section
    have_previous_ = have_pattern_ = false;
    skipping_ = false;
    if (is_begin_super(t)) {
      std::string_view rest = trim(t.substr(5));
      if (starts_with_word(rest, "BULK")) rest = trim(rest.substr(4));
      rest = trim(rest.substr(5));  // SUPER
      if (!rest.empty() && rest[0] == '=') rest = trim(rest.substr(1));
      std::size_t digits = 0;
      while (digits < rest.size() && rest[digits] >= '0' && rest[digits] <= '9') ++digits;
      int seid = 0;
      if (digits == 0 || digits > 9 || (seid = std::stoi(std::string(rest.substr(0, digits)))) <= 0)
        throw InputError(location(src.name, line.number) + ": " + quote_field(t) +
                         ": expected BEGIN SUPER = n with a part id n > 0");
      rest = trim(rest.substr(digits));
      if (!rest.empty()) {
        if (starts_with_word(rest, "MASSID")) {
          skipping_ = true;
          state_.note_unsupported(kPartMassSection, {src.index, line.number});
          return;
        }
        throw InputError(location(src.name, line.number) + ": " + quote_field(t) + ": text " + quote_field(rest) +
                         " after the part id; expected BEGIN SUPER = n (or BEGIN SUPER = n MASSID = m)");
      }
      in_part_ = true;
      PartReading* part = nullptr;
      for (auto& p : parts_)
        if (p->part.seid == seid) part = p.get();
      if (!part) {
        parts_.push_back(std::make_unique<PartReading>(seid, fem::CardRef{src.index, line.number}, model_.files));
        part = parts_.back().get();
      }
      st_ = &part->state;
      counts_ = &part->counts;
    } else if (is_begin_bulk(t)) {  // the residual's bulk data after the parts
      in_part_ = false;
      st_ = &state_;
      counts_ = &residual_counts_;
    } else if (starts_with_word(t, "ENDDATA")) {
      done_ = true;
    }
  }

  /// A free-field line with columns 1-8 blank and data before its first comma ("        PART=PELEM,
  /// ELSET=101", "        206, 207, 208"): how the p-element and geometry cards ADAPT, PVAL and GMCURV
  /// continue in MSC's decks. A continuation, whose fields are ambiguous (is the first one field 1 or
  /// field 2?): read_lines refuses it on a card seflex parses.
  static bool indented_free(const Line& line) {
    return line.free && line.text.size() > 8 && trim(line.text.substr(0, 8)).empty() &&
           !trim(line.text.substr(0, line.text.find(','))).empty();
  }

  /// The line continues the card before it: its first column is '+' or '*'; on a fixed-field line,
  /// a blank (columns 2-8 then hold the continuation marker, if any: QRG, "Format of Bulk Data
  /// Entries"; OptiStruct's bulk data guidelines say the same); on a free-field line, field 1 is
  /// blank (",..."), or the line is indented_free. INCLUDE and ENDDATA lines never are.
  static bool is_continuation(const Line& line) {
    const char c = line.text[0];
    if (c == '+' || c == '*') return true;
    if (line.free) return trim(line.text.substr(0, line.text.find(','))).empty() || indented_free(line);
    return c == ' ' && !starts_with_keyword(line.text, "INCLUDE") && !starts_with_keyword(line.text, "ENDDATA");
  }

  /// Split one physical line of a card: data fields into fields_/nfields, field 1 and the
  /// continuation marker (field 10) returned: on a fixed-field line, the marker's eight columns as
  /// written (continuation_markers_match compares columns), elsewhere the field's text.
  void split_line(const Source& src, const Line& line, bool first, std::string_view& field1, std::string_view& marker,
                  std::size_t& n) {
    if (line.free) {
      std::array<std::string_view, 12> short_line;
      std::size_t count = split_free(line.text, short_line.data(), short_line.size());
      const std::string_view* f = short_line.data();
      if (count > short_line.size() && count <= kMaxFreeFields) {  // rare: split again into the long buffer
        long_line_.resize(count);
        split_free(line.text, long_line_.data(), count);
        f = long_line_.data();
      }
      field1 = f[0];
      // large field: "GRID*," on the first line, "*...," on a continuation
      const bool large = first ? (!field1.empty() && field1.back() == '*') : (!field1.empty() && field1[0] == '*');
      n = large ? 4 : 8;
      overflow_.clear();
      // Blank fields after the last one ("..., 1.0, +C1," in conedg01e.bdf) add nothing: dropped
      // so that a trailing comma after the continuation marker does not make a long line of it.
      if (count <= kMaxFreeFields)
        while (count > n + 2 && f[count - 1].empty()) --count;
      if (count > n + 2 && (large || count > kMaxFreeFields))
        throw InputError(location(src.name, line.number) + ": free-field line has " + std::to_string(count) +
                         " fields; expected at most " + std::to_string(large ? n + 2 : kMaxFreeFields) +
                         " (field 1, the data fields, a continuation marker); continue on a new line starting with '+' or ','");
      for (std::size_t k = 0; k < n; ++k) fields_[k] = k + 1 < count ? f[k + 1] : std::string_view();
      marker = count == n + 2 ? f[n + 1] : std::string_view();
      // A small-field free line with more fields than one card line (pyNastran and Nastran read it):
      // every field after field 1 is data, continued 8 per card line, no continuation markers.
      if (count > n + 2) {
        overflow_.assign(f + 1 + n, f + count);
        marker = std::string_view();
      }
    } else {
      const std::string_view f1 = trim(line.text.substr(0, std::min<std::size_t>(8, line.text.size())));
      const bool large = first ? (!f1.empty() && f1.back() == '*') : line.text[0] == '*';
      n = large ? 4 : 8;
      overflow_.clear();  // a long free-field line before must not lend its fields to this card
      split_fixed(line.text, n, field1, fields_.data(), marker);
      marker = line.text.size() > 72 ? line.text.substr(72, 8) : std::string_view();
    }
  }

  /// DEQATN: its equations are not fields (commas, '=' and blanks anywhere): the card and its
  /// continuation lines (field 1 blank, '+' or '*') are skipped and listed as unsupported.
  void skip_equation_card(const Source& src, LineCursor& cursor, const Line& line) {
    st_->note_unsupported("DEQATN", {src.index, line.number});
    Line next;
    while (cursor.next(next)) {
      if (next.blank()) continue;
      const char c = next.text[0];
      if (c != ' ' && c != '\t' && c != '+' && c != '*' && c != ',') {
        cursor.push_back(next);
        break;
      }
    }
  }

  /// The data fields of the line split last (fields_, then any overflow_ 8 per card line).
  void append_line(Card& card, std::size_t n, std::uint32_t number) {
    card.append(fields_.data(), n, number);
    for (std::size_t k = 0; k < overflow_.size(); k += 8) {
      std::array<std::string_view, 8> chunk{};
      for (std::size_t j = 0; j < 8 && k + j < overflow_.size(); ++j) chunk[j] = overflow_[k + j];
      card.append(chunk.data(), 8, number);
    }
  }

  void bulk_card(const Source& src, LineCursor& cursor, const Line& line) {
    if (starts_with_word(line.text, "DEQATN") || (line.text.size() > 6 && starts_with_word(line.text.substr(0, 6), "DEQATN") &&
                                                  (line.text[6] == '*' || line.text[6] == '\t'))) {
      skip_equation_card(src, cursor, line);
      have_previous_ = have_pattern_ = false;
      return;
    }
    if (is_begin_super(line.text) || (in_part_ && is_begin_bulk(line.text))) {
      part_line(src, line);
      return;
    }
    if (starts_with_keyword(line.text, "ENDDATA")) {  // indented too (columns 1-8 would cut it)
      done_ = true;
      return;
    }
    if (is_continuation(line))
      throw InputError(location(src.name, line.number) + ": continuation line " +
                       quote_field(trim(line.text).substr(0, 16)) +
                       " without a card before it; expected continuation lines directly after their card");
    std::string_view field1, marker;
    std::size_t n = 0;
    split_line(src, line, true, field1, marker, n);
    std::string_view name = field1;
    if (!name.empty() && name.back() == '*') name = trim(name.substr(0, name.size() - 1));  // "CORD2R *" too
    char buf[16];
    const std::size_t len = std::min(name.size(), sizeof buf);
    for (std::size_t i = 0; i < len; ++i) buf[i] = ascii_upper(name[i]);
    const std::string_view uname(buf, len);
    if (uname == "ENDDATA") {
      done_ = true;
      return;
    }
    if (stray_mark(field1) && trim(line.text.substr(std::min(line.text.size(), field1.size() + line.text.find_first_not_of(' ')))).empty()) {
      // A line holding only a mark such as '&' (MYSTRAN's decks have some): listed, not a card.
      st_->note_unsupported(std::string("'") + std::string(field1) + "'", {src.index, line.number});
      have_previous_ = have_pattern_ = false;
      return;
    }
    if (!field1.empty() && field1[0] == '=') {
      replicate(src, cursor, line, field1, marker, n);
      return;
    }
    if (!valid_card_name(uname) || name.size() > 8) {
      if (starts_with_word(trim(line.text), "BEGIN"))
        throw InputError(location(src.name, line.number) + ": " + quote_field(trim(line.text)) +
                         " inside the bulk data; expected one BEGIN BULK (and BEGIN SUPER = n sections for parts)");
      throw InputError(location(src.name, line.number) + ": got " + quote_field(field1) +
                       " where a card name belongs; expected a name of up to 8 letters and digits in columns 1-8"
                       " (or before the first comma)");
    }
    card_.reset(uname, &src.name, src.index, line.number);
    read_lines(card_, src, cursor, line, marker, n);
    dispatch();
    have_previous_ = true;
    have_pattern_ = false;
  }

  /// The first line of a card (already split) and its continuation lines, into `card`.
  void read_lines(Card& card, const Source& src, LineCursor& cursor, const Line& line, std::string_view marker,
                  std::size_t n) {
    append_line(card, n, line.number);
    Line next;
    while (cursor.next(next)) {
      if (next.blank()) continue;
      if (!is_continuation(next)) {
        cursor.push_back(next);
        break;
      }
      if (indented_free(next) && find_card_type(card.name()) >= 0)
        throw InputError(location(src.name, next.number) + ": free-field continuation of " + card.label() +
                         " with data in columns 1-8 (" + quote_field(trim(next.text).substr(0, 16)) +
                         "); expected a blank field 1: start the line with a comma");
      std::string_view cont1, cont_marker;
      split_line(src, next, false, cont1, cont_marker, n);
      const std::string_view columns1 = next.free ? cont1 : next.text.substr(0, std::min<std::size_t>(8, next.text.size()));
      if (!continuation_markers_match(marker, columns1))
        throw InputError(location(src.name, next.number) + ": continuation " + quote_field(cont1) + " does not match " +
                         quote_field(trim(marker)) + " in field 10 of the line before (" + card.label() +
                         "); expected matching continuation markers (the same text in columns 2-8 of both; the first "
                         "column is not compared), or a blank one");
      append_line(card, n, next.number);
      marker = cont_marker;
    }
  }

  /// A replication line ('=' or '=n'; nastran_replication.hpp): the cards it makes, parsed.
  void replicate(const Source& src, LineCursor& cursor, const Line& line, std::string_view field1,
                 std::string_view marker, std::size_t n) {
    const std::string where = location(src.name, line.number);
    if (!have_previous_)
      throw InputError(where + ": replication " + quote_field(field1) +
                       " without a card before it; expected '=' lines directly after the card they copy");
    if (field1 == "=") {
      pattern_.reset("=", &src.name, src.index, line.number);
      read_lines(pattern_, src, cursor, line, marker, n);
      replicate_once(src, line.number, where);
      have_pattern_ = true;
      return;
    }
    const int count = replication_count(field1, fields_.data(), n, where);
    if (!have_pattern_)
      throw InputError(where + ": replication " + quote_field(field1) +
                       " does not follow a '=' replication line; expected the increments to repeat on the line before");
    // The repeat line itself may not have continuations; a continuation after it is an error below.
    for (int k = 0; k < count; ++k) replicate_once(src, line.number, where);
  }

  /// One card from card_ (the card before) and pattern_ (the '=' line), parsed.
  void replicate_once(const Source& src, std::uint32_t line_number, const std::string& where) {
    std::vector<std::string>& out = generated_[generated_which_ ^= 1];
    replicate_fields(card_, pattern_, where, out);
    std::vector<std::string_view> views(out.begin(), out.end());
    const std::string name(card_.name());
    card_.reset(name, &src.name, src.index, line_number);
    card_.append(views.data(), views.size(), line_number);
    dispatch();
  }

  void dispatch() {
    const std::string_view name = card_.name();
    int type = -1;
    if (name == last_name_) {
      type = last_type_;
    } else {
      type = find_card_type(name);
      last_name_.assign(name);
      last_type_ = type;
    }
    if (type < 0) {
      st_->note_unsupported_card(card_);
      return;
    }
    kCardTypes[type].parse(card_, *st_);
    ++(*counts_)[type];
  }

  using Counts = std::array<std::size_t, kNumCardTypes>;

  static void add_counts(fem::Model& model, const Counts& counts) {
    for (std::size_t i = 0; i < kNumCardTypes; ++i)
      if (counts[i] > 0) model.card_counts[std::string(kCardTypes[i].name)] += counts[i];
  }

  /// GRDSET for blank GRID fields; BAROR/BEAMOR for blank CBAR/CBEAM fields; PID = EID last.
  static void apply_defaults(fem::Model& model_, const nastran::ReaderState& state_) {
    const auto& gs = model_.grdset;
    if (gs.present) {
      for (std::size_t i = 0; i < model_.grids.size(); ++i) {
        const std::uint8_t blank = state_.grid_blank[i];
        auto& g = model_.grids[i];
        if (blank & 1) g.cp = gs.cp;
        if (blank & 2) g.cd = gs.cd;
        if (blank & 4) g.ps = gs.ps;
      }
    }
    for (auto& b : model_.bars) {
      const fem::BarDefaults& d = b.is_beam ? model_.beamor : model_.baror;
      if (b.pid == 0) b.pid = d.present && d.pid > 0 ? d.pid : b.id;
      if (!b.has_g0 && b.v.squaredNorm() == 0.0 && d.present) {
        b.has_g0 = d.has_g0;
        b.g0 = d.g0;
        b.v = d.v;
      }
      if (b.offt.empty()) b.offt = d.present ? d.offt : "GGG";
    }
  }

  static constexpr std::size_t kMaxIncludeDepth = 64;
  fem::Model& model_;
  nastran::ReaderState state_;
  CaseControlReader case_control_;
  IncludeResolver includes_;
  std::vector<std::unique_ptr<Source>> sources_;
  Section section_ = Section::Bulk;
  bool done_ = false;
  /// One BEGIN SUPER = n part as read (its cards may come in several sections).
  struct PartReading {
    PartReading(int seid, fem::CardRef begin, const std::vector<std::string>& files) : state(part.model, files) {
      part.seid = seid;
      part.begin = begin;
    }
    fem::Part part;
    nastran::ReaderState state;
    Counts counts{};
  };
  std::vector<std::unique_ptr<PartReading>> parts_;
  nastran::ReaderState* st_ = &state_;  ///< the residual's state_ or the part's being read
  Counts residual_counts_{};
  Counts* counts_ = &residual_counts_;           ///< cards read of each type, of the residual or the part being read
  bool in_part_ = false;       ///< inside BEGIN SUPER = n
  bool skipping_ = false;      ///< inside BEGIN SUPER = n MASSID = m: lines skipped
  bool executive_statements_ = false;
  std::filesystem::path main_dir_;  ///< relative ASSIGN file names start here
  Card card_;
  Card pattern_;                                ///< the last '=' replication line (and its continuations)
  std::array<std::vector<std::string>, 2> generated_;  ///< fields of the last two replicated cards
  unsigned generated_which_ = 0;
  bool have_previous_ = false;                  ///< card_ holds a card a replication line can copy
  bool have_pattern_ = false;                   ///< card_ was made by pattern_ ('=n' may repeat it)
  std::array<std::string_view, 8> fields_{};
  static constexpr std::size_t kMaxFreeFields = 1 + 8 * 32;  ///< field 1 and 32 card lines of data
  std::vector<std::string_view> overflow_;                  ///< data beyond one card line of a long free-field line
  std::vector<std::string_view> long_line_;                 ///< fields of a free-field line longer than 12
  std::string last_name_;
  int last_type_ = -1;
};

}  // namespace

CardParser find_card_parser(std::string_view name) {
  const int type = find_card_type(name);
  return type < 0 ? nullptr : kCardTypes[type].parse;
}

}  // namespace nastran

fem::Model read_nastran(const std::filesystem::path& path, const NastranReadOptions& options) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw InputError(path.string() + ": no such file; expected a Nastran deck");
  std::string text = nastran::load_text(path, "");
  std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
  if (ec) canonical = path.lexically_normal();
  fem::Model model;
  nastran::DeckReader reader(model, path.parent_path(), options.symbols);
  reader.read_main(std::move(text), path.string(), path.parent_path(), canonical);
  if (options.main_text) *options.main_text = reader.take_main_text();
  if (options.finalize) fem::finalize(model);
  return model;
}

fem::Model read_nastran_text(std::string_view text, const std::string& name, const std::filesystem::path& dir,
                             const NastranReadOptions& options) {
  std::string copy(text);
  if (copy.find('\t') != std::string::npos) nastran::expand_tabs(copy);
  fem::Model model;
  nastran::DeckReader reader(model, dir, options.symbols);
  reader.read_main(std::move(copy), name, dir, dir / name);
  if (options.main_text) *options.main_text = reader.take_main_text();
  if (options.finalize) fem::finalize(model);
  return model;
}

}  // namespace seflex::io
