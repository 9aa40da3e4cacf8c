#pragma once
// Where the file of an INCLUDE statement is, as MSC Nastran finds it (docs/nastran-support.md, INCLUDE):
//   - `NAME:path`: a logical symbol (MSC Installation and Operations Guide, "Using Filenames and
//     Logical Symbols"): NAME's folder, then path. NAME from NastranReadOptions::symbols (MSC's
//     `symbol=NAME=VALUE` keyword, seflex's --symbol; a value may use `$VAR` / `${VAR}` of a symbol
//     given before it or of an environment variable, as MSC expands them in a symbol definition), else
//     the environment variable NAME (as pyNastran reads such decks). A one-letter NAME with no symbol
//     of that name is a Windows drive: an error saying how to map it.
//   - an absolute path: itself.
//   - a relative path: against the main deck's folder first, then against the including file's folder
//     (MSC and pyNastran resolve nested INCLUDEs of paths against the main input's folder). When both
//     hold a file of that name and the two differ, the first is read and a warning says so.
// A file found nowhere is an InputError naming every place tried.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "seflex/io/nastran.hpp"

namespace seflex::io::nastran {

/// A symbol or environment variable name: a letter or '_', then letters, digits and '_'.
bool is_name(std::string_view s);

struct IncludeTarget {
  std::filesystem::path path;
  std::string warning;  ///< not empty: found in two places, which one is read and why
};

class IncludeResolver {
 public:
  /// Expands the symbols' values; throws InputError naming a symbol whose value uses an undefined
  /// `$VAR`, or whose name is not a name.
  IncludeResolver(std::filesystem::path main_dir, const std::vector<NastranSymbol>& symbols);

  /// The file of `INCLUDE 'name'` (name with '\' read as '/') in a file of folder `including_dir`;
  /// `where` ("deck.bdf:12: INCLUDE 'x'") starts error messages.
  IncludeTarget resolve(const std::string& name, const std::filesystem::path& including_dir, const std::string& where) const;

 private:
  struct Symbol {
    std::string name;   ///< as given
    std::string value;  ///< $VARs expanded
  };
  const Symbol* find_symbol(std::string_view name) const;
  std::filesystem::path main_dir_;
  std::vector<Symbol> symbols_;
};

}  // namespace seflex::io::nastran
