#include "seflex/io/gmsh_directives.hpp"

#include <climits>

#include "seflex/common/error.hpp"
#include "seflex/io/nastran_lines.hpp"
#include "seflex/io/nastran_number.hpp"

namespace seflex::io::gmsh {
namespace {

constexpr std::string_view kPrefix = "$seflex";

bool starts_with_prefix(std::string_view line) {
  if (line.size() <= kPrefix.size()) return false;
  for (std::size_t i = 0; i < kPrefix.size(); ++i) {
    char c = line[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != kPrefix[i]) return false;
  }
  return line[kPrefix.size()] == ' ' || line[kPrefix.size()] == '\t';
}

class DirectiveLine {
 public:
  DirectiveLine(std::string_view text, const std::string& file, int line) : file_(file), line_(line) {
    std::size_t i = 0;
    while (i < text.size()) {
      while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r')) ++i;
      if (i >= text.size()) break;
      if (text[i] == '"') {
        const std::size_t close = text.find('"', i + 1);
        if (close == std::string_view::npos) fail("a name in double quotes has no closing quote", "a closing \"");
        tokens_.emplace_back(text.substr(i + 1, close - i - 1));
        i = close + 1;
      } else {
        const std::size_t start = i;
        while (i < text.size() && text[i] != ' ' && text[i] != '\t' && text[i] != '\r') ++i;
        tokens_.emplace_back(text.substr(start, i - start));
      }
    }
  }

  std::size_t size() const { return tokens_.size(); }
  const std::string& operator[](std::size_t i) const { return tokens_[i]; }
  std::string upper(std::size_t i) const { return nastran::upper(tokens_[i]); }

  [[noreturn]] void fail(const std::string& problem, const std::string& expected) const {
    std::string head = std::string(kPrefix);
    for (std::size_t k = 0; k < tokens_.size() && k < 3; ++k) head += " " + tokens_[k];
    throw InputError(SourceRef{file_, line_}, head + ": " + problem + "; expected " + expected);
  }

  const std::string& need(std::size_t i, const char* what) const {
    if (i >= tokens_.size()) fail(std::string("no ") + what, what);
    return tokens_[i];
  }

  double number(std::size_t i, const char* what) const {
    const std::string& t = need(i, what);
    int n = 0;
    double x = 0;
    if (nastran::parse_int(t, n)) return n;
    if (nastran::parse_real(t, x)) return x;
    fail(std::string(what) + " is '" + t + "'", std::string("a number for ") + what);
  }

  int id(std::size_t i, const char* what) const {
    const std::string& t = need(i, what);
    int n = 0;
    if (!nastran::parse_int(t, n) || n <= 0) fail(std::string(what) + " is '" + t + "'", std::string("an id (integer > 0) for ") + what);
    return n;
  }

  void no_more(std::size_t n, const std::string& expected) const {
    if (tokens_.size() > n) fail("unexpected '" + tokens_[n] + "'", expected);
  }

  int line() const { return line_; }

 private:
  const std::string& file_;
  int line_;
  std::vector<std::string> tokens_;
};

void group_directive(const DirectiveLine& d, Directives& out) {
  using Kind = GroupDirective::Kind;
  GroupDirective g;
  g.line = d.line();
  g.group = d.need(1, "group name");
  if (g.group.empty()) d.fail("the group name is empty", "a physical group name");
  d.need(2, "keyword");
  g.keyword = d.upper(2);
  const std::string& k = g.keyword;
  if (k == "PSHELL" || k == "PROD") {
    g.kind = k == "PSHELL" ? Kind::Shell : Kind::Rod;
    g.pid = d.id(3, "PID");
    d.no_more(4, "nothing after the PID");
  } else if (k == "PBAR" || k == "PBARL" || k == "PBEAM" || k == "PBEAML") {
    g.kind = k == "PBAR" || k == "PBARL" ? Kind::Bar : Kind::Beam;
    g.pid = d.id(3, "PID");
    if (d.size() > 4) {
      if (d.size() != 7) d.fail("the orientation vector has " + std::to_string(d.size() - 4) + " components", "X1 X2 X3");
      g.v = Eigen::Vector3d(d.number(4, "X1"), d.number(5, "X2"), d.number(6, "X3"));
      if (!(g.v->squaredNorm() > 0.0)) d.fail("the orientation vector is zero", "a non-zero vector X1 X2 X3");
    }
  } else if (k == "CONM2") {
    g.kind = Kind::Mass;
    g.mass = d.number(3, "M");
    if (!(g.mass >= 0.0)) d.fail("M is negative", "a mass >= 0");
    static const char* names[6] = {"I11", "I21", "I22", "I31", "I32", "I33"};
    if (d.size() > 4) {
      if (d.size() != 10)
        d.fail("the inertia has " + std::to_string(d.size() - 4) + " terms", "M alone, or M I11 I21 I22 I31 I32 I33");
      for (std::size_t i = 0; i < 6; ++i) g.inertia[i] = d.number(4 + i, names[i]);
      for (std::size_t i : {0u, 2u, 5u})
        if (!(g.inertia[i] >= 0.0)) d.fail(std::string(names[i]) + " is negative", "moments of inertia >= 0");
    }
  } else if (k == "GRID") {
    g.kind = Kind::Grid;
    g.grid = d.id(3, "ID");
    d.no_more(4, "one grid id");
  } else if (k == "SET") {
    g.kind = Kind::Set;
    d.no_more(3, "nothing after SET");
  } else {
    d.fail("unknown keyword '" + d[2] + "'", "PSHELL, PBAR, PBARL, PBEAM, PBEAML, PROD, CONM2, GRID or SET");
  }
  out.groups.push_back(std::move(g));
}

void first_id(const DirectiveLine& d, std::optional<int>& value, int& line, const char* what) {
  if (value) d.fail(std::string("a second ") + what + " (the first is on line " + std::to_string(line) + ")", std::string("one ") + what);
  value = d.id(1, "N");
  line = d.line();
  d.no_more(2, "one number");
}

}  // namespace

std::string_view kind_name(GroupDirective::Kind kind) {
  switch (kind) {
    case GroupDirective::Kind::Shell: return "PSHELL";
    case GroupDirective::Kind::Bar: return "PBAR";
    case GroupDirective::Kind::Beam: return "PBEAM";
    case GroupDirective::Kind::Rod: return "PROD";
    case GroupDirective::Kind::Mass: return "CONM2";
    case GroupDirective::Kind::Grid: return "GRID";
    case GroupDirective::Kind::Set: return "SET";
  }
  return "?";
}

Directives parse_directives(std::string_view text, const std::string& file) {
  Directives out;
  std::size_t pos = 0;
  int number = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++number;
    if (line.empty() || line[0] != '$' || !starts_with_prefix(line)) continue;
    const DirectiveLine d(line.substr(kPrefix.size()), file, number);
    if (d.size() == 0) d.fail("nothing after $seflex", "group, set, first_grid or first_element");
    const std::string key = d.upper(0);
    if (key == "GROUP") {
      group_directive(d, out);
    } else if (key == "SET") {
      NamedSet s;
      s.name = d.need(1, "set name");
      s.line = number;
      for (std::size_t i = 2; i < d.size(); ++i) s.ids.push_back(d.id(i, "ID"));
      if (s.ids.empty()) d.fail("no grid ids", "at least one grid id after the set name");
      out.sets.push_back(std::move(s));
    } else if (key == "FIRST_GRID") {
      first_id(d, out.first_grid, out.first_grid_line, "first_grid");
    } else if (key == "FIRST_ELEMENT") {
      first_id(d, out.first_element, out.first_element_line, "first_element");
    } else {
      d.fail("unknown directive '" + d[0] + "'", "group, set, first_grid or first_element");
    }
  }
  return out;
}

}  // namespace seflex::io::gmsh
