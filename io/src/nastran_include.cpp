// Where an INCLUDE's file is (nastran_include.hpp).
#include "nastran_include.hpp"

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "seflex/common/error.hpp"

namespace seflex::io::nastran {
namespace {

bool name_char(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; }

bool same_name(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if ((a[i] | 0x20) != (b[i] | 0x20)) return false;  // names: letters, digits, '_' only
  return true;
}

/// Both files hold the same bytes (false if either cannot be read).
bool same_content(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ea, eb;
  if (std::filesystem::file_size(a, ea) != std::filesystem::file_size(b, eb) || ea || eb) return false;
  std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
  if (!fa || !fb) return false;
  return std::equal(std::istreambuf_iterator<char>(fa), std::istreambuf_iterator<char>(),
                    std::istreambuf_iterator<char>(fb), std::istreambuf_iterator<char>());
}

bool file_exists(const std::filesystem::path& p) {
  std::error_code ec;
  return std::filesystem::exists(p, ec);
}

std::string shown(const std::filesystem::path& p) { return p.lexically_normal().string(); }

}  // namespace

bool is_name(std::string_view s) {
  if (s.empty() || (s[0] >= '0' && s[0] <= '9')) return false;
  for (const char c : s)
    if (!name_char(c)) return false;
  return true;
}

IncludeResolver::IncludeResolver(std::filesystem::path main_dir, const std::vector<NastranSymbol>& symbols)
    : main_dir_(std::move(main_dir)) {
  for (const NastranSymbol& s : symbols) {
    const std::string what = "logical symbol " + s.name + "=" + s.value;
    if (!is_name(s.name))
      throw InputError(what + ": '" + s.name + "' is not a name; expected letters, digits and '_' (not starting with a digit)");
    if (s.value.empty()) throw InputError(what + ": blank; expected a folder");
    // $VAR or ${VAR}: a symbol defined before this one, else an environment variable (MSC expands
    // environment variables only inside symbol definitions)
    std::string value;
    for (std::size_t i = 0; i < s.value.size();) {
      if (s.value[i] != '$') {
        value += s.value[i++];
        continue;
      }
      const bool braced = i + 1 < s.value.size() && s.value[i + 1] == '{';
      const std::size_t begin = i + (braced ? 2 : 1);
      std::size_t end = begin;
      while (end < s.value.size() && name_char(s.value[end])) ++end;
      const std::string var = s.value.substr(begin, end - begin);
      if (var.empty() || (braced && (end >= s.value.size() || s.value[end] != '}')))
        throw InputError(what + ": '$' at character " + std::to_string(i + 1) + " is not followed by a name; expected $NAME or ${NAME}");
      if (const Symbol* before = find_symbol(var))
        value += before->value;
      else if (const char* env = std::getenv(var.c_str()))
        value += env;
      else
        throw InputError(what + ": $" + var + " is neither a logical symbol given before it nor an environment variable");
      i = end + (braced ? 1 : 0);
    }
    symbols_.push_back({s.name, std::move(value)});
  }
}

const IncludeResolver::Symbol* IncludeResolver::find_symbol(std::string_view name) const {
  for (auto it = symbols_.rbegin(); it != symbols_.rend(); ++it)  // the last definition counts
    if (same_name(it->name, name)) return &*it;
  return nullptr;
}

IncludeTarget IncludeResolver::resolve(const std::string& name, const std::filesystem::path& including_dir,
                                       const std::string& where) const {
  // NAME:path, a logical symbol
  const std::size_t colon = name.find(':');
  if (colon != std::string::npos && is_name(std::string_view(name).substr(0, colon))) {
    const std::string symbol = name.substr(0, colon);
    std::string rest = name.substr(colon + 1);
    while (!rest.empty() && rest.front() == '/') rest.erase(0, 1);
    std::string folder, from;
    if (const Symbol* s = find_symbol(symbol)) {
      folder = s->value;
      from = "logical symbol " + symbol + " = " + folder;
    } else if (const char* env = std::getenv(symbol.c_str()); env != nullptr && *env != '\0') {
      folder = env;
      from = "environment variable " + symbol + " = " + folder;
    } else if (symbol.size() == 1) {
      throw InputError(where + ": '" + symbol + ":' is a Windows drive; expected a path on this machine, or the drive "
                       "mapped to a folder: --symbol " + symbol + "=DIR");
    } else {
      throw InputError(where + ": logical symbol " + symbol + " is not defined; expected --symbol " + symbol +
                       "=DIR (MSC Nastran: symbol=" + symbol + "=DIR in an rc file) or an environment variable " + symbol);
    }
    const std::filesystem::path path = std::filesystem::path(folder) / rest;
    if (!file_exists(path)) throw InputError(where + ": the file does not exist; tried " + shown(path) + " (" + from + ")");
    return {path, {}};
  }
  const std::filesystem::path relative(name);
  if (relative.is_absolute()) {
    if (!file_exists(relative)) throw InputError(where + ": the file does not exist; tried " + shown(relative));
    return {relative, {}};
  }
  // relative: the main deck's folder, then the including file's
  const std::filesystem::path main = main_dir_ / relative, local = including_dir / relative;
  const bool one_place = main.lexically_normal() == local.lexically_normal();
  const bool in_main = file_exists(main), in_local = !one_place && file_exists(local);
  if (in_main) {
    IncludeTarget t{main, {}};
    std::error_code ec;
    if (in_local && !std::filesystem::equivalent(main, local, ec) && !same_content(main, local))
      t.warning = where + ": read " + shown(main) + " (relative to the main deck's folder, as MSC Nastran reads it); " +
                  shown(local) + " (relative to the including file's folder) exists too and differs";
    return t;
  }
  if (in_local) return {local, {}};
  throw InputError(where + ": the file does not exist; tried " + shown(main) + " (relative to the main deck's folder)" +
                   (one_place ? std::string() : " and " + shown(local) + " (relative to the including file's folder)") +
                   "; expected a path relative to " + (one_place ? "it" : "one of them") +
                   ", an absolute path, or SYMBOL:path");
}

}  // namespace seflex::io::nastran

namespace seflex::io {

NastranSymbol parse_nastran_symbol(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || !nastran::is_name(std::string_view(text).substr(0, eq)))
    throw InputError("logical symbol '" + text + "': expected NAME=FOLDER (NAME of letters, digits and '_', not starting "
                     "with a digit), e.g. Satellite_V02_BULK=/data/Satellite_V02/BULK");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

}  // namespace seflex::io
