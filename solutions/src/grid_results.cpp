// Grid results in the basic system (grid_results.hpp).
#include "seflex/solutions/grid_results.hpp"

#include "seflex/common/error.hpp"
#include "seflex/fem/assembly.hpp"

namespace seflex::solutions {

GridTable grid_vectors_basic(const fem::Model& model, const fem::DofMap& dofs, const Eigen::Ref<const Eigen::VectorXd>& v_g) {
  SEFLEX_DEMAND(v_g.size() == dofs.size(), "grid_vectors_basic: vector does not match the dof map");
  const auto axes = fem::grid_cd_axes(model);
  GridTable out(dofs.n_grids, 6);
  for (Eigen::Index i = 0; i < dofs.n_grids; ++i) {
    const Eigen::Vector3d t = v_g.segment<3>(dofs.grid_dof(i, 1)), r = v_g.segment<3>(dofs.grid_dof(i, 4));
    const auto& A = axes[static_cast<std::size_t>(i)];
    out.block<1, 3>(i, 0) = (A ? Eigen::Vector3d(*A * t) : t).transpose();
    out.block<1, 3>(i, 3) = (A ? Eigen::Vector3d(*A * r) : r).transpose();
  }
  return out;
}

Eigen::Matrix<double, 6, 1> resultant_basic(const fem::Model& model, const fem::DofMap& dofs,
                                            const Eigen::Ref<const Eigen::VectorXd>& f_g) {
  const GridTable f = grid_vectors_basic(model, dofs, f_g);
  Eigen::Matrix<double, 6, 1> R = Eigen::Matrix<double, 6, 1>::Zero();
  for (Eigen::Index i = 0; i < f.rows(); ++i) {
    const Eigen::Vector3d force = f.block<1, 3>(i, 0).transpose(), moment = f.block<1, 3>(i, 3).transpose();
    R.head<3>() += force;
    R.tail<3>() += model.grids[static_cast<std::size_t>(i)].x_basic.cross(force) + moment;
  }
  return R;
}

}  // namespace seflex::solutions
