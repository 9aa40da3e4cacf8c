// PLOAD4 grid forces on shells and solid faces (face_pressure.hpp).
#include "face_pressure.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "model_lookup.hpp"
#include "seflex/common/error.hpp"
#include "solid_shapes.hpp"

namespace seflex::fem::detail {
namespace {

struct SurfacePoint {
  double w = 0;                                   ///< quadrature weight in (s, t)
  Eigen::Vector3d s = Eigen::Vector3d::Zero();    ///< (s, t, unused)
};

/// Quadrature over [-1, 1]^2 (quad) or the unit triangle (tri), 4 points per direction.
std::vector<SurfacePoint> surface_rule(bool quad) {
  double g[5], gw[5];
  gauss_legendre(4, g, gw);
  std::vector<SurfacePoint> out;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      SurfacePoint p;
      if (quad) {
        p.s = {g[i], g[j], 0};
        p.w = gw[i] * gw[j];
      } else {
        const double u = 0.5 * (g[i] + 1), v = 0.5 * (g[j] + 1);
        p.s = {u, v * (1 - u), 0};
        p.w = 0.25 * gw[i] * gw[j] * (1 - u);
      }
      out.push_back(p);
    }
  return out;
}

/// Unit load direction of a PLOAD4 with N given, at basic point x.
Eigen::Vector3d load_direction(const Model& model, const FaceLoad& l, const Eigen::Vector3d& x) {
  const Eigen::Matrix3d A = axes_at(model, l.cid, x, l.ref, "PLOAD4", l.sid, "CID");
  return (A * l.n).normalized();
}

}  // namespace

void shell_face_forces(const Model& model, const Shell& sh, const FaceLoad& l, std::vector<GridForce>& out) {
  const char* card = shell_card(sh);
  std::array<Eigen::Vector3d, 4> x;
  std::array<std::uint32_t, 4> gi{};
  for (int k = 0; k < sh.nnode; ++k) {
    gi[k] = grid_index(model, sh.g[k], sh.ref, card, sh.id, "G" + std::to_string(k + 1));
    x[k] = model.grids[gi[k]].x_basic;
  }
  const bool quad = sh.nnode == 4, directed = l.n.squaredNorm() > 0;
  std::array<Eigen::Vector3d, 4> f;
  for (auto& v : f) v.setZero();
  for (const SurfacePoint& q : surface_rule(quad)) {
    double N[4], Ns[4], Nt[4];
    if (quad) {
      static const double sn[4] = {-1, 1, 1, -1}, tn[4] = {-1, -1, 1, 1};
      for (int k = 0; k < 4; ++k) {
        N[k] = 0.25 * (1 + sn[k] * q.s[0]) * (1 + tn[k] * q.s[1]);
        Ns[k] = 0.25 * sn[k] * (1 + tn[k] * q.s[1]);
        Nt[k] = 0.25 * tn[k] * (1 + sn[k] * q.s[0]);
      }
    } else {
      N[0] = 1 - q.s[0] - q.s[1], N[1] = q.s[0], N[2] = q.s[1];
      Ns[0] = -1, Ns[1] = 1, Ns[2] = 0;
      Nt[0] = -1, Nt[1] = 0, Nt[2] = 1;
    }
    Eigen::Vector3d xs = Eigen::Vector3d::Zero(), xt = Eigen::Vector3d::Zero(), xp = Eigen::Vector3d::Zero();
    double p = 0;
    for (int k = 0; k < sh.nnode; ++k) {
      xs += Ns[k] * x[k];
      xt += Nt[k] * x[k];
      xp += N[k] * x[k];
      p += N[k] * l.p[static_cast<std::size_t>(k)];
    }
    const Eigen::Vector3d ndA = xs.cross(xt);
    const Eigen::Vector3d t = directed ? Eigen::Vector3d(load_direction(model, l, xp) * ndA.norm()) : ndA;
    for (int k = 0; k < sh.nnode; ++k) f[k] += q.w * N[k] * p * t;
  }
  for (int k = 0; k < sh.nnode; ++k) out.push_back({gi[k], f[k]});
}

void solid_face_forces(const Model& model, const Solid& so, const FaceLoad& l, std::vector<GridForce>& out) {
  const char* card = so.card();
  const int corners = so.corners();
  auto corner_of = [&](int grid) {
    for (int k = 0; k < corners; ++k)
      if (so.g[static_cast<std::size_t>(k)] == grid) return k;
    return -1;
  };
  auto bad = [&](const char* field, const std::string& what) {
    fail(model, l.ref, "PLOAD4", l.sid, field, "element " + std::to_string(so.id) + " (" + card + "): " + what);
  };
  if (l.g1 == 0) bad("G1", "G1 is blank; expected a corner grid of the loaded face (required for solids)");
  const int c1 = corner_of(l.g1);
  if (c1 < 0) bad("G1", "grid " + std::to_string(l.g1) + " is not a corner grid of the element");
  const auto& faces = solid_faces(so.shape);
  int face = -1, start = -1;
  if (so.shape == Solid::Shape::Tetra) {
    const int c4 = corner_of(l.g34);
    if (l.g34 == 0 || c4 < 0 || c4 == c1)
      bad("G4", "G4 = " + std::to_string(l.g34) + "; expected the corner grid of the CTETRA that is not on the loaded face");
    for (std::size_t f = 0; f < faces.size(); ++f) {
      bool has4 = false;
      for (int k = 0; k < 3; ++k) has4 = has4 || faces[f].corners[static_cast<std::size_t>(k)] == c4;
      if (!has4) face = static_cast<int>(f);
    }
  } else if (l.g34 == 0) {
    if (so.shape == Solid::Shape::Hexa) bad("G3", "G3 is blank; expected the corner diagonally opposite G1 on the face");
    if (so.shape == Solid::Shape::Pyram)
      bad("G3", "G3 is blank; expected the base corner diagonally opposite G1 (the base) or next to it (the triangle "
                "through both and the apex)");
    face = c1 < 3 ? 0 : 1;  // CPENTA triangular face
  } else if (so.shape == Solid::Shape::Pyram && corner_of(l.g34) >= 0 && corner_of(l.g34) < 4 && c1 < 4 &&
             (c1 - corner_of(l.g34) + 4) % 2 == 1) {
    // CPYRAM triangular face: G1 and G3 adjacent corners of the base (QRG PLOAD4), the face through
    // them and the apex; faces 1..4 start at base corners 0..3 and run to the next one.
    const int c3 = corner_of(l.g34);
    face = 1 + ((c3 - c1 + 4) % 4 == 1 ? c1 : c3);
  } else {
    const int c3 = corner_of(l.g34);
    if (c3 < 0) bad("G3", "grid " + std::to_string(l.g34) + " is not a corner grid of the element");
    for (std::size_t f = 0; f < faces.size() && face < 0; ++f) {
      if (faces[f].ncorner != 4) continue;
      int i1 = -1, i3 = -1;
      for (int k = 0; k < 4; ++k) {
        if (faces[f].corners[static_cast<std::size_t>(k)] == c1) i1 = k;
        if (faces[f].corners[static_cast<std::size_t>(k)] == c3) i3 = k;
      }
      if (i1 >= 0 && i3 >= 0 && (i1 - i3 + 4) % 4 == 2) face = static_cast<int>(f);
    }
    if (face < 0)
      bad("G3", "grids " + std::to_string(l.g1) + " and " + std::to_string(l.g34) +
                    " are not diagonally opposite corners of one quadrilateral face" +
                    (so.shape == Solid::Shape::Pyram ? " nor adjacent corners of the base (a triangular face)" : ""));
  }
  const SolidFace& F = faces[static_cast<std::size_t>(face)];
  for (int k = 0; k < F.ncorner; ++k)
    if (F.corners[static_cast<std::size_t>(k)] == c1) start = k;
  if (start < 0) bad("G1", "grid " + std::to_string(l.g1) + " is not on the face the other grid selects");

  // Grids and geometry.
  std::array<Eigen::Vector3d, 20> x;
  std::array<std::uint32_t, 20> gi{};
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(), face_centre = Eigen::Vector3d::Zero();
  for (int a = 0; a < so.nnode; ++a) {
    gi[static_cast<std::size_t>(a)] = grid_index(model, so.g[static_cast<std::size_t>(a)], so.ref, card, so.id, "G" + std::to_string(so.grid_number(a)));
    x[static_cast<std::size_t>(a)] = model.grids[gi[static_cast<std::size_t>(a)]].x_basic;
    if (a < corners) centre += x[static_cast<std::size_t>(a)] / corners;
  }
  for (int k = 0; k < F.ncorner; ++k) face_centre += x[static_cast<std::size_t>(F.corners[static_cast<std::size_t>(k)])] / F.ncorner;
  // Corner pressures: P1 at G1, then around the face in the order of F.corners.
  double P[8] = {};
  for (int k = 0; k < F.ncorner; ++k) P[F.corners[static_cast<std::size_t>((start + k) % F.ncorner)]] = l.p[static_cast<std::size_t>(k)];

  const bool directed = l.n.squaredNorm() > 0;
  std::array<Eigen::Vector3d, 20> f;
  for (auto& v : f) v.setZero();
  double orientation = 0;  // +1 if ds x dt of the face map points outward
  ShapeValues sv, lin;
  for (const SurfacePoint& q : surface_rule(F.ncorner == 4)) {
    const Eigen::Vector3d xi = F.origin + F.ds * q.s[0] + F.dt * q.s[1];
    solid_shape(so.shape, so.nnode, so.missing_mid, xi, sv);
    solid_shape(so.shape, corners, 0, xi, lin);
    Eigen::Vector3d xs = Eigen::Vector3d::Zero(), xt = Eigen::Vector3d::Zero(), xp = Eigen::Vector3d::Zero();
    for (int a = 0; a < so.nnode; ++a) {
      const Eigen::Vector3d dN(sv.dN[a][0], sv.dN[a][1], sv.dN[a][2]);
      xs += dN.dot(F.ds) * x[static_cast<std::size_t>(a)];
      xt += dN.dot(F.dt) * x[static_cast<std::size_t>(a)];
      xp += sv.N[a] * x[static_cast<std::size_t>(a)];
    }
    double p = 0;
    for (int a = 0; a < corners; ++a) p += lin.N[a] * P[a];
    Eigen::Vector3d ndA = xs.cross(xt);
    if (orientation == 0) orientation = ndA.dot(face_centre - centre) >= 0 ? 1.0 : -1.0;
    ndA *= orientation;  // outward
    const Eigen::Vector3d t = directed ? Eigen::Vector3d(load_direction(model, l, xp) * ndA.norm()) : Eigen::Vector3d(-ndA);
    for (int a = 0; a < so.nnode; ++a) f[static_cast<std::size_t>(a)] += q.w * sv.N[a] * p * t;
  }
  for (int a = 0; a < so.nnode; ++a)
    if (f[static_cast<std::size_t>(a)].squaredNorm() > 0) out.push_back({gi[static_cast<std::size_t>(a)], f[static_cast<std::size_t>(a)]});
}

}  // namespace seflex::fem::detail
