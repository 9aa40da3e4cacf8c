#include "seflex/io/model_reader.hpp"

#include <string>
#include <string_view>

#include "seflex/common/error.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/io/gmsh.hpp"
#include "seflex/io/gmsh_directives.hpp"
#include "seflex/io/nastran.hpp"
#include "seflex/io/nastran_lines.hpp"
#include "seflex/io/nastran_number.hpp"

namespace seflex::io {
namespace {

/// Does a line of `text` start with "$seflex" (any case)? A quick test before parse_directives splits
/// every line: '$' is rare in bulk data.
bool has_directive(std::string_view text) {
  constexpr std::string_view kPrefix = "$seflex";
  for (std::size_t p = text.find('$'); p != std::string_view::npos; p = text.find('$', p + 1)) {
    if (p > 0 && text[p - 1] != '\n') continue;
    if (text.size() - p < kPrefix.size()) return false;
    bool same = true;
    for (std::size_t i = 1; i < kPrefix.size() && same; ++i) same = (text[p + i] | 0x20) == kPrefix[i];
    if (same) return true;
  }
  return false;
}

}  // namespace

bool is_gmsh_path(const std::filesystem::path& path) {
  std::string e = path.extension().string();
  for (char& c : e) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return e == ".msh" || e == ".geo";
}

fem::Model read_model(const std::filesystem::path& path, const ModelReadOptions& options) {
  if (is_gmsh_path(path)) return read_gmsh(path, options);
  if (!options.parameters.empty())
    throw InputError(path.string() + ": parameter '" + options.parameters.front().name +
                     "' given for a Nastran deck; expected parameters only for a gmsh .geo file");
  if (options.properties)
    throw InputError(path.string() + ": a property file (" + options.properties->string() +
                     ") given for a Nastran deck; expected one only for a gmsh .msh or .geo file");
  NastranReadOptions nastran_options;
  nastran_options.finalize = false;
  std::string text;  // the deck, read once (a 1M-element deck is 100 MB)
  nastran_options.main_text = &text;
  nastran_options.symbols = options.symbols;
  fem::Model model = read_nastran(path, nastran_options);
  const gmsh::Directives directives =
      has_directive(text) ? gmsh::parse_directives(text, path.string()) : gmsh::Directives{};
  if (!directives.groups.empty() || directives.first_grid || directives.first_element) {
    const int line = !directives.groups.empty() ? directives.groups.front().line
                                                : std::max(directives.first_grid_line, directives.first_element_line);
    throw InputError(SourceRef{path.string(), line},
                     "$seflex group / first_grid / first_element in a Nastran deck; expected these only in the property "
                     "file of a gmsh mesh ($seflex set is the one directive of a deck)");
  }
  gmsh::add_named_sets(model, directives.sets, path.string());
  if (options.finalize) fem::finalize(model);
  return model;
}

GmshParameter parse_gmsh_parameter(const std::string& text) {
  const std::size_t eq = text.find('=');
  auto fail = [&](const std::string& problem) {
    throw InputError("parameter '" + text + "': " + problem + "; expected NAME=VALUE, e.g. refine=8");
  };
  if (eq == std::string::npos) fail("no '='");
  GmshParameter p;
  p.name = std::string(nastran::trim(std::string_view(text).substr(0, eq)));
  const std::string value(nastran::trim(std::string_view(text).substr(eq + 1)));
  if (p.name.empty() || !((p.name[0] >= 'a' && p.name[0] <= 'z') || (p.name[0] >= 'A' && p.name[0] <= 'Z') || p.name[0] == '_'))
    fail("the name must start with a letter or '_'");
  for (const char c : p.name)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'))
      fail("the name has a character other than letters, digits and '_'");
  int i = 0;
  if (nastran::parse_int(value, i)) {
    p.value = i;
  } else if (!nastran::parse_real(value, p.value)) {
    fail("the value '" + value + "' is not a number");
  }
  return p;
}

}  // namespace seflex::io
