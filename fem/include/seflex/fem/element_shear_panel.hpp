#pragma once
// CSHEAR / PSHEAR: Nastran's shear panel, 12 x 12 on the translations of G1-G4 (basic); no rotations.
//
// Element plane (as Nastran's): normal k along the cross product of the diagonals 1-3 and 2-4, x
// along the projection of edge 1-2, y = k x x; the corners projected on it. Projected area PA = half
// the length of the diagonals' cross product. Two parts:
//
// - Shear: one stress mode, the panel's shear flow. The stress field is sigma = s (e1 e2^T + e2 e1^T)
//   with e1, e2 the unit mean directions of the edge pairs 1-2/4-3 and 1-4/2-3: on a parallelogram
//   its edge tractions are pure shear flows q = s t sin(alpha) (alpha the angle between e1 and e2),
//   the stress state of Garvey's panel, whose flexibility it reproduces exactly: complementary energy
//   q^2 PA / (2 G t^2) (1 + 4 G cot^2(alpha) / E) per unit thickness, i.e. NASTRAN's
//   Z = PA / (2 G t) (1 + 2 cot^2(alpha) / (1 + nu)) when G = E / (2 (1 + nu)). A general quadrilateral
//   keeps the field of its mean parallelogram (Garvey's field varies along a tapered panel; the two
//   agree to first order in the taper). Hybrid form (Pian): H = t PA P^T S P (S the plane-stress
//   compliance with MAT1's E, NU, G), G = t int P^T B dA over the bilinear in-plane displacements
//   (exact by 2 x 2 Gauss), K_s = G^T G / H: rank one. On a warped panel the corner forces of the
//   mode get normal "kick" components (the least ones that equilibrate the moment of the in-plane
//   corner forces about the actual corners), so that the six rigid-body motions stay force-free.
// - Extension: rods on the edges (QRG PSHEAR remark 2): on edges 1-2 and 3-4 each of area
//   F1 T PA / (L12 + L34) if F1 <= 1.01 (F1 = 1: the panel fully effective in that direction), else
//   F1 T^2 / 2 (an effective skin width F1 T / 2 on each flange); F2 alike on edges 2-3 and 1-4;
//   axial stiffness E A / L along the actual edge. No Poisson coupling (QRG remark 3).
//
// Mass: lumped, (rho T + NSM) PA split over the corners in proportion to the areas of the triangles
// (i-1, i, i+1) at each corner (equal quarters on a parallelogram), in all three translations.
#include <Eigen/Core>
#include <array>

#include "seflex/fem/element_common.hpp"
#include "seflex/fem/material.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

struct ShearPanelElement {
  std::array<Eigen::Vector3d, 4> x;  ///< basic positions of G1-G4
  double t = 0, nsm = 0, f1 = 0, f2 = 0;
  IsotropicMaterial material;
};

NodeMatrix<4> shear_panel_stiffness(const ShearPanelElement& e);
NodeMatrix<4> shear_panel_mass(const ShearPanelElement& e);  ///< lumped, before WTMASS

/// Projected area PA = |(x3 - x1) x (x4 - x2)| / 2.
double shear_panel_area(const ShearPanelElement& e);

/// Resolve a CSHEAR (PSHEAR, MAT1) of a finalized model; throws InputError for undefined references,
/// a degenerate panel or an interior angle of 180 degrees or more (QRG CSHEAR remark 3).
ShearPanelElement make_shear_panel_element(const Model& model, const ShearPanel& panel);

}  // namespace seflex::fem
