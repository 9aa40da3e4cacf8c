// The gmsh element types with a fixed number of nodes (gmsh_mesh.hpp: element_types): numbers, names,
// dimensions, orders and node counts as gmsh 4.8's gmshModelMeshGetElementProperties gives them
// (types 1-137; tests/io/gmsh_msh_reader_test.cpp checks every entry, and that the library knows no
// other type with a fixed number of nodes below 200). For the prisms of order 3 and more and the
// types 67, 68 and 70 the library logs an error about their basis functions, but describes them.
#include <algorithm>

#include "seflex/io/gmsh_mesh.hpp"

namespace seflex::io::gmsh {

const std::vector<ElementType>& element_types() {
  // clang-format off
  static const std::vector<ElementType> kTypes = {
      {1, "Line 2", 1, 1, 2}, {2, "Triangle 3", 2, 1, 3}, {3, "Quadrilateral 4", 2, 1, 4},
      {4, "Tetrahedron 4", 3, 1, 4}, {5, "Hexahedron 8", 3, 1, 8}, {6, "Prism 6", 3, 1, 6}, {7, "Pyramid 5", 3, 1, 5},
      {8, "Line 3", 1, 2, 3}, {9, "Triangle 6", 2, 2, 6}, {10, "Quadrilateral 9", 2, 2, 9},
      {11, "Tetrahedron 10", 3, 2, 10}, {12, "Hexahedron 27", 3, 2, 27}, {13, "Prism 18", 3, 2, 18},
      {14, "Pyramid 14", 3, 2, 14}, {15, "Point", 0, 0, 1}, {16, "Quadrilateral 8", 2, 2, 8},
      {17, "Hexahedron 20", 3, 2, 20}, {18, "Prism 15", 3, 2, 15}, {19, "Pyramid 13", 3, 2, 13},
      {20, "Triangle 9", 2, 3, 9}, {21, "Triangle 10", 2, 3, 10}, {22, "Triangle 12", 2, 4, 12},
      {23, "Triangle 15", 2, 4, 15}, {24, "Triangle 15I", 2, 5, 15}, {25, "Triangle 21", 2, 5, 21},
      {26, "Line 4", 1, 3, 4}, {27, "Line 5", 1, 4, 5}, {28, "Line 6", 1, 5, 6}, {29, "Tetrahedron 20", 3, 3, 20},
      {30, "Tetrahedron 35", 3, 4, 35}, {31, "Tetrahedron 56", 3, 5, 56}, {32, "Tetrahedron 22", 3, 4, 22},
      {33, "Tetrahedron 28", 3, 5, 28}, {36, "Quadrilateral 16", 2, 3, 16}, {37, "Quadrilateral 25", 2, 4, 25},
      {38, "Quadrilateral 36", 2, 5, 36}, {39, "Quadrilateral 12", 2, 3, 12}, {40, "Quadrilateral 16I", 2, 4, 16},
      {41, "Quadrilateral 20", 2, 5, 20}, {42, "Triangle 28", 2, 6, 28}, {43, "Triangle 36", 2, 7, 36},
      {44, "Triangle 45", 2, 8, 45}, {45, "Triangle 55", 2, 9, 55}, {46, "Triangle 66", 2, 10, 66},
      {47, "Quadrilateral 49", 2, 6, 49}, {48, "Quadrilateral 64", 2, 7, 64}, {49, "Quadrilateral 81", 2, 8, 81},
      {50, "Quadrilateral 100", 2, 9, 100}, {51, "Quadrilateral 121", 2, 10, 121}, {52, "Triangle 18", 2, 6, 18},
      {53, "Triangle 21I", 2, 7, 21}, {54, "Triangle 24", 2, 8, 24}, {55, "Triangle 27", 2, 9, 27},
      {56, "Triangle 30", 2, 10, 30}, {57, "Quadrilateral 24", 2, 6, 24}, {58, "Quadrilateral 28", 2, 7, 28},
      {59, "Quadrilateral 32", 2, 8, 32}, {60, "Quadrilateral 36I", 2, 9, 36}, {61, "Quadrilateral 40", 2, 10, 40},
      {62, "Line 7", 1, 6, 7}, {63, "Line 8", 1, 7, 8}, {64, "Line 9", 1, 8, 9}, {65, "Line 10", 1, 9, 10},
      {66, "Line 11", 1, 10, 11}, {67, "Line Border", 1, 1, 2}, {68, "Triangle Border", 2, 1, 3},
      {70, "Line Child", 1, 1, 2}, {71, "Tetrahedron 84", 3, 6, 84}, {72, "Tetrahedron 120", 3, 7, 120},
      {73, "Tetrahedron 165", 3, 8, 165}, {74, "Tetrahedron 220", 3, 9, 220}, {75, "Tetrahedron 286", 3, 10, 286},
      {79, "Tetrahedron 34", 3, 6, 34}, {80, "Tetrahedron 40", 3, 7, 40}, {81, "Tetrahedron 46", 3, 8, 46},
      {82, "Tetrahedron 52", 3, 9, 52}, {83, "Tetrahedron 58", 3, 10, 58}, {84, "Line 1", 1, 0, 1},
      {85, "Triangle 1", 2, 0, 1}, {86, "Quadrilateral 1", 2, 0, 1}, {87, "Tetrahedron 1", 3, 0, 1},
      {88, "Hexahedron 1", 3, 0, 1}, {89, "Prism 1", 3, 0, 1}, {90, "Prism 40", 3, 3, 40}, {91, "Prism 75", 3, 4, 75},
      {92, "Hexahedron 64", 3, 3, 64}, {93, "Hexahedron 125", 3, 4, 125}, {94, "Hexahedron 216", 3, 5, 216},
      {95, "Hexahedron 343", 3, 6, 343}, {96, "Hexahedron 512", 3, 7, 512}, {97, "Hexahedron 729", 3, 8, 729},
      {98, "Hexahedron 1000", 3, 9, 1000}, {99, "Hexahedron 32", 3, 3, 32}, {100, "Hexahedron 44", 3, 4, 44},
      {101, "Hexahedron 56", 3, 5, 56}, {102, "Hexahedron 68", 3, 6, 68}, {103, "Hexahedron 80", 3, 7, 80},
      {104, "Hexahedron 92", 3, 8, 92}, {105, "Hexahedron 104", 3, 9, 104}, {106, "Prism 126", 3, 5, 126},
      {107, "Prism 196", 3, 6, 196}, {108, "Prism 288", 3, 7, 288}, {109, "Prism 405", 3, 8, 405},
      {110, "Prism 550", 3, 9, 550}, {111, "Prism 24", 3, 3, 24}, {112, "Prism 33", 3, 4, 33},
      {113, "Prism 42", 3, 5, 42}, {114, "Prism 51", 3, 6, 51}, {115, "Prism 60", 3, 7, 60},
      {116, "Prism 69", 3, 8, 69}, {117, "Prism 78", 3, 9, 78}, {118, "Pyramid 30", 3, 3, 30},
      {119, "Pyramid 55", 3, 4, 55}, {120, "Pyramid 91", 3, 5, 91}, {121, "Pyramid 140", 3, 6, 140},
      {122, "Pyramid 204", 3, 7, 204}, {123, "Pyramid 285", 3, 8, 285}, {124, "Pyramid 385", 3, 9, 385},
      {125, "Pyramid 21", 3, 3, 21}, {126, "Pyramid 29", 3, 4, 29}, {127, "Pyramid 37", 3, 5, 37},
      {128, "Pyramid 45", 3, 6, 45}, {129, "Pyramid 53", 3, 7, 53}, {130, "Pyramid 61", 3, 8, 61},
      {131, "Pyramid 69", 3, 9, 69}, {132, "Pyramid 1", 3, 0, 1}, {137, "Tetrahedron 16", 3, 3, 16},
  };
  // clang-format on
  return kTypes;
}

const ElementType* find_element_type(int type) {
  const auto& types = element_types();
  const auto it =
      std::lower_bound(types.begin(), types.end(), type, [](const ElementType& t, int n) { return t.type < n; });
  return it != types.end() && it->type == type ? &*it : nullptr;
}

const char* dimension_name(int dim) {
  switch (dim) {
    case 0:
      return "point";
    case 1:
      return "curve";
    case 2:
      return "surface";
    default:
      return "volume";
  }
}

}  // namespace seflex::io::gmsh
