#pragma once
// `$seflex` directives: comment lines of a bulk-data file that Nastran ignores and seflex reads.
//
//   $seflex group NAME PSHELL PID                 surface group -> CQUAD4 / CTRIA3 with PSHELL PID
//   $seflex group NAME PBAR PID [X1 X2 X3]        curve group -> CBAR (PBARL also accepted) ...
//   $seflex group NAME PBEAM PID [X1 X2 X3]       ... CBEAM (PBEAML also accepted); orientation
//                                                   vector in basic, or the file's BAROR/BEAMOR
//   $seflex group NAME PROD PID                   curve group -> CROD
//   $seflex group NAME CONM2 M [I11 I21 I22 I31 I32 I33]   a CONM2 (CID 0, no offset) on every node
//   $seflex group NAME GRID ID                    the group's single node gets grid id ID
//   $seflex group NAME SET                        the group's nodes become Model::node_sets[NAME]
//   $seflex first_grid N                          ids of the other nodes start at N (default: one
//                                                   above the highest pinned or companion grid id)
//   $seflex first_element N                       element ids start at N (default: one above the
//                                                   highest companion element id, or 1)
//   $seflex set NAME ID ID ...                    (Nastran decks) a named node set of grid ids
//
// A line is a directive if it starts with `$seflex` (any case) and a blank. Keywords are
// case-insensitive; group and set names are case-sensitive, as gmsh stores them; a name with blanks
// is written in double quotes. Numbers are integers or reals in C or Nastran form (1.98e-4, 1.98-4).
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "seflex/fem/model.hpp"

namespace seflex::io::gmsh {

struct GroupDirective {
  enum class Kind : std::uint8_t { Shell, Bar, Beam, Rod, Mass, Grid, Set };
  Kind kind = Kind::Set;
  std::string group;                ///< physical group name
  std::string keyword;              ///< as written, upper case (PSHELL, PBAR, PBARL, CONM2, ...)
  int line = 0;                     ///< 1-based line in the file
  int pid = 0;                      ///< Shell, Bar, Beam, Rod
  std::optional<Eigen::Vector3d> v; ///< Bar, Beam: orientation vector (basic)
  double mass = 0;                  ///< Mass
  std::array<double, 6> inertia{};  ///< Mass: I11 I21 I22 I31 I32 I33
  int grid = 0;                     ///< Grid: the id
};

struct NamedSet {
  std::string name;
  std::vector<int> ids;
  int line = 0;
};

struct Directives {
  std::vector<GroupDirective> groups;
  std::vector<NamedSet> sets;
  std::optional<int> first_grid, first_element;
  int first_grid_line = 0, first_element_line = 0;
};

/// Every `$seflex` line of `text`; `file` names it in errors. Throws InputError "file:line: $seflex
/// ...: problem; expected ..." for an unknown keyword, a missing or malformed value, or a
/// repeated first_grid / first_element.
Directives parse_directives(std::string_view text, const std::string& file);

/// Add `$seflex set` node sets to model.node_sets (merged with sets of the same name). Throws
/// InputError "file:line" for an id that is not a GRID of the model.
void add_named_sets(fem::Model& model, const std::vector<NamedSet>& sets, const std::string& file);

/// Short name of a directive kind for messages ("PSHELL", "CONM2", ...).
std::string_view kind_name(GroupDirective::Kind kind);

}  // namespace seflex::io::gmsh
