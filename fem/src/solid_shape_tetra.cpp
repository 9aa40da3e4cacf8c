// CTETRA shape functions: linear (4 grids) and quadratic (10 grids), grids in the QRG CTETRA order:
// G1-G4 corners, G5-G10 mid-edge grids of edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4.
#include "solid_shapes.hpp"

namespace seflex::fem::detail {

void tetra_shape(int nnode, const Eigen::Vector3d& xi, ShapeValues& s) {
  s.n = nnode;
  const double L[4] = {1 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
  static const double dL[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  if (nnode == 4) {
    for (int a = 0; a < 4; ++a) {
      s.N[a] = L[a];
      for (int k = 0; k < 3; ++k) s.dN[a][k] = dL[a][k];
    }
    return;
  }
  for (int a = 0; a < 4; ++a) {
    s.N[a] = L[a] * (2 * L[a] - 1);
    for (int k = 0; k < 3; ++k) s.dN[a][k] = (4 * L[a] - 1) * dL[a][k];
  }
  static const int edge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  for (int e = 0; e < 6; ++e) {
    const int i = edge[e][0], j = edge[e][1];
    s.N[4 + e] = 4 * L[i] * L[j];
    for (int k = 0; k < 3; ++k) s.dN[4 + e][k] = 4 * (dL[i][k] * L[j] + L[i] * dL[j][k]);
  }
}

}  // namespace seflex::fem::detail
