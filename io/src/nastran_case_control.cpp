#include "seflex/io/nastran_case_control.hpp"

#include <charconv>

#include "seflex/common/error.hpp"
#include "seflex/io/nastran_card.hpp"
#include "seflex/io/nastran_cards.hpp"
#include "seflex/io/nastran_number.hpp"

namespace seflex::io::nastran {
namespace {

/// `key` names `command` if equal or an abbreviation of at least four letters (Nastran's rule).
bool is_command(std::string_view key, std::string_view command) {
  if (key == command) return true;
  return key.size() >= 4 && key.size() < command.size() && command.substr(0, key.size()) == key;
}

/// Case-control commands that select analysis input seflex does not use, in full (abbreviable to four
/// letters); they are kept in Subcase::other so that a solution that needs them can refuse the deck.
constexpr std::string_view kSelectionCommands[] = {
    "TEMPERATURE", "DLOAD",    "DEFORM",   "SUPORT1",  "BC",        "STATSUB",   "SDAMPING", "FREQUENCY",
    "TSTEP",       "TSTEPNL",  "NLPARM",   "CMETHOD",  "RANDOM",    "IC",        "DESSUB",   "DESOBJ",
    "DESGLB",      "ANALYSIS", "TRIM",     "GUST",     "FMETHOD",   "DIVERG",    "AUXMODEL", "ADAPT",
    "NONLINEAR",   "SMETHOD",  "RGYRO",    "AXISYMMETRIC", "HARMONICS", "BCONTACT", "BCSET", "P2G",
    "K2PP",        "M2PP",     "B2GG",     "B2PP",     "K42GG",     "TFL",       "RESVEC",   "SEALL",
    "SUPER",       "MFLUID",   "EBDSET",   "DRSPAN"};

std::string_view first_word(std::string_view s) {
  std::size_t e = 0;
  while (e < s.size() && s[e] != ' ' && s[e] != ',' && s[e] != '=' && s[e] != '(') ++e;
  return s.substr(0, e);
}

}  // namespace

bool CaseControlReader::executive_line(const Line& line, const std::string& file, std::uint32_t) {
  const std::string t = upper(trim(line.text));
  if (t == "CEND") return true;
  const std::string_view word = first_word(t);
  if (word == "ASSIGN") assign(std::string(trim(line.text)), location(file, line.number));
  if (word == "SOL") {
    std::string_view rest = trim(std::string_view(t).substr(3));
    if (!rest.empty() && rest[0] == ',') rest = trim(rest.substr(1));
    model_.case_control.sol = std::string(first_word(rest));
  }
  return false;
}

// ASSIGN INPUTT4='path',UNIT=n[,FORM=FORMATTED|UNFORMATTED][,...]; other ASSIGNs (OUTPUT2, DBALL,
// ...) are not kept. The path keeps its case; the keywords may be in any case and spacing.
void CaseControlReader::assign(const std::string& text, const std::string& where) {
  std::string_view rest = trim(std::string_view(text).substr(6));
  const std::size_t eq = rest.find('=');
  if (eq == std::string_view::npos || upper(trim(rest.substr(0, eq))) != "INPUTT4") return;
  rest = trim(rest.substr(eq + 1));
  AssignedUnit a;
  a.where = where;
  std::string_view options;
  if (!rest.empty() && (rest[0] == '\'' || rest[0] == '"')) {
    const std::size_t close = rest.find(rest[0], 1);
    if (close == std::string_view::npos)
      throw InputError(where + ": ASSIGN INPUTT4: the file name " + quote_field(rest) + " has no closing quote; expected INPUTT4='file',UNIT=n");
    a.path = std::string(rest.substr(1, close - 1));
    options = rest.substr(close + 1);
  } else {
    const std::size_t comma = rest.find(',');
    a.path = std::string(trim(rest.substr(0, comma)));
    options = comma == std::string_view::npos ? std::string_view() : rest.substr(comma);
  }
  if (a.path.empty()) throw InputError(where + ": ASSIGN INPUTT4: no file name; expected INPUTT4='file',UNIT=n");
  while (!options.empty()) {
    options = trim(options);
    if (!options.empty() && options[0] == ',') options = trim(options.substr(1));
    const std::size_t comma = options.find(',');
    const std::string_view opt = trim(options.substr(0, comma));
    options = comma == std::string_view::npos ? std::string_view() : options.substr(comma);
    const std::size_t e = opt.find('=');
    if (e == std::string_view::npos || upper(trim(opt.substr(0, e))) != "UNIT") continue;
    const std::string_view v = trim(opt.substr(e + 1));
    int unit = 0;
    const auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), unit);
    if (ec != std::errc() || p != v.data() + v.size() || unit <= 0)
      throw InputError(where + ": ASSIGN INPUTT4, UNIT: got " + quote_field(v) + "; expected a Fortran unit number > 0");
    a.unit = unit;
  }
  if (a.unit == 0) throw InputError(where + ": ASSIGN INPUTT4='" + a.path + "': no UNIT; expected INPUTT4='file',UNIT=n");
  for (const auto& b : assigned_)
    if (b.unit == a.unit)
      throw InputError(where + ": ASSIGN INPUTT4: UNIT " + std::to_string(a.unit) + " is assigned already at " + b.where +
                       "; expected one file per unit");
  assigned_.push_back(a);
}

void CaseControlReader::case_line(const Line& line, const std::string& file, std::uint32_t file_index) {
  const std::string_view t = trim(line.text);
  if (t.empty()) return;
  if (pending_.empty()) {
    pending_line_ = line.number;
    pending_file_ = file;
    pending_file_index_ = file_index;
  }
  pending_ += std::string(t);
  const std::string key = upper(first_word(trim(pending_)));
  const bool text_command = is_command(key, "TITLE") || is_command(key, "SUBTITLE") || is_command(key, "LABEL");
  if (!text_command && pending_.back() == ',') return;  // continued on the next line
  std::string text;
  text.swap(pending_);
  command(text, pending_file_, pending_file_index_, pending_line_);
}

void CaseControlReader::command(const std::string& text, const std::string& file, std::uint32_t file_index,
                                std::uint32_t line) {
  const std::string where = location(file, line);
  const std::string u = upper(text);
  const std::string key(first_word(u));
  if (is_command(key, "SUBCASE")) {
    std::string_view rest = trim(std::string_view(u).substr(u.find(key) + key.size()));
    if (!rest.empty() && rest[0] == '=') rest = trim(rest.substr(1));  // "SUBCASE = 1" (ZONA's decks; pyNastran reads it)
    int id = 0;
    const auto [p, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), id);
    if (ec != std::errc() || p != rest.data() + rest.size() || id <= 0)
      throw InputError(where + ": case control SUBCASE: got " + quote_field(rest) + "; expected a subcase id (integer > 0)");
    for (const auto& s : model_.case_control.subcases)
      if (s.id == id) throw InputError(where + ": case control SUBCASE " + std::to_string(id) + " appears twice; expected unique subcase ids");
    fem::Subcase s;
    s.id = id;
    s.ref = {file_index, line};
    model_.case_control.subcases.push_back(s);
    in_subcase_ = true;
    return;
  }
  if (key == "PARAM") {
    fem::Param p;
    std::string_view rest = trim(std::string_view(text).substr(5));
    std::vector<std::string> words;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= rest.size(); ++i) {
      if (i == rest.size() || rest[i] == ',' || rest[i] == ' ') {
        const std::string_view w = trim(rest.substr(start, i - start));
        if (!w.empty()) words.push_back(param_value(w));
        start = i + 1;
      }
    }
    if (words.size() < 2 || classify(words[0]) != FieldKind::Text)
      throw InputError(where + ": case control PARAM: got " + quote_field(rest) + "; expected PARAM,NAME,VALUE");
    p.name = words[0];
    p.values.assign(words.begin() + 1, words.end());
    p.ref = {file_index, line};
    model_.params.push_back(std::move(p));
    return;
  }
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos) return;  // ECHOON, OUTPUT(PLOT), BEGIN ... : nothing seflex keeps
  const std::string value(trim(std::string_view(text).substr(eq + 1)));
  fem::Subcase& sc = current();
  if (is_command(key, "TITLE") || is_command(key, "SUBTITLE") || is_command(key, "LABEL")) {
    if (is_command(key, "LABEL")) {
      sc.label = value;
    } else if (!in_subcase_) {
      (is_command(key, "TITLE") ? model_.case_control.title : model_.case_control.subtitle) = value;
    }
    return;
  }
  auto set_id = [&](std::optional<int>& target, const char* name) {
    int id = 0;
    const auto [p, ec] = std::from_chars(value.data(), value.data() + value.size(), id);
    if (ec != std::errc() || p != value.data() + value.size() || id <= 0)
      throw InputError(where + ": case control " + name + ": got " + quote_field(value) + "; expected a set id (integer > 0)");
    target = id;
  };
  if (is_command(key, "TEMPERATURE")) {  // TEMPERATURE(LOAD | BOTH) or bare: the thermal load set
    const std::size_t open = u.find('('), close = u.find(')');
    std::string describer;
    if (open != std::string::npos && open < eq && close != std::string::npos && close < eq && open < close)
      describer = std::string(trim(std::string_view(u).substr(open + 1, close - open - 1)));
    if (describer.empty() || describer == "LOAD" || describer == "BOTH")
      return set_id(sc.temperature, describer.empty() ? "TEMPERATURE" : ("TEMPERATURE(" + describer + ")").c_str());
  }
  for (const std::string_view command : kSelectionCommands) {
    if (!(key == command || is_command(key, command))) continue;
    fem::CaseCommand c;
    c.name = std::string(command);
    const std::size_t open = u.find('('), close = u.find(')');
    if (open != std::string::npos && open < eq && close != std::string::npos && close < eq && open < close)
      c.name += "(" + std::string(trim(std::string_view(u).substr(open + 1, close - open - 1))) + ")";
    c.value = value;
    c.ref = {file_index, line};
    sc.other.push_back(std::move(c));
    return;
  }
  if (key == "SPC") return set_id(sc.spc, "SPC");
  if (key == "MPC") return set_id(sc.mpc, "MPC");
  if (is_command(key, "LOAD")) return set_id(sc.load, "LOAD");
  if (is_command(key, "METHOD")) return set_id(sc.method, "METHOD");
  if (key == "K2GG" || key == "M2GG") {
    auto& names = key == "K2GG" ? sc.k2gg : sc.m2gg;
    names.clear();
    std::size_t start = 0;
    const std::string uv = upper(value);
    for (std::size_t i = 0; i <= uv.size(); ++i) {
      if (i != uv.size() && uv[i] != ',') continue;
      const std::string_view term = trim(std::string_view(uv).substr(start, i - start));
      start = i + 1;
      if (term.empty()) continue;
      if (term.find('*') != std::string_view::npos || classify(term) != FieldKind::Text)
        throw InputError(where + ": case control " + key + ": got " + quote_field(term) +
                         "; expected DMIG matrix names (scale factors are not supported)");
      names.emplace_back(term);
    }
  }
}

void CaseControlReader::finish() {
  if (!pending_.empty()) {  // a trailing comma on the last command: read it as it stands
    std::string text;
    text.swap(pending_);
    text.pop_back();
    command(text, pending_file_, pending_file_index_, pending_line_);
  }
  auto& cc = model_.case_control;
  for (auto& s : cc.subcases) {
    if (!s.spc) s.spc = cc.global.spc;
    if (!s.load) s.load = cc.global.load;
    if (!s.method) s.method = cc.global.method;
    if (!s.mpc) s.mpc = cc.global.mpc;
    if (!s.temperature) s.temperature = cc.global.temperature;
    if (s.k2gg.empty()) s.k2gg = cc.global.k2gg;
    if (s.m2gg.empty()) s.m2gg = cc.global.m2gg;
    if (s.label.empty()) s.label = cc.global.label;
    for (const auto& g : cc.global.other) {  // inherited unless the subcase gives the same command
      bool given = false;
      for (const auto& o : s.other) given = given || o.name == g.name;
      if (!given) s.other.push_back(g);
    }
  }
}

}  // namespace seflex::io::nastran
