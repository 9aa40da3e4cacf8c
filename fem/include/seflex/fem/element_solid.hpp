#pragma once
// CHEXA (8-20 grids), CPENTA (6-15), CTETRA (4-10), CPYRAM (5-13): isoparametric linear-elastic
// solids with PSOLID and an isotropic MAT1 or an anisotropic MAT9. Matrices are 3N x 3N on the
// translations T1 T2 T3 of the N grids (grid after grid, BASIC components); solids give no rotational
// stiffness or mass (assembly puts these blocks into the 6-dof grid blocks; AUTOSPC removes
// rotations nothing else stiffens).
//
// Stiffness K = int B^T D B dV, D the elasticity matrix in basic axes (Voigt xx yy zz xy yz zx,
// engineering shear strains): MAT1 isotropic (lambda = E nu / ((1 + nu)(1 - 2 nu)), mu =
// E / (2 (1 + nu)), nu < 0.5); MAT9 its G matrix in the PSOLID CORDM axes, rotated to basic
// (D = T^T G T, eps_CORDM = T eps_basic), positive definite.
// Some mid-edge grids blank (CHEXA 9-19, CPENTA 7-14, CTETRA 5-9, CPYRAM 6-12 grids): that edge is straight and
// its displacement linear (QRG). The shape functions are the full quadratic element's with the
// missing mid-edge functions removed and half of each added to the two corners of its edge, which
// is the corner correction of the variable-number-of-nodes elements (Bathe, Finite Element
// Procedures, 1996, sec. 5.3.1: elements with a variable number of nodes, 2-D and 3-D):
//   N_corner = N_corner,linear - 1/2 sum over the mid-edge grids present on its edges of N_mid.
// Integration, mass lumping and checks are those of the full quadratic element.
// Integration (PSOLID IN / ISOP, docs/nastran-support.md):
// - CHEXA 8, IN blank or BUBBLE (MSC's default "reduced shear with bubble functions"): 2 x 2 x 2
//   Gauss with the three incompatible bubble modes 1 - xi_k^2 per displacement component, condensed
//   statically; their strains use the centre Jacobian scaled by det J0 / det J so that the element
//   passes the constant-strain patch test on any shape (Wilson, Taylor, Doherty & Ghaboussi,
//   "Incompatible displacement models", 1973; Taylor, Beresford & Wilson, IJNME 10 (1976)
//   1211-1219). Exact in pure bending on a rectangular brick: no shear locking.
//   IN = TWO with ISOP = FULL: plain 2 x 2 x 2 Gauss. IN = THREE: 3 x 3 x 3 Gauss.
//   IN = TWO with ISOP blank or REDUCED (the QRG's "reduced shear only"): 2 x 2 x 2 Gauss with each
//   shear strain averaged over the four points of its own natural plane, on each side of it (the
//   selective substitution of MYSTRAN's HEXA8, Source/EMG/EMG5/HEXA.f90; solid_kinematics.hpp):
//   exact in pure bending on a rectangular brick, no spurious zero-energy mode.
// - CPENTA 6, CTETRA 4: full integration (exact for the straight-sided element), no bubbles.
// - CPYRAM 5 and 13: Bedrosian's rational pyramids (solid_shape_pyram.cpp) on the collapsed-cube
//   Gauss rule (solid_shapes.hpp), 2 and 3 points per direction, exact for a parallelogram base;
//   PSOLID IN/ISOP change nothing on the 5-grid one, and the 13-grid one refuses reduced
//   integration as the other quadratic solids do.
// - CHEXA 20 (3 x 3 x 3 Gauss), CPENTA 15 and CTETRA 10 (collapsed Gauss rules, 3 points per
//   direction, exact for straight sides): full integration; reduced integration of the quadratic
//   solids (IN = TWO) is refused by the reader.
// Mass (before WTMASS): coupled (COUPMASS > 0) rho int N_a N_b dV on each translation; lumped
// (Nastran's default): rho int N_a dV for the linear solids (V/8 per grid of a parallelepiped), and
// for the quadratic ones, whose int N_a dV are negative at the corners, the diagonal of the coupled
// mass scaled to the element mass (Hinton, Rock & Zienkiewicz, "A note on mass lumping and related
// processes in the finite element method", Earthquake Eng. Struct. Dyn. 4 (1976) 245-249).
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "seflex/fem/element_common.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

struct SolidElement {
  enum class Scheme : unsigned char { Gauss, IncompatibleModes, ReducedShear };
  Solid::Shape shape = Solid::Shape::Hexa;
  int nnode = 8;
  std::uint16_t missing_mid = 0;                               ///< Solid::missing_mid (nnode > corners)
  std::array<Eigen::Vector3d, 20> x{};                         ///< positions of Solid::g[0..nnode), basic
  Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();  ///< elasticity, basic axes
  double rho = 0;
  double alpha = 0, tref = 0;                                  ///< MAT1 ALPHA (MAT9: 1 if any Ai), TREF
  /// Thermal strain per unit alpha and degree, basic Voigt (MAT1: 1 1 1 0 0 0; MAT9: A1-A6 rotated).
  Eigen::Matrix<double, 6, 1> thermal_strain = (Eigen::Matrix<double, 6, 1>() << 1, 1, 1, 0, 0, 0).finished();
  Scheme scheme = Scheme::Gauss;
  int points = 2;                                              ///< quadrature points per direction
};

/// Isotropic elasticity matrix (6 x 6, Voigt xx yy zz xy yz zx with engineering shear strains).
Eigen::Matrix<double, 6, 6> isotropic_elasticity(double E, double nu);

/// Stiffness (3N x 3N, basic translations).
Eigen::MatrixXd solid_stiffness(const SolidElement& e);
/// Mass (3N x 3N, basic translations), before WTMASS.
Eigen::MatrixXd solid_mass(const SolidElement& e, MassKind kind);
/// Volume int dV.
double solid_volume(const SolidElement& e);

/// Equivalent grid loads (3N, basic translations) of the thermal strain alpha (T - tref)
/// e.thermal_strain ((1 1 1 0 0 0) for an isotropic solid), T interpolated from the grid
/// temperatures dT_grid = T_a - tref (size N) with the shape functions (as Nastran and MYSTRAN do
/// for solids):
///   f = int B^T D eps_T dV, and with bubble modes (IncompatibleModes) f - K_ci K_ii^-1 f_i, f_i the
///   same integral over the bubble strains (zero for a uniform temperature, ibid.).
/// Its response in an unconstrained element is the free thermal expansion when the temperature is
/// uniform. Implemented in element_solid_thermal.cpp.
Eigen::VectorXd solid_thermal_load(const SolidElement& e, double alpha, const Eigen::Ref<const Eigen::VectorXd>& dT_grid);

/// Corner grids (0-based positions in the element's grid list) of each face of a shape, ordered so
/// that the right-hand rule gives the outward normal of an element numbered as the QRG figures show:
/// CHEXA 6 quadrilaterals; CPENTA 2 triangles then 3 quadrilaterals; CTETRA 4 triangles; CPYRAM the
/// base then 4 triangles.
std::vector<std::vector<int>> solid_face_corners(Solid::Shape shape);

/// Resolve a CHEXA/CPENTA/CTETRA/CPYRAM of a finalized model: grids, PSOLID, MAT1 or MAT9, integration
/// scheme. Throws InputError for undefined references, a material that is not a MAT1 or MAT9, a MAT1
/// with nu >= 0.5 or E <= 0, a MAT9 that is not positive definite or whose CORDM is not 0 or a
/// rectangular system, a distorted element (Jacobian determinant zero or changing sign inside the
/// element), or (unless mass_only: the mass does not depend on it) an integration scheme not
/// modelled (PSOLID IN / ISOP).
SolidElement make_solid_element(const Model& model, const Solid& solid, bool mass_only = false);

}  // namespace seflex::fem
