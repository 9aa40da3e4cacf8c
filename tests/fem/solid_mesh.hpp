#pragma once
// Test helper: structured solid meshes of a box [0, Lx] x [0, Ly] x [0, Lz] (n cells per direction)
// in a fem::Model, for every solid type: CHEXA 8/20 (one per cell), CPENTA 6/15 (two per cell, the
// cell's xy square cut along its diagonal), CTETRA 4/10 (six per cell, Kuhn's split along the cell
// diagonal: conforming). Quadratic elements take their mid-edge grids from a lattice twice as fine.
// Only grids that an element uses are created. Grid id = 1 + lattice index.
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

#include "fem_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/loads.hpp"

namespace seflex::fem::test {

enum class SolidType { Hexa8, Hexa20, Penta6, Penta15, Tetra4, Tetra10 };
inline const char* name(SolidType t) {
  static const char* n[] = {"CHEXA8", "CHEXA20", "CPENTA6", "CPENTA15", "CTETRA4", "CTETRA10"};
  return n[static_cast<int>(t)];
}
inline bool quadratic(SolidType t) { return t == SolidType::Hexa20 || t == SolidType::Penta15 || t == SolidType::Tetra10; }

struct BoxMesh {
  int nx = 1, ny = 1, nz = 1;
  double Lx = 1, Ly = 1, Lz = 1;
  /// Lattice point (i, j, k) on the doubled lattice (0..2n) -> grid id.
  int id(int i, int j, int k) const { return 1 + i + (2 * nx + 1) * (j + (2 * ny + 1) * k); }
  Eigen::Vector3d point(int i, int j, int k) const {
    return {Lx * i / (2.0 * nx), Ly * j / (2.0 * ny), Lz * k / (2.0 * nz)};
  }
};

using LatticePoint = std::array<int, 3>;

/// Append solid `eid` (PSOLID 1) on lattice points: its corners, then, if quadratic, the midpoints of
/// its `edges` (pairs of corners, QRG order); grid ids from id_of(i, j, k), each recorded in `used`.
template <class IdOf>
inline void add_lattice_solid(Model& m, int eid, Solid::Shape shape, const std::vector<LatticePoint>& corners,
                              const std::vector<std::array<int, 2>>& edges, bool quadratic, const IdOf& id_of,
                              std::map<int, LatticePoint>& used) {
  Solid s;
  s.id = eid;
  s.pid = 1;
  s.shape = shape;
  std::vector<LatticePoint> pts = corners;
  if (quadratic)
    for (const auto& e : edges) {
      const LatticePoint& a = corners[static_cast<std::size_t>(e[0])];
      const LatticePoint& b = corners[static_cast<std::size_t>(e[1])];
      pts.push_back({(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2});
    }
  s.nnode = static_cast<std::uint8_t>(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    s.g[k] = id_of(pts[k][0], pts[k][1], pts[k][2]);
    used[s.g[k]] = pts[k];
  }
  m.solids.push_back(s);
}

/// Add PSOLID 1 / MAT1 1 and the elements and grids of `box` to m. `map` (optional) moves the
/// lattice points (e.g. to a cylinder). Returns the lattice coordinates of every grid by id.
inline std::map<int, std::array<int, 3>> add_box_solids(Model& m, const BoxMesh& box, SolidType type, double E,
                                                        double nu, double rho,
                                                        const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& map = {}) {
  add_mat1(m, 1, E, nu, rho);
  SolidProperty p;
  p.id = 1;
  p.mid = 1;
  m.solid_props.push_back(p);
  std::map<int, std::array<int, 3>> used;
  using P = LatticePoint;
  int eid = 1;
  auto add = [&](Solid::Shape shape, const std::vector<P>& corners, const std::vector<std::array<int, 2>>& edges) {
    add_lattice_solid(m, eid++, shape, corners, edges, quadratic(type), [&](int i, int j, int k) { return box.id(i, j, k); }, used);
  };
  static const std::vector<std::array<int, 2>> hexa_edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                                                            {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  static const std::vector<std::array<int, 2>> penta_edges = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 4},
                                                             {2, 5}, {3, 4}, {4, 5}, {5, 3}};
  static const std::vector<std::array<int, 2>> tetra_edges = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  for (int k = 0; k < box.nz; ++k)
    for (int j = 0; j < box.ny; ++j)
      for (int i = 0; i < box.nx; ++i) {
        auto c = [&](int a, int b, int d) { return P{2 * (i + a), 2 * (j + b), 2 * (k + d)}; };
        switch (type) {
          case SolidType::Hexa8:
          case SolidType::Hexa20:
            add(Solid::Shape::Hexa, {c(0, 0, 0), c(1, 0, 0), c(1, 1, 0), c(0, 1, 0), c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)},
                hexa_edges);
            break;
          case SolidType::Penta6:
          case SolidType::Penta15:
            add(Solid::Shape::Penta, {c(0, 0, 0), c(1, 0, 0), c(1, 1, 0), c(0, 0, 1), c(1, 0, 1), c(1, 1, 1)}, penta_edges);
            add(Solid::Shape::Penta, {c(0, 0, 0), c(1, 1, 0), c(0, 1, 0), c(0, 0, 1), c(1, 1, 1), c(0, 1, 1)}, penta_edges);
            break;
          case SolidType::Tetra4:
          case SolidType::Tetra10: {
            static const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
            for (const auto& pr : perm) {
              P v1{0, 0, 0}, v2;
              v1[static_cast<std::size_t>(pr[0])] = 1;
              v2 = v1;
              v2[static_cast<std::size_t>(pr[1])] = 1;
              add(Solid::Shape::Tetra, {c(0, 0, 0), c(v1[0], v1[1], v1[2]), c(v2[0], v2[1], v2[2]), c(1, 1, 1)}, tetra_edges);
            }
            break;
          }
        }
      }
  for (const auto& [gid, lp] : used) {
    Eigen::Vector3d x = box.point(lp[0], lp[1], lp[2]);
    if (map) x = map(x);
    add_grid(m, gid, x.x(), x.y(), x.z());
  }
  return used;
}

/// Solve K u = p on the translations with the dofs in `fixed` prescribed (rotations are not solved:
/// solids do not stiffen them). Returns u on all g-set dofs.
inline Eigen::VectorXd solve_translations(const Model& m, const GlobalMatrices& g, const Eigen::VectorXd& p,
                                   const std::map<Eigen::Index, double>& fixed) {
  const Eigen::Index n = g.dofs.size();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  std::vector<Eigen::Index> free;
  for (Eigen::Index gi = 0; gi < static_cast<Eigen::Index>(m.grids.size()); ++gi)
    for (int c = 1; c <= 3; ++c) {
      const Eigen::Index d = g.dofs.grid_dof(gi, c);
      if (const auto it = fixed.find(d); it != fixed.end())
        u[d] = it->second;
      else
        free.push_back(d);
    }
  std::vector<Eigen::Triplet<double>> t;
  for (std::size_t k = 0; k < free.size(); ++k) t.emplace_back(free[k], static_cast<Eigen::Index>(k), 1.0);
  Eigen::SparseMatrix<double> S(n, static_cast<Eigen::Index>(free.size()));
  S.setFromTriplets(t.begin(), t.end());
  const Eigen::SparseMatrix<double> Kff = S.transpose() * g.K * S;
  const Eigen::VectorXd rhs = S.transpose() * (p - g.K * u);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(Kff);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  u += S * ldlt.solve(rhs);
  return u;
}

inline Eigen::Vector3d translation(const Model& m, const GlobalMatrices& g, const Eigen::VectorXd& u, int grid) {
  const Eigen::Index gi = m.grid_index.at(grid);
  return {u[g.dofs.grid_dof(gi, 1)], u[g.dofs.grid_dof(gi, 2)], u[g.dofs.grid_dof(gi, 3)]};
}

/// Resultant force (basic) of the grid loads of load set sid of a finalized model.
inline Eigen::Vector3d load_resultant(const Model& m, int sid) {
  const DofMap dofs = make_dof_map(m);
  const Eigen::VectorXd f = load_vector(m, dofs, sid);
  Eigen::Vector3d F = Eigen::Vector3d::Zero();
  for (Eigen::Index gi = 0; gi < static_cast<Eigen::Index>(m.grids.size()); ++gi)
    for (int c = 0; c < 3; ++c) F[c] += f[dofs.grid_dof(gi, c + 1)];
  return F;
}

/// Cantilever along x clamped at lattice x = 0 (every translation) under the loads p: the mean
/// deflection -u_z of the grids at lattice x = x_end.
inline double mean_tip_deflection(const Model& m, const GlobalMatrices& g, const Eigen::VectorXd& p,
                                  const std::map<int, std::array<int, 3>>& lattice, int x_end) {
  std::map<Eigen::Index, double> fixed;
  for (const auto& [id, l] : lattice)
    if (l[0] == 0)
      for (int c = 1; c <= 3; ++c) fixed[g.dofs.grid_dof(m.grid_index.at(id), c)] = 0.0;
  const Eigen::VectorXd u = solve_translations(m, g, p, fixed);
  double w = 0;
  int n = 0;
  for (const auto& [id, l] : lattice)
    if (l[0] == x_end) w -= translation(m, g, u, id).z(), ++n;
  return w / n;
}

/// The grids strictly inside the lattice box (0, hi)^3, each moved by `amplitude` times a fixed
/// pseudo-random unit-ish vector; returns their ids.
inline std::set<int> distort_interior(Model& m, const std::map<int, std::array<int, 3>>& lattice, int hi, double amplitude) {
  int k = 0;
  std::set<int> interior;
  for (Grid& g : m.grids) {
    const auto& l = lattice.at(g.id);
    ++k;
    if (l[0] > 0 && l[0] < hi && l[1] > 0 && l[1] < hi && l[2] > 0 && l[2] < hi) {
      interior.insert(g.id);
      g.x += amplitude * Eigen::Vector3d(std::sin(1.7 * k), std::cos(2.3 * k), std::sin(3.1 * k + 0.4));
    }
  }
  return interior;
}

/// Patch test: the boundary grids (all but `interior`) moved by the linear field u = A x + c, no
/// load; returns the largest distance of an interior grid from that field (0 to round-off for an
/// element that passes).
inline double patch_test_error(Model& m, const std::set<int>& interior, const Eigen::Matrix3d& A, const Eigen::Vector3d& c) {
  finalize_for_test(m);
  const GlobalMatrices g = assemble(m, assembly_options(m));
  std::map<Eigen::Index, double> fixed;
  for (std::size_t gi = 0; gi < m.grids.size(); ++gi) {
    if (interior.count(m.grids[gi].id)) continue;
    const Eigen::Vector3d u = A * m.grids[gi].x_basic + c;
    for (int cc = 1; cc <= 3; ++cc) fixed[g.dofs.grid_dof(static_cast<Eigen::Index>(gi), cc)] = u[cc - 1];
  }
  EXPECT_FALSE(interior.empty());
  const Eigen::VectorXd u = solve_translations(m, g, Eigen::VectorXd::Zero(g.dofs.size()), fixed);
  double worst = 0;
  for (const int id : interior) {
    const Eigen::Vector3d exact = A * m.grids[m.grid_index.at(id)].x_basic + c;
    worst = std::max(worst, (translation(m, g, u, id) - exact).norm());
  }
  return worst;
}

}  // namespace seflex::fem::test
