#pragma once
// MIN4T: the bending + transverse shear part of CQUAD4 under PARAM QUAD4TYP MIN4T (MYSTRAN's default
// QUAD4; assembly.hpp MystranPlate).
//
// Four MIN3 triangles (element_plate_min3.hpp) G1-G2-C, G2-G3-C, G3-G4-C, G4-G1-C around a centre
// node C at the intersection of the diagonals; C's (w, theta_x, theta_y) are condensed statically,
// K = K_aa - K_ac K_cc^-1 K_ca and f = f_a - K_ac K_cc^-1 f_c for the pressure load (A. Tessler et
// al., "A four-node, shear-deformable shell element developed via explicit Kirchhoff constraints",
// IJNME 49 (2000); MYSTRAN QPLT3 with PARAM MIN4TRED = 'STC', its default). Each sub-triangle has its
// own shear factor phi^2 from its own bending/shear diagonals with the factor cb (PARAM CBMIN4T,
// 3.6: with it MYSTRAN 12.0's published AQ3U2S004 eigenvalues are reproduced to 7 digits, although
// MYSTRAN's present TPLT2 sets CBMIN4T = CBMIN3 for these sub-triangles; see assembly.hpp). The
// sub-triangles are formed in the quadrilateral's own axes (MIN3 is invariant under a rotation of
// the plane for an isotropic section; for an anisotropic one the section is the quad's, which is
// what MYSTRAN's rotation of the material by the sub-triangle angle achieves).
#include <Eigen/Core>
#include <array>

namespace seflex::fem {

using PlateMatrix4 = Eigen::Matrix<double, 12, 12>;  ///< (w, theta_x, theta_y) of corner i at 3 i + 0..2
using PlateVector4 = Eigen::Matrix<double, 12, 1>;

/// Bending + shear stiffness of MIN4T; corners p counter-clockwise about +z (a convex quadrilateral),
/// D, S the section's bending and transverse shear stiffness in the same axes, cb the shear factor.
PlateMatrix4 min4t_stiffness(const std::array<Eigen::Vector2d, 4>& p, const Eigen::Matrix3d& D, const Eigen::Matrix2d& S,
                             double cb);

/// Work-equivalent load of a uniform pressure q along +z (the sub-triangles' MIN3 loads, the centre
/// condensed with the stiffness): forces and corner moments.
PlateVector4 min4t_pressure_load(const std::array<Eigen::Vector2d, 4>& p, const Eigen::Matrix3d& D,
                                 const Eigen::Matrix2d& S, double cb, double q);

}  // namespace seflex::fem
