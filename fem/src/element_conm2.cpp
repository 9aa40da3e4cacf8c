// CONM2 element (see element_conm2.hpp).
#include "seflex/fem/element_conm2.hpp"

#include <array>

#include "model_lookup.hpp"

namespace seflex::fem {

Matrix6 conm2_mass(const Conm2Element& e) {
  NodeMatrix<1> M = NodeMatrix<1>::Zero();
  M.topLeftCorner<3, 3>() = e.m * Eigen::Matrix3d::Identity();
  M.bottomRightCorner<3, 3>() = e.J;
  apply_node_offsets<1>(std::array<Eigen::Vector3d, 1>{e.offset}, M);
  return M;
}

Conm2Element make_conm2_element(const Model& model, const Conm2& c) {
  Conm2Element e;
  const Grid& g = model.grids[detail::grid_index(model, c.grid, c.ref, "CONM2", c.id, "3 (G)")];
  e.x_grid = g.x_basic;
  e.m = c.m;
  Eigen::Matrix3d J;
  J << c.I11, -c.I21, -c.I31, -c.I21, c.I22, -c.I32, -c.I31, -c.I32, c.I33;
  if (c.cid == -1) {
    e.offset = c.x - g.x_basic;
    e.J = J;
  } else {
    const Eigen::Matrix3d A = detail::axes_at(model, c.cid, g.x_basic, c.ref, "CONM2", c.id, "4 (CID)");
    e.offset = A * c.x;
    e.J = A * J * A.transpose();
  }
  return e;
}

}  // namespace seflex::fem
