// CONM2 rotary inertia about a flat shell's normal (drilling_inertia.hpp).
#include "drilling_inertia.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

namespace seflex::solutions::detail {

DrillingInertia drilling_inertia(const fem::Model& m) {
  DrillingInertia out;
  if (m.conm2.empty() || m.shells.empty()) return out;
  std::unordered_set<int> other;  // grids something other than a shell reaches
  for (const auto& b : m.bars) other.insert({b.ga, b.gb});
  for (const auto& r : m.rods) other.insert({r.ga, r.gb});
  for (const auto& s : m.springs) other.insert({s.g1, s.g2});
  for (const auto& b : m.bushes) other.insert({b.ga, b.gb});
  for (const auto& r : m.rbe2) {
    other.insert(r.gn);
    other.insert(r.gm.begin(), r.gm.end());
  }
  for (const auto& r : m.rbars) other.insert({r.ga, r.gb});
  for (const auto& r : m.rigid_rods) other.insert({r.ga, r.gb});
  for (const auto& b : m.bends) other.insert({b.ga, b.gb});
  for (const auto& q : m.shells8) {  // curved or quadratic: their grids are not those of flat linear facets
    other.insert(q.shell.g.begin(), q.shell.g.begin() + q.shell.nnode);
    other.insert(q.mid.begin(), q.mid.end());
  }
  for (const auto& s : m.shear_panels) other.insert(s.g.begin(), s.g.end());
  for (const auto& g : m.genels)
    for (const auto* list : {&g.ui, &g.ud})
      for (const auto& d : *list) other.insert(d.point);
  for (const auto& r : m.rigid_bodies)
    for (const auto* set : {&r.independent, &r.dependent})
      for (const auto& g : *set) other.insert(g.grid);
  for (const auto& r : m.rbe3) {
    other.insert(r.refgrid);
    for (const auto& g : r.groups) other.insert(g.grids.begin(), g.grids.end());
  }
  for (const auto& e : m.mpcs)
    for (const auto& t : e.terms) other.insert(t.grid);
  auto x = [&](int id) -> const Eigen::Vector3d* {
    const auto it = m.grid_index.find(id);
    return it == m.grid_index.end() ? nullptr : &m.grids[it->second].x_basic;
  };
  // Unit normal of every shell at its grids; a grid whose shells are not coplanar is dropped.
  std::unordered_map<int, Eigen::Vector3d> normal;
  std::unordered_set<int> bent;
  for (const auto& s : m.shells) {
    const Eigen::Vector3d *a = x(s.g[0]), *b = x(s.g[1]), *c = x(s.g[2]), *d = s.nnode == 4 ? x(s.g[3]) : c;
    if (!a || !b || !c || !d) continue;
    const Eigen::Vector3d n = s.nnode == 4 ? (*c - *a).cross(*d - *b) : (*b - *a).cross(*c - *a);
    if (!(n.norm() > 0.0)) continue;
    const Eigen::Vector3d u = n.normalized();
    for (int k = 0; k < s.nnode; ++k) {
      const auto [it, fresh] = normal.emplace(s.g[k], u);
      if (!fresh && std::abs(it->second.dot(u)) < std::cos(1.0 * 3.14159265358979 / 180.0)) bent.insert(s.g[k]);
    }
  }
  for (const auto& c : m.conm2) {
    if (c.cid > 0 || other.count(c.grid) || bent.count(c.grid)) continue;
    const auto it = normal.find(c.grid);
    if (it == normal.end()) continue;
    Eigen::Matrix3d I;
    I << c.I11, -c.I21, -c.I31, -c.I21, c.I22, -c.I32, -c.I31, -c.I32, c.I33;
    const double inn = it->second.dot(I * it->second);
    if (!(inn > 1e-12 * std::max(1.0, I.trace()))) continue;
    if (out.count++ == 0) {
      out.first = c.ref;
      out.first_grid = c.grid;
      out.first_inertia = inn;
    }
  }
  return out;
}

}  // namespace seflex::solutions::detail
