// CHEXA shape functions: trilinear (8 grids) and the 20-grid serendipity brick (Zienkiewicz & Taylor,
// The Finite Element Method, vol. 1, 5th ed., sec. 8.7), grids in the QRG CHEXA order.
#include "solid_shapes.hpp"

namespace seflex::fem::detail {
namespace {
// Natural coordinates of the 20 grids: G1-G8 corners, G9-G12 bottom edges (1-2, 2-3, 3-4, 4-1),
// G13-G16 vertical edges (1-5, 2-6, 3-7, 4-8), G17-G20 top edges (5-6, 6-7, 7-8, 8-5).
constexpr double kNode[20][3] = {
    {-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1},  {-1, 1, 1},
    {0, -1, -1},  {1, 0, -1},  {0, 1, -1}, {-1, 0, -1}, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0},  {-1, 1, 0},
    {0, -1, 1},   {1, 0, 1},   {0, 1, 1},  {-1, 0, 1}};
}  // namespace

void hexa_shape(int nnode, const Eigen::Vector3d& xi, ShapeValues& s) {
  s.n = nnode;
  const double x = xi[0], y = xi[1], z = xi[2];
  if (nnode == 8) {
    for (int a = 0; a < 8; ++a) {
      const double xa = kNode[a][0], ya = kNode[a][1], za = kNode[a][2];
      const double fx = 1 + xa * x, fy = 1 + ya * y, fz = 1 + za * z;
      s.N[a] = 0.125 * fx * fy * fz;
      s.dN[a][0] = 0.125 * xa * fy * fz;
      s.dN[a][1] = 0.125 * fx * ya * fz;
      s.dN[a][2] = 0.125 * fx * fy * za;
    }
    return;
  }
  for (int a = 0; a < 20; ++a) {
    const double xa = kNode[a][0], ya = kNode[a][1], za = kNode[a][2];
    const double fx = 1 + xa * x, fy = 1 + ya * y, fz = 1 + za * z;
    if (a < 8) {  // corner: (1/8) fx fy fz (xa x + ya y + za z - 2)
      const double g = xa * x + ya * y + za * z - 2;
      s.N[a] = 0.125 * fx * fy * fz * g;
      s.dN[a][0] = 0.125 * (xa * fy * fz * g + fx * fy * fz * xa);
      s.dN[a][1] = 0.125 * (ya * fx * fz * g + fx * fy * fz * ya);
      s.dN[a][2] = 0.125 * (za * fx * fy * g + fx * fy * fz * za);
    } else if (xa == 0) {  // (1/4)(1 - x^2) fy fz
      s.N[a] = 0.25 * (1 - x * x) * fy * fz;
      s.dN[a][0] = -0.5 * x * fy * fz;
      s.dN[a][1] = 0.25 * (1 - x * x) * ya * fz;
      s.dN[a][2] = 0.25 * (1 - x * x) * fy * za;
    } else if (ya == 0) {
      s.N[a] = 0.25 * (1 - y * y) * fx * fz;
      s.dN[a][0] = 0.25 * (1 - y * y) * xa * fz;
      s.dN[a][1] = -0.5 * y * fx * fz;
      s.dN[a][2] = 0.25 * (1 - y * y) * fx * za;
    } else {
      s.N[a] = 0.25 * (1 - z * z) * fx * fy;
      s.dN[a][0] = 0.25 * (1 - z * z) * xa * fy;
      s.dN[a][1] = 0.25 * (1 - z * z) * fx * ya;
      s.dN[a][2] = -0.5 * z * fx * fy;
    }
  }
}

}  // namespace seflex::fem::detail
