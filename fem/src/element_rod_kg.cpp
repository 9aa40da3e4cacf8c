// CROD / CONROD differential stiffness and axial force (see element_rod.hpp).
#include "seflex/common/error.hpp"
#include "seflex/fem/element_rod.hpp"

namespace seflex::fem {

double rod_axial_force(const RodElement& e, const Eigen::Matrix<double, 12, 1>& u_basic) {
  const Eigen::Vector3d d = e.x_B - e.x_A;
  const double L = d.norm();
  SEFLEX_DEMAND(L > 0.0, "rod of zero length");
  return e.material.E * e.A / L * (d / L).dot(u_basic.segment<3>(6) - u_basic.segment<3>(0));
}

NodeMatrix<2> rod_geometric_stiffness(const RodElement& e, double N) {
  const double L = (e.x_B - e.x_A).norm();
  SEFLEX_DEMAND(L > 0.0, "rod of zero length");
  const Eigen::Matrix3d k = (N / L) * Eigen::Matrix3d::Identity();
  NodeMatrix<2> K = NodeMatrix<2>::Zero();
  K.block<3, 3>(0, 0) = k;
  K.block<3, 3>(6, 6) = k;
  K.block<3, 3>(0, 6) = -k;
  K.block<3, 3>(6, 0) = -k;
  return K;
}

}  // namespace seflex::fem
