#pragma once
// Structured shell meshes for the fem tests: (nx+1) x (ny+1) grids mapped from the unit square by a
// function, CQUAD4 (or two CTRIA3 per cell), one PSHELL with MID1 = MID2 = MID3.
#include <functional>

#include "fem_test_util.hpp"

namespace seflex::fem::test {

struct ShellMesh {
  int nx = 1, ny = 1;
  int id(int i, int j) const { return 1 + i + (nx + 1) * j; }  // grid id of node (i, j)
};

/// Grids id(i, j) at map(i / nx, j / ny); elements numbered from 1; material 1, PSHELL 1.
inline ShellMesh add_shell_mesh(Model& m, int nx, int ny, const std::function<Eigen::Vector3d(double, double)>& map,
                                bool triangles = false) {
  ShellMesh s{nx, ny};
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const Eigen::Vector3d x = map(double(i) / nx, double(j) / ny);
      add_grid(m, s.id(i, j), x.x(), x.y(), x.z());
    }
  int e = 1;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = s.id(i, j), b = s.id(i + 1, j), c = s.id(i + 1, j + 1), d = s.id(i, j + 1);
      if (triangles) {
        add_shell(m, e++, 1, {a, b, c});
        add_shell(m, e++, 1, {a, c, d});
      } else {
        add_shell(m, e++, 1, {a, b, c, d});
      }
    }
  return s;
}

inline void add_spc(Model& m, int sid, int grid, const std::string& components) {
  add_spc1(m, sid, mask(components), grid);
}

inline void add_force(Model& m, int sid, int grid, const Eigen::Vector3d& f, bool moment = false) {
  PointLoad l;
  l.kind = moment ? PointLoad::Kind::Moment : PointLoad::Kind::Force;
  l.sid = sid;
  l.grid = grid;
  l.scale = 1.0;
  l.n = f;
  m.point_loads.push_back(l);
}

}  // namespace seflex::fem::test
