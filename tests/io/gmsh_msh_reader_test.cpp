// seflex's MSH reader (io::gmsh::read_msh) against the gmsh library itself: every format gmsh writes
// (2.2, 4.0 and 4.1, text and binary) is written by libgmsh from one model, then read by both; the
// nodes, the physical groups and the elements of their entities must be the same, exactly. Binary
// files in the other byte order (which gmsh writes only on a big-endian machine) are written here by
// hand and read by both. The table of element types is the library's.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <tuple>

#include "seflex/common/error.hpp"
#include "seflex/io/gmsh_mesh.hpp"
#include "test_support.hpp"

using namespace seflex;
namespace gmsh = seflex::io::gmsh;

namespace {

// Three surfaces (one of quadrangles, one of triangles, one in no group), ten curves, eight points;
// groups with several entities, entities in two groups (curve 3, point 1), entities in none (partial
// tagging: gmsh saves only the elements of entities in a group), an unnamed group (curve 77).
const char* kModel = R"(Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Point(5) = {2, 0, 0}; Point(6) = {2, 1, 0}; Point(7) = {3, 0, 0}; Point(8) = {3, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3}; Line(8) = {5, 7}; Line(9) = {7, 8}; Line(10) = {8, 6};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
Curve Loop(3) = {8, 9, 10, -6}; Plane Surface(3) = {3};
Transfinite Curve{1:10} = 3; Transfinite Surface{1}; Recombine Surface{1};
Physical Surface("plate") = {1, 2};
Physical Curve("edges") = {1, 3, 5};
Physical Curve("edge_set") = {3};
Physical Curve(77) = {9};
Physical Point("corner") = {1};
Physical Point("ends") = {1, 7};
)";

/// `x` as gmsh writes a coordinate in a text file (printf "%.16g").
std::string format_g16(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.16g", x);
  return buf;
}

using Node = std::tuple<std::size_t, double, double, double>;

std::vector<Node> sorted_nodes(const gmsh::MeshData& m) {
  std::vector<Node> n;
  for (std::size_t i = 0; i < m.node_tags.size(); ++i)
    n.emplace_back(m.node_tags[i], m.coords[3 * i], m.coords[3 * i + 1], m.coords[3 * i + 2]);
  std::sort(n.begin(), n.end());
  return n;
}

/// Nodes (tags and coordinates), groups (dimension, tag, name, entities) and their element blocks
/// (type, its description, entity, node tags) of `a` and `b`, compared exactly.
void expect_same(const gmsh::MeshData& a, const gmsh::MeshData& b) {
  EXPECT_EQ(sorted_nodes(a), sorted_nodes(b));
  EXPECT_EQ(a.total_elements, b.total_elements);
  ASSERT_EQ(a.groups.size(), b.groups.size());
  for (std::size_t i = 0; i < a.groups.size(); ++i) {
    const gmsh::PhysicalGroup &p = a.groups[i], &q = b.groups[i];
    SCOPED_TRACE("group (" + std::to_string(p.dim) + ", " + std::to_string(p.tag) + ") '" + p.name + "'");
    EXPECT_EQ(p.dim, q.dim);
    EXPECT_EQ(p.tag, q.tag);
    EXPECT_EQ(p.name, q.name);
    EXPECT_EQ(p.entities, q.entities);
    ASSERT_EQ(p.blocks.size(), q.blocks.size());
    for (std::size_t k = 0; k < p.blocks.size(); ++k) {
      const gmsh::ElementBlock &x = p.blocks[k], &y = q.blocks[k];
      EXPECT_EQ(x.type, y.type) << k;
      EXPECT_EQ(x.type_name, y.type_name) << k;
      EXPECT_EQ(std::tie(x.dim, x.order, x.nodes_per_element, x.entity_tag),
                std::tie(y.dim, y.order, y.nodes_per_element, y.entity_tag))
          << k;
      EXPECT_EQ(x.nodes, y.nodes) << k;
    }
  }
}

/// libgmsh's reading of a format 2 file, without the copies gmsh writes of an element for each more
/// group of its entity (each copy is the element before again: same entity, type and nodes), which
/// the library keeps as more elements; returns how many it removed.
std::size_t without_copies(gmsh::MeshData& m) {
  std::size_t removed = 0;
  for (auto& g : m.groups)
    for (auto& b : g.blocks) {
      const auto per = static_cast<std::size_t>(b.nodes_per_element);
      std::vector<std::size_t> kept;
      for (std::size_t e = 0; e < b.count(); ++e) {
        const auto first = b.nodes.begin() + static_cast<long>(e * per);
        if (!kept.empty() && std::equal(first, first + static_cast<long>(per), kept.end() - static_cast<long>(per))) {
          ++removed;
          continue;
        }
        kept.insert(kept.end(), first, first + static_cast<long>(per));
      }
      b.nodes = std::move(kept);
    }
  return removed;
}

}  // namespace

TEST(MshReader, ReadsEveryFormatGmshWritesAsTheLibraryReadsIt) {
  test::TempDir dir;
  const auto model = dir.write("model.geo", kModel);
  struct Format {
    const char* name;
    double version;
    bool binary;
  };
  gmsh::MeshData first;
  for (const Format f : {Format{"msh41", 4.1, false}, Format{"msh41_binary", 4.1, true}, Format{"msh22", 2.2, false},
                         Format{"msh22_binary", 2.2, true}, Format{"msh40", 4.0, false}}) {
    SCOPED_TRACE(f.name);
    const auto path = dir / (std::string(f.name) + ".msh");
    gmsh::library::write_msh(model, {}, path, f.version, f.binary);
    const gmsh::MeshData ours = gmsh::read_msh(path);
    gmsh::MeshData theirs = gmsh::library::read(path, {});
    // The model: 21 nodes; 5 groups of points, curves and surfaces; 4 quadrangles and 14 triangles on
    // the plate, 2 lines on each of curves 1, 3, 5 and 9, points 1 and 7 (what gmsh saves).
    EXPECT_EQ(ours.node_tags.size(), 21u);
    ASSERT_EQ(ours.groups.size(), 6u);
    EXPECT_EQ(ours.total_elements, 4u + 14u + 8u + 2u);
    EXPECT_EQ(ours.groups[0].name, "corner");
    EXPECT_EQ(ours.groups[1].entities, (std::vector<int>{1, 7}));
    EXPECT_EQ(ours.groups[2].entities, (std::vector<int>{1, 3, 5}));
    EXPECT_EQ(ours.groups[4].tag, 77);
    EXPECT_EQ(ours.groups[4].name, "");
    ASSERT_EQ(ours.groups[5].blocks.size(), 2u);  // surface 1: quadrangles; surface 2: triangles
    EXPECT_EQ(ours.groups[5].blocks[0].type, 3);
    EXPECT_EQ(ours.groups[5].blocks[0].count(), 4u);
    EXPECT_EQ(ours.groups[5].blocks[1].type, 2);
    EXPECT_EQ(ours.groups[5].blocks[1].count(), 14u);
    if (f.version < 3) {
      // The library keeps gmsh's copies of the lines of curve 3 (in 'edges' and 'edge_set') and of
      // point 1 (in 'corner' and 'ends'), in every group that holds them: 2 lines x 2 groups + 1
      // point x 2 groups. seflex reads each once.
      EXPECT_EQ(without_copies(theirs), 6u);
      EXPECT_EQ(theirs.total_elements, ours.total_elements + 3);
      theirs.total_elements = ours.total_elements;
    }
    expect_same(ours, theirs);
    // Every format gives the same mesh (gmsh numbers the nodes and elements the same way in all);
    // the same coordinates too, to the 16 significant digits gmsh writes in text files.
    if (first.groups.empty()) {
      first = ours;
    } else {
      gmsh::MeshData rounded = ours;
      for (double& x : rounded.coords) x = std::stod(format_g16(x));
      for (double& x : first.coords) x = std::stod(format_g16(x));
      expect_same(rounded, first);
    }
  }
}

namespace {

/// A small mesh in binary MSH (4.1 or 2.2) in either byte order, written here: gmsh writes the byte
/// order of the machine it runs on, so a big-endian file cannot come from it on this one.
class BinaryWriter {
 public:
  explicit BinaryWriter(bool big_endian) : big_(big_endian) {}
  BinaryWriter& text(const std::string& s) {
    out_ += s;
    return *this;
  }
  template <class T>
  BinaryWriter& number(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (big_ == (std::endian::native == std::endian::little)) std::reverse(b, b + sizeof(T));
    out_.append(b, sizeof(T));
    return *this;
  }
  BinaryWriter& i32(std::int32_t v) { return number(v); }
  BinaryWriter& u64(std::uint64_t v) { return number(v); }
  BinaryWriter& f64(double v) { return number(v); }
  const std::string& str() const { return out_; }

 private:
  bool big_;
  std::string out_;
};

const double kX[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, -0.25}, {2, 0.125, 0}};

/// Curve 5 (group 2 "edge": the line 1 2), surface 7 (group 1 "plate": the triangles 1 2 3 and 1 3 4,
/// the quadrangle 2 5 3 4), nodes 1-5.
std::string msh41_binary(bool big_endian) {
  BinaryWriter w(big_endian);
  w.text("$MeshFormat\n4.1 1 8\n").i32(1).text("\n$EndMeshFormat\n");
  w.text("$PhysicalNames\n2\n1 2 \"edge\"\n2 1 \"plate\"\n$EndPhysicalNames\n");
  w.text("$Entities\n").u64(0).u64(1).u64(1).u64(0);
  w.i32(5).f64(0).f64(0).f64(0).f64(1).f64(0).f64(0).u64(1).i32(2).u64(0);
  w.i32(7).f64(0).f64(0).f64(-0.25).f64(2).f64(1).f64(0.5).u64(1).i32(1).u64(0);
  w.text("\n$EndEntities\n$Nodes\n").u64(2).u64(5).u64(1).u64(5);
  w.i32(1).i32(5).i32(0).u64(2).u64(1).u64(2);
  for (int i : {0, 1})
    for (double c : kX[i]) w.f64(c);
  w.i32(2).i32(7).i32(0).u64(3).u64(3).u64(4).u64(5);
  for (int i : {2, 3, 4})
    for (double c : kX[i]) w.f64(c);
  w.text("\n$EndNodes\n$Elements\n").u64(3).u64(4).u64(1).u64(4);
  w.i32(1).i32(5).i32(1).u64(1).u64(1).u64(1).u64(2);
  w.i32(2).i32(7).i32(2).u64(2).u64(2).u64(1).u64(2).u64(3).u64(3).u64(1).u64(3).u64(4);
  w.i32(2).i32(7).i32(3).u64(1).u64(4).u64(2).u64(5).u64(3).u64(4);
  w.text("\n$EndElements\n");
  return w.str();
}

/// The same mesh in binary MSH 2.2: one block per element, as gmsh writes them (tags: physical group,
/// entity).
std::string msh22_binary(bool big_endian) {
  BinaryWriter w(big_endian);
  w.text("$MeshFormat\n2.2 1 8\n").i32(1).text("\n$EndMeshFormat\n");
  w.text("$PhysicalNames\n2\n1 2 \"edge\"\n2 1 \"plate\"\n$EndPhysicalNames\n");
  w.text("$Nodes\n5\n");
  for (int i = 0; i < 5; ++i) {
    w.i32(i + 1);
    for (double c : kX[i]) w.f64(c);
  }
  w.text("\n$EndNodes\n$Elements\n4\n");
  w.i32(1).i32(1).i32(2).i32(1).i32(2).i32(5).i32(1).i32(2);
  w.i32(2).i32(1).i32(2).i32(2).i32(1).i32(7).i32(1).i32(2).i32(3);
  w.i32(2).i32(1).i32(2).i32(3).i32(1).i32(7).i32(1).i32(3).i32(4);
  w.i32(3).i32(1).i32(2).i32(4).i32(1).i32(7).i32(2).i32(5).i32(3).i32(4);
  w.text("\n$EndElements\n");
  return w.str();
}

}  // namespace

TEST(MshReader, BinaryFilesInEitherByteOrder) {
  test::TempDir dir;
  // The same mesh as text, for reference.
  const auto text = dir.write(
      "text.msh",
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n1 2 \"edge\"\n2 1 \"plate\"\n$EndPhysicalNames\n"
      "$Entities\n0 1 1 0\n5 0 0 0 1 0 0 1 2 0\n7 0 0 -0.25 2 1 0.5 1 1 0\n$EndEntities\n"
      "$Nodes\n2 5 1 5\n1 5 0 2\n1\n2\n0 0 0\n1 0 0\n2 7 0 3\n3\n4\n5\n1 1 0.5\n0 1 -0.25\n2 0.125 0\n$EndNodes\n"
      "$Elements\n3 4 1 4\n1 5 1 1\n1 1 2\n2 7 2 2\n2 1 2 3\n3 1 3 4\n2 7 3 1\n4 2 5 3 4\n$EndElements\n");
  const gmsh::MeshData reference = gmsh::read_msh(text);
  ASSERT_EQ(reference.groups.size(), 2u);
  EXPECT_EQ(reference.groups[1].name, "plate");
  EXPECT_EQ(reference.groups[1].blocks.at(0).nodes, (std::vector<std::size_t>{1, 2, 3, 1, 3, 4}));
  EXPECT_EQ(reference.groups[1].blocks.at(1).nodes, (std::vector<std::size_t>{2, 5, 3, 4}));
  EXPECT_EQ(reference.coords.at(3 * 4 + 1), 0.125);
  expect_same(reference, gmsh::library::read(text, {}));
  for (const bool big : {false, true}) {
    SCOPED_TRACE(big ? "big-endian" : "little-endian");
    for (const auto& [name, bytes] :
         {std::pair{"b41.msh", msh41_binary(big)}, std::pair{"b22.msh", msh22_binary(big)}}) {
      SCOPED_TRACE(name);
      const auto path = dir.write(name, bytes);
      const gmsh::MeshData ours = gmsh::read_msh(path);
      expect_same(ours, reference);
      expect_same(ours, gmsh::library::read(path, {}));
    }
  }
}

TEST(MshReader, ElementTypesAreTheLibrarys) {
  // Every type the library knows up to 200 with a fixed number of nodes is in the table, with the
  // library's name, dimension, order and node count; the table holds nothing else.
  std::size_t matched = 0;
  for (const auto& t : gmsh::library::element_types(200)) {
    SCOPED_TRACE(t.type);
    const gmsh::ElementType* ours = gmsh::find_element_type(t.type);
    if (t.nodes == 0) {  // polygons, polyhedra, XFEM types
      EXPECT_EQ(ours, nullptr) << t.name;
      continue;
    }
    ASSERT_NE(ours, nullptr) << t.name;
    EXPECT_EQ(ours->name, t.name);
    EXPECT_EQ(std::tie(ours->dim, ours->order, ours->nodes), std::tie(t.dim, t.order, t.nodes));
    ++matched;
  }
  EXPECT_EQ(matched, gmsh::element_types().size());
  EXPECT_EQ(matched, 127u);
  EXPECT_EQ(gmsh::find_element_type(0), nullptr);
  EXPECT_EQ(gmsh::find_element_type(34), nullptr);  // a polygon
  EXPECT_EQ(gmsh::find_element_type(3)->name, "Quadrilateral 4");
}
