// CPYRAM shape functions: the 5-grid and 13-grid pyramids of Bedrosian (G. Bedrosian, "Shape
// functions and integration formulas for three-dimensional finite element analysis", IJNME 35
// (1992) 95-108; also Zgainski, Coulomb & Marechal, IEEE Trans. Magn. 32 (1996) 1393-1396), grids in
// the QRG CPYRAM order: G1-G4 the base, G5 the apex, G6-G9 the base edges (1-2, 2-3, 3-4, 4-1),
// G10-G13 the edges to the apex (1-5, 2-5, 3-5, 4-5).
// Natural coordinates (solid_shapes.hpp): base at zeta = 0 with corners (xi, eta) = (a, b) =
// (-1,-1) (1,-1) (1,1) (-1,1), apex (0, 0, 1); with d = 1 - zeta the pyramid is |xi|, |eta| <= d.
// No polynomial basis on five points is conforming with both the bilinear base and the linear
// triangles, so the functions are rational in d:
//   5 grids:  L_i = (d + a xi)(d + b eta) / (4 d),  L_5 = zeta;
//   13 grids: corners (a xi + b eta - 1) L_i, apex zeta (2 zeta - 1),
//             base edge along xi at eta = b:  (d^2 - xi^2)(d + b eta) / (2 d)  (along eta likewise),
//             edge from corner (a, b) to the apex: zeta (d + a xi)(d + b eta) / d.
// Both reproduce the complete linear (5) and quadratic (13) polynomials in (xi, eta, zeta), are
// bilinear / serendipity on the base and linear / quadratic on the triangles, so they conform with
// CHEXA 8/20 on a quadrilateral face and CTETRA 4/10 or CPENTA on a triangular one. The functions are
// bounded at the apex but their gradient is not defined there; the quadrature points
// (solid_rules.cpp) never reach it. In the collapsed coordinates (u, v) = (xi, eta) / d they are
// polynomials: the 5-grid pyramid is the trilinear brick with its top face collapsed to the apex.
#include <algorithm>

#include "solid_shapes.hpp"

namespace seflex::fem::detail {
namespace {
constexpr double kA[4] = {-1, 1, 1, -1}, kB[4] = {-1, -1, 1, 1};
}  // namespace

void pyram_shape(int nnode, const Eigen::Vector3d& xi, ShapeValues& s) {
  s.n = nnode;
  const double x = xi[0], y = xi[1], z = xi[2];
  const double d = std::max(1 - z, 1e-14);  // at the apex itself: the limit along the axis
  // L_i = A B / (4 d) with A = d + a x, B = d + b y (dA/dz = dB/dz = -1, d(1/d)/dz = 1/d^2).
  double L[4], dL[4][3], A[4], B[4];
  for (int i = 0; i < 4; ++i) {
    A[i] = d + kA[i] * x;
    B[i] = d + kB[i] * y;
    L[i] = A[i] * B[i] / (4 * d);
    dL[i][0] = kA[i] * B[i] / (4 * d);
    dL[i][1] = kB[i] * A[i] / (4 * d);
    dL[i][2] = -(A[i] + B[i]) / (4 * d) + A[i] * B[i] / (4 * d * d);
  }
  if (nnode == 5) {
    for (int i = 0; i < 4; ++i) {
      s.N[i] = L[i];
      for (int k = 0; k < 3; ++k) s.dN[i][k] = dL[i][k];
    }
    s.N[4] = z;
    s.dN[4][0] = s.dN[4][1] = 0;
    s.dN[4][2] = 1;
    return;
  }
  for (int i = 0; i < 4; ++i) {  // corners: (a x + b y - 1) L_i
    const double f = kA[i] * x + kB[i] * y - 1;
    const double df[3] = {kA[i], kB[i], 0};
    s.N[i] = f * L[i];
    for (int k = 0; k < 3; ++k) s.dN[i][k] = df[k] * L[i] + f * dL[i][k];
  }
  s.N[4] = z * (2 * z - 1);
  s.dN[4][0] = s.dN[4][1] = 0;
  s.dN[4][2] = 4 * z - 1;
  // Base edges G6-G9 (corners 0-1, 1-2, 2-3, 3-0): along xi at eta = b (0-1, 2-3) or along eta at
  // xi = a (1-2, 3-0): N = P Q / (2 d), P = d^2 - t^2 (t the coordinate along the edge), Q = d + c w
  // (w the other one, c its value on the edge).
  for (int e = 0; e < 4; ++e) {
    const bool along_xi = e % 2 == 0;
    const int i = e;  // the edge starts at corner e
    const double t = along_xi ? x : y, w = along_xi ? y : x, c = along_xi ? kB[i] : kA[i];
    const double P = d * d - t * t, Q = d + c * w;
    const double dt = -t * Q / d, dw = c * P / (2 * d);
    const double dz = -(2 * d * Q + P) / (2 * d) + P * Q / (2 * d * d);
    s.N[5 + e] = P * Q / (2 * d);
    s.dN[5 + e][along_xi ? 0 : 1] = dt;
    s.dN[5 + e][along_xi ? 1 : 0] = dw;
    s.dN[5 + e][2] = dz;
  }
  // Edges to the apex G10-G13: z A B / d = 4 z L_i.
  for (int i = 0; i < 4; ++i) {
    s.N[9 + i] = 4 * z * L[i];
    s.dN[9 + i][0] = 4 * z * dL[i][0];
    s.dN[9 + i][1] = 4 * z * dL[i][1];
    s.dN[9 + i][2] = 4 * L[i] + 4 * z * dL[i][2];
  }
}

}  // namespace seflex::fem::detail
