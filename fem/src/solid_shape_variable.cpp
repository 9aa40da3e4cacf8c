// The solids' shape functions by element (solid_shapes.hpp: solid_shape): linear, full quadratic, or
// quadratic with some mid-edge grids blank (a variable-number-of-nodes element: Bathe, Finite Element
// Procedures, 1996, sec. 5.3.1). With N_m the full element's mid-edge functions, its corner
// functions are N_c = L_c - 1/2 sum_{m on an edge of c} N_m (L_c the linear element's). Dropping a
// mid-edge grid m removes N_m, and its term from the corners of its edge: N_c += N_m / 2 for both.
// The element then interpolates that edge linearly, and reproduces every linear field.
#include <stdexcept>

#include "solid_shapes.hpp"

namespace seflex::fem::detail {
namespace {

// Corner pairs of the mid-edge grids, in the QRG order of each shape (solid_shape_*.cpp).
constexpr int kHexaEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                                   {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
constexpr int kPentaEdges[9][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 4}, {2, 5}, {3, 4}, {4, 5}, {5, 3}};
constexpr int kTetraEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
constexpr int kPyramEdges[8][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}};

void base_shape(Solid::Shape shape, int nnode, const Eigen::Vector3d& xi, ShapeValues& s) {
  switch (shape) {
    case Solid::Shape::Hexa: hexa_shape(nnode, xi, s); return;
    case Solid::Shape::Penta: penta_shape(nnode, xi, s); return;
    case Solid::Shape::Tetra: tetra_shape(nnode, xi, s); return;
    case Solid::Shape::Pyram: pyram_shape(nnode, xi, s); return;
  }
}

}  // namespace

std::array<int, 2> solid_edge_ends(Solid::Shape shape, int k) {
  const int(*e)[2] = shape == Solid::Shape::Hexa    ? kHexaEdges
                     : shape == Solid::Shape::Penta ? kPentaEdges
                     : shape == Solid::Shape::Pyram ? kPyramEdges
                                                    : kTetraEdges;
  return {e[k][0], e[k][1]};
}

void solid_shape(Solid::Shape shape, int nnode, std::uint16_t missing_mid, const Eigen::Vector3d& xi, ShapeValues& s) {
  const int corners = Solid::corners(shape), edges = Solid::edges(shape), full = corners + edges;
  if (nnode == corners || (nnode == full && missing_mid == 0)) {
    base_shape(shape, nnode, xi, s);
    return;
  }
  int missing = 0;
  for (int k = 0; k < edges; ++k) missing += missing_mid >> k & 1u;
  if (nnode < corners || nnode > full || missing_mid >> edges != 0 || nnode != full - missing)
    throw std::logic_error("solid_shape: " + std::to_string(nnode) + " grids do not match the missing mid-edge mask");
  base_shape(shape, full, xi, s);
  int out = corners;
  for (int k = 0; k < edges; ++k) {
    const int m = corners + k;
    if (missing_mid >> k & 1u) {
      const std::array<int, 2> ends = solid_edge_ends(shape, k);
      for (const int c : ends) {
        s.N[c] += 0.5 * s.N[m];
        for (int j = 0; j < 3; ++j) s.dN[c][j] += 0.5 * s.dN[m][j];
      }
      continue;
    }
    if (out != m) {
      s.N[out] = s.N[m];
      for (int j = 0; j < 3; ++j) s.dN[out][j] = s.dN[m][j];
    }
    ++out;
  }
  s.n = nnode;
}

}  // namespace seflex::fem::detail
