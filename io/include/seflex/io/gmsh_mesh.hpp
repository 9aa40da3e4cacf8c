#pragma once
// What seflex takes from a gmsh model: nodes, physical groups and the elements of their entities,
// as plain data. load_gmsh_mesh (io/src/gmsh_session.cpp, the only file that includes gmsh.h) fills
// it; io/src/gmsh_model.cpp turns it into a fem::Model with the companion file's directives.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "seflex/io/model_reader.hpp"

namespace seflex::io::gmsh {

/// Elements of one type on one entity (gmsh's element type numbers: 1 = 2-node line, 2 = 3-node
/// triangle, 3 = 4-node quadrangle, 15 = point, ...).
struct ElementBlock {
  int type = 0;
  std::string type_name;            ///< gmsh's name, e.g. "Triangle 6"
  int dim = 0, order = 1, nodes_per_element = 0;
  int entity_tag = 0;               ///< entity of dimension `dim` holding these elements
  std::vector<std::size_t> nodes;   ///< nodes_per_element tags per element, concatenated
  std::size_t count() const { return nodes_per_element > 0 ? nodes.size() / static_cast<std::size_t>(nodes_per_element) : 0; }
};

struct PhysicalGroup {
  int dim = 0, tag = 0;
  std::string name;                 ///< may be empty (an unnamed group)
  std::vector<int> entities;
  std::vector<ElementBlock> blocks;
};

struct MeshData {
  std::string file;                 ///< the mesh as named by the caller (for messages)
  std::vector<std::size_t> node_tags;
  std::vector<double> coords;       ///< x y z per node, same order as node_tags
  std::vector<PhysicalGroup> groups;  ///< sorted by (dim, tag)
  std::size_t total_elements = 0;   ///< elements in the whole mesh, in groups or not
};

/// Open `path` with gmsh (a .msh file, or a .geo file that is then meshed up to its dimension unless
/// it holds a mesh already) and extract nodes and physical groups. `parameters` set ONELAB
/// parameters of a .geo file (the file is parsed, the values set, and the file parsed again).
/// Throws InputError naming the file, with gmsh's own error text, if gmsh cannot read or mesh it.
MeshData load_gmsh_mesh(const std::filesystem::path& path, const std::vector<GmshParameter>& parameters);

/// "surface", "curve", "point" or "volume" for a dimension.
const char* dimension_name(int dim);

}  // namespace seflex::io::gmsh
