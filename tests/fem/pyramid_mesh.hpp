#pragma once
// Test helper: a box [0, Lx] x [0, Ly] x [0, Lz] of nx x ny x nz cells meshed with CPYRAM 5 or 13:
// each cell split into six pyramids, one on each face of the cell with its apex at the cell's centre
// (a conforming mesh: neighbouring pyramids share their triangles, neighbouring cells their bases).
// Mixed: every other cell (i + j + k odd) is one CHEXA 8/20 instead, which shares its faces with
// the pyramids' bases, and every other pyramid whose base lies on the box's boundary is split along a
// base diagonal into two CTETRA 4/10, which share their triangles with the pyramids beside them. The
// grids lie on a lattice four times as fine as the cells (the quadratic pyramids' mid-edge grids to
// the apex are at a quarter of the cell); grid id = 1 + lattice index. Only the grids an element
// uses are created.
#include <array>
#include <functional>
#include <map>
#include <vector>

#include "solid_mesh.hpp"

namespace seflex::fem::test {

struct PyramidBox {
  int nx = 1, ny = 1, nz = 1;
  double Lx = 1, Ly = 1, Lz = 1;
  bool quadratic = false;  ///< CPYRAM 13 (and CHEXA 20, CTETRA 10) instead of 5 (8, 4)
  bool mixed = false;
  int id(int i, int j, int k) const { return 1 + i + (4 * nx + 1) * (j + (4 * ny + 1) * k); }
  Eigen::Vector3d point(int i, int j, int k) const { return {Lx * i / (4.0 * nx), Ly * j / (4.0 * ny), Lz * k / (4.0 * nz)}; }
};

/// Add PSOLID 1 / MAT1 1 and the elements and grids of `box` to m; `map` (optional) moves the
/// lattice points. Returns the lattice coordinates (0..4n) of every grid by id.
inline std::map<int, std::array<int, 3>> add_pyramid_box(Model& m, const PyramidBox& box, double E, double nu, double rho,
                                                         const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& map = {}) {
  using P = LatticePoint;
  add_mat1(m, 1, E, nu, rho);
  SolidProperty prop;
  prop.id = 1;
  prop.mid = 1;
  m.solid_props.push_back(prop);
  std::map<int, P> used;
  int eid = 1;
  auto add = [&](Solid::Shape shape, const std::vector<P>& corners, const std::vector<std::array<int, 2>>& edges) {
    add_lattice_solid(m, eid++, shape, corners, edges, box.quadratic, [&](int i, int j, int k) { return box.id(i, j, k); }, used);
  };
  static const std::vector<std::array<int, 2>> hexa_edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                                                            {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  static const std::vector<std::array<int, 2>> pyram_edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}};
  static const std::vector<std::array<int, 2>> tetra_edges = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  const int n[3] = {box.nx, box.ny, box.nz};
  int split = 0;
  for (int k = 0; k < box.nz; ++k)
    for (int j = 0; j < box.ny; ++j)
      for (int i = 0; i < box.nx; ++i) {
        const int cell[3] = {i, j, k};
        auto c = [&](int a, int b, int d) { return P{4 * (i + a), 4 * (j + b), 4 * (k + d)}; };
        if (box.mixed && (i + j + k) % 2 == 1) {
          add(Solid::Shape::Hexa, {c(0, 0, 0), c(1, 0, 0), c(1, 1, 0), c(0, 1, 0), c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)},
              hexa_edges);
          continue;
        }
        const P apex{4 * i + 2, 4 * j + 2, 4 * k + 2};
        for (int axis = 0; axis < 3; ++axis)
          for (int side = 0; side < 2; ++side) {
            // The face's corners in cyclic order, turned so that their right-hand normal points to the apex.
            const int u = (axis + 1) % 3, w = (axis + 2) % 3;
            std::vector<P> base;
            for (const auto& uw : {std::array<int, 2>{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
              P p{};
              p[static_cast<std::size_t>(axis)] = 4 * (cell[axis] + side);
              p[static_cast<std::size_t>(u)] = 4 * (cell[u] + uw[0]);
              p[static_cast<std::size_t>(w)] = 4 * (cell[w] + uw[1]);
              base.push_back(p);
            }
            if (side == 1) std::swap(base[1], base[3]);  // (u x w) = +axis points out of the cell on side 1
            const bool boundary = cell[axis] + side == 0 || cell[axis] + side == n[axis];
            if (box.mixed && boundary && split++ % 2 == 0) {
              add(Solid::Shape::Tetra, {base[0], base[1], base[2], apex}, tetra_edges);
              add(Solid::Shape::Tetra, {base[0], base[2], base[3], apex}, tetra_edges);
              continue;
            }
            add(Solid::Shape::Pyram, {base[0], base[1], base[2], base[3], apex}, pyram_edges);
          }
      }
  for (const auto& [gid, lp] : used) {
    Eigen::Vector3d x = box.point(lp[0], lp[1], lp[2]);
    if (map) x = map(x);
    add_grid(m, gid, x.x(), x.y(), x.z());
  }
  return used;
}

}  // namespace seflex::fem::test
