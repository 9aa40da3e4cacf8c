#pragma once
// What seflex takes from a gmsh model: nodes, physical groups and the elements of their entities,
// as plain data. load_gmsh_mesh fills it: a .msh file with seflex's own reader (read_msh,
// io/src/gmsh_msh_reader.cpp), a .geo script with the gmsh library (io/src/gmsh_session.cpp);
// io/src/gmsh_model.cpp turns it into a fem::Model with the companion file's directives.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "seflex/io/model_reader.hpp"

namespace seflex::io::gmsh {

/// Elements of one type on one entity (gmsh's element type numbers: 1 = 2-node line, 2 = 3-node
/// triangle, 3 = 4-node quadrangle, 15 = point, ...).
struct ElementBlock {
  int type = 0;
  std::string type_name;  ///< gmsh's name, e.g. "Triangle 6"
  int dim = 0, order = 1, nodes_per_element = 0;
  int entity_tag = 0;              ///< entity of dimension `dim` holding these elements
  std::vector<std::size_t> nodes;  ///< nodes_per_element tags per element, concatenated
  std::size_t count() const {
    return nodes_per_element > 0 ? nodes.size() / static_cast<std::size_t>(nodes_per_element) : 0;
  }
};

struct PhysicalGroup {
  int dim = 0, tag = 0;
  std::string name;                  ///< may be empty (an unnamed group)
  std::vector<int> entities;         ///< ascending
  std::vector<ElementBlock> blocks;  ///< entity by entity, by ascending element type within one
};

struct MeshData {
  std::string file;  ///< the mesh as named by the caller (for messages)
  std::vector<std::size_t> node_tags;
  std::vector<double> coords;         ///< x y z per node, same order as node_tags
  std::vector<PhysicalGroup> groups;  ///< sorted by (dim, tag)
  std::size_t total_elements = 0;     ///< elements in the whole mesh, in groups or not
};

/// Read `path`: a .geo file with the gmsh library (meshed up to its dimension unless it holds a mesh
/// already; `parameters` set its ONELAB parameters: the file is parsed, the values set, and the file
/// parsed again), any other file with read_msh. Throws InputError naming the file.
MeshData load_gmsh_mesh(const std::filesystem::path& path, const std::vector<GmshParameter>& parameters);

/// seflex's reader of gmsh's MSH format: versions 2.2 (and 2.1), 4.1 and 4.0 (4.0 as text only, as
/// gmsh reads it), text or binary, binary in either byte order. It reads $MeshFormat,
/// $PhysicalNames, $Entities, $Nodes and $Elements and skips any other section; a partitioned mesh
/// is refused. Groups are what gmsh makes of the file: in format 4 the physical tags of $Entities, in
/// format 2 the first tag of every element (the physical group of its entity, the second tag). In
/// format 2 gmsh writes an element once per physical group of its entity: consecutive copies of an
/// element are read as one element of several groups. Every count is checked against the bytes left
/// in the file before anything is allocated for it. Throws InputError naming the file, the line (text)
/// or byte offset (binary), the section and what was expected.
MeshData read_msh(const std::filesystem::path& path);
/// The same on a file's bytes; `file` names it in messages.
MeshData read_msh_bytes(std::string_view bytes, const std::string& file);

/// A gmsh element type with a fixed number of nodes: its number in MSH files, gmsh's name ("Line 2",
/// "Triangle 6", ...), dimension, order and nodes per element.
struct ElementType {
  int type = 0;
  std::string_view name;
  int dim = 0, order = 0, nodes = 0;
};
/// Every such type gmsh 4.8 knows (tests/io/gmsh_msh_reader_test.cpp compares the table with the
/// library's own), ascending by number; polygons, polyhedra and gmsh's XFEM types have no fixed
/// number of nodes and are not in it.
const std::vector<ElementType>& element_types();
/// The type numbered `type`, or nullptr.
const ElementType* find_element_type(int type);

/// "surface", "curve", "point" or "volume" for a dimension.
const char* dimension_name(int dim);

/// The gmsh library itself (loaded with dlopen at the first use). It runs any file it opens that does
/// not start with $MeshFormat as a script, and a script can run programs: trusted input only. seflex
/// gives it .geo files (load_gmsh_mesh); tests and benchmarks compare read_msh with it.
namespace library {
/// What load_gmsh_mesh gets from a .geo file, for any file the library opens.
MeshData read(const std::filesystem::path& path, const std::vector<GmshParameter>& parameters);
/// Open `model` (meshed as read() meshes it) and save its mesh to `out` in MSH `version` (2.2, 4.0 or
/// 4.1), binary or text, as `gmsh model -format msh41 [-bin] -o out` does.
void write_msh(const std::filesystem::path& model, const std::vector<GmshParameter>& parameters,
               const std::filesystem::path& out, double version, bool binary);
/// The library's own description of every element type numbered 1 to `last` that it knows.
struct LibraryElementType {
  int type = 0;
  std::string name;
  int dim = 0, order = 0, nodes = 0;
};
std::vector<LibraryElementType> element_types(int last);
}  // namespace library

}  // namespace seflex::io::gmsh
