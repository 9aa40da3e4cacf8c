#pragma once
// Internal: shape functions, quadrature rules and faces of the isoparametric solids (CHEXA 8/20,
// CPENTA 6/15, CTETRA 4/10, CPYRAM 5/13), in Nastran's grid order (QRG CHEXA, CPENTA, CTETRA,
// CPYRAM: the corners, then the mid-edge grids). One shape per file: solid_shape_hexa.cpp,
// solid_shape_penta.cpp, solid_shape_tetra.cpp, solid_shape_pyram.cpp. Natural coordinates
// xi = (xi1, xi2, xi3):
//   HEXA:  xi in [-1, 1]^3; G1-G4 at xi3 = -1 (xi1, xi2 = (-1,-1) (1,-1) (1,1) (-1,1)), G5-G8 above.
//   PENTA: (xi1, xi2) triangle (area coordinates L1 = 1 - xi1 - xi2, L2 = xi1, L3 = xi2) times
//          xi3 in [-1, 1]; G1-G3 at xi3 = -1, G4-G6 at +1.
//   TETRA: L1 = 1 - xi1 - xi2 - xi3, L2 = xi1, L3 = xi2, L4 = xi3.
//   PYRAM: base G1-G4 at xi3 = 0 with (xi1, xi2) as the HEXA's, apex G5 at (0, 0, 1); the pyramid
//          is |xi1|, |xi2| <= 1 - xi3, 0 <= xi3 <= 1.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "seflex/fem/model_solids.hpp"

namespace seflex::fem::detail {

constexpr int kMaxSolidNodes = 20;

/// Shape function values N[a] and natural derivatives dN[a][k] = dN_a / dxi_k of n nodes.
struct ShapeValues {
  int n = 0;
  double N[kMaxSolidNodes] = {};
  double dN[kMaxSolidNodes][3] = {};
};

void hexa_shape(int nnode, const Eigen::Vector3d& xi, ShapeValues& s);   ///< nnode 8 or 20
void penta_shape(int nnode, const Eigen::Vector3d& xi, ShapeValues& s);  ///< nnode 6 or 15
void tetra_shape(int nnode, const Eigen::Vector3d& xi, ShapeValues& s);  ///< nnode 4 or 10
void pyram_shape(int nnode, const Eigen::Vector3d& xi, ShapeValues& s);  ///< nnode 5 or 13 (rational)
/// The shape functions of the element with nnode grids (Solid::g order). nnode between corners and
/// the full count: the quadratic element without the mid-edge grids of missing_mid (Solid), each
/// missing mid-edge function removed and half of it added to the two corners of its edge (Bathe,
/// Finite Element Procedures, sec. 5.3.1); throws std::logic_error if nnode and missing_mid disagree.
void solid_shape(Solid::Shape shape, int nnode, std::uint16_t missing_mid, const Eigen::Vector3d& xi, ShapeValues& s);
/// The corners (0-based) at the ends of mid-edge grid k (0-based among the mid-edge grids).
std::array<int, 2> solid_edge_ends(Solid::Shape shape, int k);

struct QuadraturePoint {
  Eigen::Vector3d xi = Eigen::Vector3d::Zero();
  double w = 0;
};

/// Gauss-Legendre points and weights on [-1, 1], n = 1..5.
void gauss_legendre(int n, double* x, double* w);
/// A rule over the element's natural domain with n points per direction: Gauss n x n x n for the
/// HEXA, a collapsed (Duffy) Gauss rule for the triangle and the tetrahedron, exact for
/// polynomials of degree 2n - 3 in the area/volume coordinates (2n - 1 along the HEXA/PENTA axes).
/// PYRAM: the pyramid as the cube (u, v, t) in [-1, 1]^3 collapsed to its apex, xi3 = (1 + t) / 2,
/// (xi1, xi2) = (1 - xi3) (u, v), Jacobian (1 - xi3)^2 / 2, Gauss n x n x n in (u, v, t) (Duffy's
/// map; the pyramid rules of Felippa, "A compendium of FEM integration formulas for symbolic work",
/// Eng. Comput. 21 (2004) 867-890, its pyramid rules). The 5- and 13-grid shape functions are polynomials of
/// (u, v, xi3), so the rule is exact for them: with n = 2 (linear) and 3 (quadratic) for the stiffness
/// of a pyramid whose base is a parallelogram.
std::vector<QuadraturePoint> solid_rule(Solid::Shape shape, int n);

/// A face of a solid: its corner grids (0-based positions in the element's grid list), ordered
/// around the face so that the right-hand rule gives the outward normal of an element numbered as
/// the QRG figures show, and the map from face coordinates (s, t) to the element's xi:
///   quadrilateral faces: (s, t) in [-1, 1]^2;  triangular faces: s, t >= 0, s + t <= 1.
struct SolidFace {
  int ncorner = 0;
  std::array<int, 4> corners{};
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< xi = origin + ds * s + dt * t
  Eigen::Vector3d ds = Eigen::Vector3d::Zero(), dt = Eigen::Vector3d::Zero();
};
/// The faces of a shape (6 for HEXA, 5 for PENTA: two triangles then three quadrilaterals, 4 for TETRA,
/// 5 for PYRAM: the base then the four triangles 1-2-5, 2-3-5, 3-4-5, 4-1-5).
const std::vector<SolidFace>& solid_faces(Solid::Shape shape);

}  // namespace seflex::fem::detail
