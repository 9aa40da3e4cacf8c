#pragma once
// The plate (bending) part of a triangle on its own: (w, theta_x, theta_y) of corner i at 3 i + 0..2,
// in the element's axes (element_plate_min3.hpp, element_plate_dkt.hpp).
#include <Eigen/Core>

namespace seflex::fem {

using PlateMatrix3 = Eigen::Matrix<double, 9, 9>;
using PlateVector3 = Eigen::Matrix<double, 9, 1>;

}  // namespace seflex::fem
