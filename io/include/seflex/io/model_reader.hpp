#pragma once
// One entry point for every FE model seflex reads:
//
//   fem::Model model = seflex::io::read_model("meshes/panel.geo", {.parameters = {{"refine", 8}}});
//
// Dispatch on the extension (case-insensitive): .msh and .geo -> gmsh (io/gmsh.hpp, with its companion
// bulk-data file), anything else -> a Nastran deck (io/nastran.hpp). The model comes back finalized
// (fem::finalize) unless options.finalize is false.
//
// Named node sets in Nastran decks: comment lines `$seflex set NAME ID ID ...` in the main deck (not
// in its INCLUDEs) become Model::node_sets[NAME] (`seflex convert` writes them so that the node sets
// of a gmsh model survive a round trip through Nastran). docs/gmsh-input.md describes both.
//
// Errors: InputError naming the file (and line, group or card). Options that do not apply (gmsh
// parameters or a property file for a Nastran deck) are an InputError too, not silently ignored.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "seflex/fem/model.hpp"
#include "seflex/io/nastran.hpp"

namespace seflex::io {

/// A value for a parameter of a .geo file (a ONELAB number, as set in the gmsh GUI's parameter list).
struct GmshParameter {
  std::string name;
  double value = 0;
};

struct ModelReadOptions {
  /// gmsh models: the companion bulk-data file; default `<mesh stem>.props.bdf` beside the mesh.
  std::optional<std::filesystem::path> properties;
  /// .geo models: values of the file's ONELAB parameters (DefineConstant[x = {v, Name "Path/x"}]),
  /// named by the last part of the Name or the full Name; an unknown name is an InputError.
  std::vector<GmshParameter> parameters;
  /// Run fem::finalize (ids, references, coordinate systems).
  bool finalize = true;
  /// Logical symbols for INCLUDE names `NAME:path` (NastranReadOptions::symbols), in the deck and in
  /// a gmsh model's property file.
  std::vector<NastranSymbol> symbols;
};

/// True if `path` is read as a gmsh model (.msh or .geo, any case).
bool is_gmsh_path(const std::filesystem::path& path);

/// Read the model at `path` (gmsh or Nastran, by extension). Throws InputError.
fem::Model read_model(const std::filesystem::path& path, const ModelReadOptions& options = {});

/// Parse "NAME=VALUE" (a command-line --set argument) into a GmshParameter; throws InputError naming
/// `text` if it is not an identifier, '=' and a number.
GmshParameter parse_gmsh_parameter(const std::string& text);

}  // namespace seflex::io
