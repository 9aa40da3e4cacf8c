// Coordinate systems: resolution of CORD2x/CORD1x to basic, point transformation, displacement axes.
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "seflex/fem/finalize.hpp"

namespace seflex::fem {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

const char* card_name(const CoordSys& c) {
  static const char* names[2][3] = {{"CORD2R", "CORD2C", "CORD2S"}, {"CORD1R", "CORD1C", "CORD1S"}};
  return names[c.by_grids ? 1 : 0][static_cast<int>(c.type)];
}

/// Cartesian coordinates in the system's own axes of a point given in its (R,THETA,Z) / (R,THETA,PHI).
Eigen::Vector3d local_cartesian(CoordType type, const Eigen::Vector3d& x) {
  switch (type) {
    case CoordType::Cylindrical: return {x[0] * std::cos(x[1] * kDeg), x[0] * std::sin(x[1] * kDeg), x[2]};
    case CoordType::Spherical: {
      const double t = x[1] * kDeg, p = x[2] * kDeg;
      return {x[0] * std::sin(t) * std::cos(p), x[0] * std::sin(t) * std::sin(p), x[0] * std::cos(t)};
    }
    case CoordType::Rectangular: break;
  }
  return x;
}

[[noreturn]] void fail(const Model& m, const CoordSys& c, const std::string& problem) {
  throw InputError(where(m, c.ref), std::string(card_name(c)) + " " + std::to_string(c.id) + problem);
}

/// Origin and axes from three points in basic: A origin, B on the z axis, C in the x-z plane.
void axes_from_points(const Model& m, CoordSys& c, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                      const Eigen::Vector3d& p) {
  const double scale = a.norm() + b.norm() + p.norm();
  const Eigen::Vector3d ab = b - a, ac = p - a;
  const char* pts = c.by_grids ? "grids G1 and G2" : "points A and B";
  if (!(ab.norm() > 1e-12 * scale))
    fail(m, c, ": " + std::string(pts) + " coincide; expected distinct points defining the z axis");
  const Eigen::Vector3d e3 = ab.normalized();
  const Eigen::Vector3d n = e3.cross(ac);
  if (!(n.norm() > 1e-9 * ac.norm()) || !(ac.norm() > 1e-12 * scale))
    fail(m, c, std::string(": ") + (c.by_grids ? "grid G3" : "point C") +
                   " lies on the z axis; expected a point off the axis defining the x-z plane");
  const Eigen::Vector3d e2 = n.normalized();
  c.origin = a;
  c.axes.col(0) = e2.cross(e3);
  c.axes.col(1) = e2;
  c.axes.col(2) = e3;
  c.resolved = true;
}

}  // namespace

Eigen::Vector3d to_basic(const Model& m, int cid, const Eigen::Vector3d& x) {
  if (cid == 0) return x;
  const auto it = m.coord_index.find(cid);
  SEFLEX_DEMAND(it != m.coord_index.end(), "coordinate system " + std::to_string(cid) + " is not defined");
  const CoordSys& c = m.coords[it->second];
  SEFLEX_DEMAND(c.resolved, "coordinate system " + std::to_string(cid) + " is not resolved (call finalize)");
  return c.origin + c.axes * local_cartesian(c.type, x);
}

Eigen::Matrix3d displacement_axes(const Model& m, int cd, const Eigen::Vector3d& x_basic) {
  if (cd == 0) return Eigen::Matrix3d::Identity();
  const auto it = m.coord_index.find(cd);
  SEFLEX_DEMAND(it != m.coord_index.end(), "coordinate system " + std::to_string(cd) + " is not defined");
  const CoordSys& c = m.coords[it->second];
  SEFLEX_DEMAND(c.resolved, "coordinate system " + std::to_string(cd) + " is not resolved (call finalize)");
  if (c.type == CoordType::Rectangular) return c.axes;
  const Eigen::Vector3d p = c.axes.transpose() * (x_basic - c.origin);
  const double phi = std::atan2(p.y(), p.x());
  const double cp = std::cos(phi), sp = std::sin(phi);
  Eigen::Matrix3d local;
  if (c.type == CoordType::Cylindrical) {
    local << cp, -sp, 0, sp, cp, 0, 0, 0, 1;
  } else {
    const double theta = std::atan2(std::hypot(p.x(), p.y()), p.z());
    const double ct = std::cos(theta), st = std::sin(theta);
    local << st * cp, ct * cp, -sp, st * sp, ct * sp, cp, ct, -st, 0;
  }
  return c.axes * local;
}

void resolve_coordinates(Model& m) {
  const std::size_t n = m.coords.size();
  for (auto& c : m.coords) c.resolved = false;
  std::vector<std::uint8_t> state(n, 0);  // 0 new, 1 on the stack, 2 done
  auto grid_of = [&](const CoordSys& c, int k) -> Grid& {
    const auto it = m.grid_index.find(c.grids[k]);
    if (it == m.grid_index.end()) {
      static const char* names[3] = {"G1", "G2", "G3"};
      fail(m, c, ", " + std::string(names[k]) + ": references grid " + std::to_string(c.grids[k]) +
                     ", which is not defined; expected the id of a GRID");
    }
    return m.grids[it->second];
  };
  auto coord_of = [&](const CoordSys& from, int cid, const std::string& what) -> std::size_t {
    const auto it = m.coord_index.find(cid);
    if (it == m.coord_index.end())
      fail(m, from, ", " + what + ": references coordinate system " + std::to_string(cid) +
                        ", which is not defined; expected the id of a CORD1x or CORD2x card (or 0)");
    return it->second;
  };
  // Depth-first over dependencies with an explicit stack (a long CORD2 chain must not overflow the
  // call stack). A CORD2x depends on its RID; a CORD1x on the CP systems of its three grids.
  std::vector<std::size_t> stack;
  for (std::size_t root = 0; root < n; ++root) {
    if (state[root] == 2) continue;
    stack.push_back(root);
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      CoordSys& c = m.coords[i];
      std::size_t pending = n;
      if (c.by_grids) {
        for (int k = 0; k < 3 && pending == n; ++k) {
          const Grid& g = grid_of(c, k);
          if (g.cp != 0) {
            const std::size_t d = coord_of(c, g.cp, "grid " + std::to_string(g.id) + " CP");
            if (state[d] != 2) pending = d;
          }
        }
      } else if (c.rid != 0) {
        const std::size_t d = coord_of(c, c.rid, "field 3 (RID)");
        if (state[d] != 2) pending = d;
      }
      if (pending != n) {
        if (state[pending] == 1) {
          std::string chain;
          for (const std::size_t s : stack) chain += std::to_string(m.coords[s].id) + " -> ";
          fail(m, c, ": coordinate systems are defined in a cycle (" + chain + std::to_string(m.coords[pending].id) +
                         "); expected each system to be defined from systems that do not depend on it");
        }
        state[i] = 1;
        stack.push_back(pending);
        continue;
      }
      if (c.by_grids) {
        Eigen::Vector3d x[3];
        for (int k = 0; k < 3; ++k) {
          Grid& g = grid_of(c, k);
          g.x_basic = to_basic(m, g.cp, g.x);
          x[k] = g.x_basic;
        }
        axes_from_points(m, c, x[0], x[1], x[2]);
      } else {
        const Eigen::Vector3d a = to_basic(m, c.rid, {c.abc[0], c.abc[1], c.abc[2]});
        const Eigen::Vector3d b = to_basic(m, c.rid, {c.abc[3], c.abc[4], c.abc[5]});
        const Eigen::Vector3d p = to_basic(m, c.rid, {c.abc[6], c.abc[7], c.abc[8]});
        axes_from_points(m, c, a, b, p);
      }
      state[i] = 2;
      stack.pop_back();
    }
  }
  for (auto& g : m.grids) {
    if (g.cp != 0 && !m.coord_index.count(g.cp))
      throw InputError(where(m, g.ref), "GRID " + std::to_string(g.id) + ", field 3 (CP): references coordinate system " +
                                            std::to_string(g.cp) + ", which is not defined; expected the id of a CORD1x or CORD2x card (or 0)");
    if (g.cd != 0 && !m.coord_index.count(g.cd))
      throw InputError(where(m, g.ref), "GRID " + std::to_string(g.id) + ", field 7 (CD): references coordinate system " +
                                            std::to_string(g.cd) + ", which is not defined; expected the id of a CORD1x or CORD2x card (or 0)");
    g.x_basic = g.cp == 0 ? g.x : to_basic(m, g.cp, g.x);
  }
}

}  // namespace seflex::fem
