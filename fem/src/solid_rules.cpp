// Quadrature rules and faces of the solids (solid_shapes.hpp).
#include <cmath>

#include "seflex/common/error.hpp"
#include "solid_shapes.hpp"

namespace seflex::fem::detail {

void gauss_legendre(int n, double* x, double* w) {
  SEFLEX_DEMAND(n >= 1 && n <= 5, "gauss_legendre: 1 to 5 points");
  switch (n) {
    case 1: x[0] = 0; w[0] = 2; return;
    case 2: x[0] = -1 / std::sqrt(3.0); x[1] = -x[0]; w[0] = w[1] = 1; return;
    case 3:
      x[0] = -std::sqrt(0.6); x[1] = 0; x[2] = -x[0];
      w[0] = w[2] = 5.0 / 9.0; w[1] = 8.0 / 9.0;
      return;
    case 4: {
      const double a = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(1.2)), b = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(1.2));
      const double wa = (18 + std::sqrt(30.0)) / 36, wb = (18 - std::sqrt(30.0)) / 36;
      x[0] = -b; x[1] = -a; x[2] = a; x[3] = b;
      w[0] = w[3] = wb; w[1] = w[2] = wa;
      return;
    }
    default: {
      const double a = std::sqrt(5 - 2 * std::sqrt(10.0 / 7.0)) / 3, b = std::sqrt(5 + 2 * std::sqrt(10.0 / 7.0)) / 3;
      const double wa = (322 + 13 * std::sqrt(70.0)) / 900, wb = (322 - 13 * std::sqrt(70.0)) / 900;
      x[0] = -b; x[1] = -a; x[2] = 0; x[3] = a; x[4] = b;
      w[0] = w[4] = wb; w[1] = w[3] = wa; w[2] = 128.0 / 225.0;
      return;
    }
  }
}

std::vector<QuadraturePoint> solid_rule(Solid::Shape shape, int n) {
  double g[5], gw[5];
  gauss_legendre(n, g, gw);
  std::vector<QuadraturePoint> q;
  q.reserve(static_cast<std::size_t>(n * n * n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        QuadraturePoint p;
        const double u = 0.5 * (g[i] + 1), v = 0.5 * (g[j] + 1);
        switch (shape) {
          case Solid::Shape::Hexa:
            p.xi = {g[i], g[j], g[k]};
            p.w = gw[i] * gw[j] * gw[k];
            break;
          case Solid::Shape::Penta:  // triangle (u, v(1-u)), Jacobian (1-u), times Gauss in xi3
            p.xi = {u, v * (1 - u), g[k]};
            p.w = 0.25 * gw[i] * gw[j] * gw[k] * (1 - u);
            break;
          case Solid::Shape::Tetra: {  // (u, v(1-u), w(1-u)(1-v)), Jacobian (1-u)^2 (1-v)
            const double w = 0.5 * (g[k] + 1);
            p.xi = {u, v * (1 - u), w * (1 - u) * (1 - v)};
            p.w = 0.125 * gw[i] * gw[j] * gw[k] * (1 - u) * (1 - u) * (1 - v);
            break;
          }
          case Solid::Shape::Pyram: {  // ((1-z) g_i, (1-z) g_j, z), z = (1 + g_k) / 2, Jacobian (1-z)^2 / 2
            const double z = 0.5 * (g[k] + 1);
            p.xi = {(1 - z) * g[i], (1 - z) * g[j], z};
            p.w = 0.5 * gw[i] * gw[j] * gw[k] * (1 - z) * (1 - z);
            break;
          }
        }
        q.push_back(p);
      }
  return q;
}

namespace {
SolidFace face(std::initializer_list<int> c, Eigen::Vector3d o, Eigen::Vector3d ds, Eigen::Vector3d dt) {
  SolidFace f;
  f.ncorner = static_cast<int>(c.size());
  int k = 0;
  for (const int v : c) f.corners[static_cast<std::size_t>(k++)] = v;
  f.origin = o;
  f.ds = ds;
  f.dt = dt;
  return f;
}
}  // namespace

const std::vector<SolidFace>& solid_faces(Solid::Shape shape) {
  using V = Eigen::Vector3d;
  static const std::vector<SolidFace> hexa = {
      face({0, 3, 2, 1}, V(0, 0, -1), V(1, 0, 0), V(0, 1, 0)), face({4, 5, 6, 7}, V(0, 0, 1), V(1, 0, 0), V(0, 1, 0)),
      face({0, 1, 5, 4}, V(0, -1, 0), V(1, 0, 0), V(0, 0, 1)), face({1, 2, 6, 5}, V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)),
      face({2, 3, 7, 6}, V(0, 1, 0), V(1, 0, 0), V(0, 0, 1)),  face({3, 0, 4, 7}, V(-1, 0, 0), V(0, 1, 0), V(0, 0, 1))};
  static const std::vector<SolidFace> penta = {
      face({0, 2, 1}, V(0, 0, -1), V(1, 0, 0), V(0, 1, 0)),
      face({3, 4, 5}, V(0, 0, 1), V(1, 0, 0), V(0, 1, 0)),
      face({0, 1, 4, 3}, V(0.5, 0, 0), V(0.5, 0, 0), V(0, 0, 1)),
      face({1, 2, 5, 4}, V(0.5, 0.5, 0), V(-0.5, 0.5, 0), V(0, 0, 1)),
      face({2, 0, 3, 5}, V(0, 0.5, 0), V(0, 0.5, 0), V(0, 0, 1))};
  static const std::vector<SolidFace> tetra = {
      face({0, 2, 1}, V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)), face({0, 1, 3}, V(0, 0, 0), V(1, 0, 0), V(0, 0, 1)),
      face({0, 3, 2}, V(0, 0, 0), V(0, 1, 0), V(0, 0, 1)), face({1, 2, 3}, V(1, 0, 0), V(-1, 1, 0), V(-1, 0, 1))};
  static const std::vector<SolidFace> pyram = {
      face({0, 3, 2, 1}, V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)),  face({0, 1, 4}, V(-1, -1, 0), V(2, 0, 0), V(1, 1, 1)),
      face({1, 2, 4}, V(1, -1, 0), V(0, 2, 0), V(-1, 1, 1)), face({2, 3, 4}, V(1, 1, 0), V(-2, 0, 0), V(-1, -1, 1)),
      face({3, 0, 4}, V(-1, 1, 0), V(0, -2, 0), V(1, -1, 1))};
  switch (shape) {
    case Solid::Shape::Hexa: return hexa;
    case Solid::Shape::Penta: return penta;
    case Solid::Shape::Pyram: return pyram;
    default: return tetra;
  }
}

}  // namespace seflex::fem::detail
