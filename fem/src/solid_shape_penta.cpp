// CPENTA shape functions: the 6-grid wedge (linear triangle x linear) and the 15-grid wedge
// (quadratic serendipity; Zienkiewicz & Taylor, The Finite Element Method, vol. 1, 5th ed., sec.
// 8.8), grids in the QRG CPENTA order: G1-G3 bottom, G4-G6 top, G7-G9 bottom edges (1-2, 2-3, 3-1),
// G10-G12 vertical edges (1-4, 2-5, 3-6), G13-G15 top edges (4-5, 5-6, 6-4).
#include "solid_shapes.hpp"

namespace seflex::fem::detail {

void penta_shape(int nnode, const Eigen::Vector3d& xi, ShapeValues& s) {
  s.n = nnode;
  // Area coordinates and their derivatives with respect to (xi1, xi2).
  const double L[3] = {1 - xi[0] - xi[1], xi[0], xi[1]};
  const double dL[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
  const double z = xi[2];
  if (nnode == 6) {
    for (int h = 0; h < 2; ++h) {
      const double zh = h == 0 ? -1.0 : 1.0, fz = 0.5 * (1 + zh * z);
      for (int i = 0; i < 3; ++i) {
        const int a = 3 * h + i;
        s.N[a] = L[i] * fz;
        s.dN[a][0] = dL[i][0] * fz;
        s.dN[a][1] = dL[i][1] * fz;
        s.dN[a][2] = L[i] * 0.5 * zh;
      }
    }
    return;
  }
  // Corners: N = L_i [(2 L_i - 1)(1 + zh z) - (1 - z^2)] / 2.
  for (int h = 0; h < 2; ++h) {
    const double zh = h == 0 ? -1.0 : 1.0;
    for (int i = 0; i < 3; ++i) {
      const int a = 3 * h + i;
      const double g = (2 * L[i] - 1) * (1 + zh * z) - (1 - z * z);
      const double dg_dL = 2 * (1 + zh * z);
      const double dg_dz = (2 * L[i] - 1) * zh + 2 * z;
      s.N[a] = 0.5 * L[i] * g;
      for (int k = 0; k < 2; ++k) s.dN[a][k] = 0.5 * dL[i][k] * (g + L[i] * dg_dL);
      s.dN[a][2] = 0.5 * L[i] * dg_dz;
    }
  }
  // Triangle edges at the bottom (6..8) and top (12..14): 2 L_i L_j (1 + zh z).
  static const int edge[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  for (int h = 0; h < 2; ++h) {
    const double zh = h == 0 ? -1.0 : 1.0, fz = 1 + zh * z;
    for (int e = 0; e < 3; ++e) {
      const int a = (h == 0 ? 6 : 12) + e, i = edge[e][0], j = edge[e][1];
      s.N[a] = 2 * L[i] * L[j] * fz;
      for (int k = 0; k < 2; ++k) s.dN[a][k] = 2 * (dL[i][k] * L[j] + L[i] * dL[j][k]) * fz;
      s.dN[a][2] = 2 * L[i] * L[j] * zh;
    }
  }
  // Vertical edges (9..11): L_i (1 - z^2).
  for (int i = 0; i < 3; ++i) {
    const int a = 9 + i;
    s.N[a] = L[i] * (1 - z * z);
    for (int k = 0; k < 2; ++k) s.dN[a][k] = dL[i][k] * (1 - z * z);
    s.dN[a][2] = -2 * z * L[i];
  }
}

}  // namespace seflex::fem::detail
