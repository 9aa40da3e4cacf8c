#pragma once
// Isotropic linear-elastic material (MAT1) as the elements use it.
#include <Eigen/Core>

namespace seflex::fem {

/// MAT1 after completion (E, G, nu all set; Nastran's rule G = E / (2 (1 + nu)) for a blank one).
struct IsotropicMaterial {
  int id = 0;
  double E = 0, G = 0, nu = 0, rho = 0;
};

/// Plane-stress constitutive matrix (3 x 3, Voigt order xx, yy, xy with engineering shear strain),
/// Nastran's convention for MAT1: G11 = G22 = E/(1-nu^2), G12 = nu E/(1-nu^2), G33 = G.
inline Eigen::Matrix3d plane_stress(const IsotropicMaterial& m) {
  const double c = m.E / (1.0 - m.nu * m.nu);
  Eigen::Matrix3d D;
  D << c, m.nu * c, 0.0, m.nu * c, c, 0.0, 0.0, 0.0, m.G;
  return D;
}

}  // namespace seflex::fem
