// CONM1 element (see element_conm1.hpp).
#include "seflex/fem/element_conm1.hpp"

#include <Eigen/Eigenvalues>

#include "model_lookup.hpp"

namespace seflex::fem {

Matrix6 conm1_mass(const Model& model, const Conm1& c) {
  const Grid& g = model.grids[detail::grid_index(model, c.grid, c.ref, "CONM1", c.id, "3 (G)")];
  const Eigen::Matrix3d A = detail::axes_at(model, c.cid, g.x_basic, c.ref, "CONM1", c.id, "4 (CID)");
  const Matrix6 M = 0.5 * (c.M + c.M.transpose());
  const Eigen::SelfAdjointEigenSolver<Matrix6> es(M, Eigen::EigenvaluesOnly);
  const double scale = M.cwiseAbs().maxCoeff();
  if (!(es.eigenvalues().minCoeff() >= -1e-12 * scale))
    detail::fail(model, c.ref, "CONM1", c.id, "5-25 (Mij)",
                 "the mass matrix has a negative eigenvalue (" + std::to_string(es.eigenvalues().minCoeff()) +
                     "); expected a positive semi-definite matrix");
  NodeMatrix<1> Mb = M;
  rotate_local_to_basic<1>(A, Mb);
  return Mb;
}

}  // namespace seflex::fem
