#pragma once
// gmsh meshes (.msh format 2.2 or 4, read by seflex's own reader; or .geo scripts, meshed on the fly
// by the gmsh library) + a companion bulk-data file -> fem::Model.
//
//   fem::Model m = seflex::io::read_gmsh("meshes/panel.geo");   // uses meshes/panel.props.bdf
//
// The mesh gives the nodes (GRID) and elements; physical groups say what they are. The companion
// file is ordinary Nastran bulk data (PSHELL, PBAR, MAT1, ... read by io/nastran.hpp) plus comment
// directives that map group names to properties, masses, node ids and node sets:
//
//   $seflex group plate    PSHELL 100               2-node lines / 3-node triangles / 4-node quads
//   $seflex group edges    PBAR 10 1. 0. 0.         of the group -> CTRIA3/CQUAD4 or CBAR (CBEAM, CROD)
//   $seflex group masses   CONM2 0.55 1.98e-4 0. 1.98e-4 0. 0. 1.98e-4   a CONM2 on every node
//   $seflex group hinge1   GRID 1                   the group's one node gets id 1
//   $seflex group edge_a   SET                      the group's nodes -> Model::node_sets["edge_a"]
//
// Every physical group of points is a node set; every group of curves or surfaces needs a mapping.
// docs/gmsh-input.md has the full rules (numbering, errors) and a complete example.
//
// The gmsh library (.geo files only) is a process-wide singleton: its reads are serialised, and one
// from inside another (same thread) is an InvariantError. It prints nothing; its messages are kept and
// quoted in errors.
#include <filesystem>

#include "seflex/fem/model.hpp"
#include "seflex/io/model_reader.hpp"

namespace seflex::io {

/// The companion file of a mesh when none is given: `<stem>.props.bdf` in the mesh's folder.
std::filesystem::path default_properties_path(const std::filesystem::path& mesh);

/// Read a gmsh model (`options.properties` or the default companion file). Throws InputError naming
/// the file, line, physical group or element type for anything wrong with the input.
fem::Model read_gmsh(const std::filesystem::path& mesh, const ModelReadOptions& options = {});

}  // namespace seflex::io
