// Element results of CHEXA/CPENTA/CTETRA/CPYRAM: stresses at the centroid in basic axes (element_results.hpp).
// The CHEXA 8 bubble modes have zero strain at the centre (d(1 - xi^2)/dxi = 0), so the compatible
// strain there is the element's.
#include "seflex/fem/element_results.hpp"
#include "seflex/fem/element_solid.hpp"
#include "solid_kinematics.hpp"

namespace seflex::fem {

Eigen::Matrix<double, 6, 1> solid_results(const SolidElement& e, const Eigen::Ref<const Eigen::VectorXd>& u) {
  const Eigen::Vector3d xi = e.shape == Solid::Shape::Hexa    ? Eigen::Vector3d::Zero()
                             : e.shape == Solid::Shape::Penta ? Eigen::Vector3d(1.0 / 3, 1.0 / 3, 0)
                             : e.shape == Solid::Shape::Pyram ? Eigen::Vector3d(0, 0, 0.25)
                                                              : Eigen::Vector3d(0.25, 0.25, 0.25);
  detail::SolidPointData p;
  detail::evaluate(e, xi, p);
  return e.D * (detail::strain_matrix(e, p) * u);
}

}  // namespace seflex::fem
