#pragma once
// CBUSH / PBUSH: a generalized spring between grids GA and GB (or from GA to ground) acting at one
// point P, with the stiffnesses K1-K6 of PBUSH along and about the element axes (MSC Nastran QRG,
// CBUSH and PBUSH).
//
// Element axes E (columns of R_BE, basic): system CID at GA if CID >= 0; otherwise x along GA -> GB,
// z = x cross v / |x cross v|, y = z cross x, v the orientation vector (GO - GA, or X1-X3 in GA's
// displacement system).
// Spring point P: on the line GA-GB at GA + S (GB - GA) (OCID = -1, S default 0.5), or
// GA + (S1, S2, S3) in system OCID (OCID >= 0). Both ends are rigidly linked to P
// (u_P = u_G + theta_G x (P - G)), and the force is K (u_P^B - u_P^A) in element axes:
//   K_AB = T^T [Ke -Ke; -Ke Ke] T,  Ke = R_BE diag(K1..K6) R_BE^T per 3 x 3 block,
//   T = blockdiag(rigid_link(P - x_A), rigid_link(P - x_B));
// grounded (GB blank): K_A = rigid_link(P - x_A)^T Ke rigid_link(P - x_A) with P = x_A unless OCID
// gives an offset. 12 x 12 (6 x 6 grounded) on the grids' dofs in basic.
// CBUSH1D / PBUSH1D (Bush::one_d): the same with K1 = K and K2-K6 = 0; with CID blank the x axis runs
// from GA to GB and y, z are any perpendicular pair (nothing acts along them); its mass M is lumped,
// half on each grid's translations (grounded: half on GA's, the other half on the ground).
#include <Eigen/Core>

#include "seflex/fem/element_common.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

struct BushElement {
  Eigen::Vector3d x_A = Eigen::Vector3d::Zero(), x_B = Eigen::Vector3d::Zero();  ///< basic
  Eigen::Vector3d p_P = Eigen::Vector3d::Zero();      ///< spring point, basic
  Eigen::Matrix3d R_BE = Eigen::Matrix3d::Identity(); ///< element axes (columns) in basic
  std::array<double, 6> k{};                          ///< K1..K6 in element axes
  bool grounded = false;                              ///< GB blank
  double mass = 0;                                    ///< PBUSH1D M (total); 0 for a CBUSH
};

/// Resolve a CBUSH of a finalized model. Throws InputError for an undefined PBUSH, grid or system,
/// coincident (or grounded) ends without CID, a missing or parallel orientation vector.
BushElement make_bush_element(const Model& model, const Bush& b);

/// 12 x 12 stiffness on (GA, GB) in basic (grounded: only the top-left 6 x 6 block is non-zero).
NodeMatrix<2> bush_stiffness(const BushElement& e);

/// 12 x 12 lumped mass on (GA, GB) in basic: mass / 2 on each grid's translations (grounded: on GA's
/// only). Zero for a CBUSH (PBUSH M is not modelled).
NodeMatrix<2> bush_mass(const BushElement& e);

}  // namespace seflex::fem
