// GENEL (see element_genel.hpp).
#include "seflex/fem/element_genel.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <string>

#include "constraint_equations.hpp"
#include "model_lookup.hpp"
#include "seflex/fem/assembly.hpp"

namespace seflex::fem {
namespace {

/// The symmetric n x n matrix of its lower triangle given by columns.
Eigen::MatrixXd from_lower_columns(const std::vector<double>& v, Eigen::Index n) {
  Eigen::MatrixXd A(n, n);
  std::size_t k = 0;
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = j; i < n; ++i) A(i, j) = A(j, i) = v[k++];
  return A;
}

std::string dof_text(const Genel::Dof& d) {
  return d.c == 0 ? "scalar point " + std::to_string(d.point) : "grid " + std::to_string(d.point) + " component " + std::to_string(d.c);
}

}  // namespace

GenelElement make_genel_element(const Model& model, const DofMap& dofs, const Genel& g) {
  GenelElement e;
  const auto n = static_cast<Eigen::Index>(g.ui.size()), m = static_cast<Eigen::Index>(g.ud.size());
  for (const auto* list : {&g.ui, &g.ud})
    for (const Genel::Dof& d : *list) {
      const auto dof = find_dof(model, dofs, d.point, d.c);
      if (!dof)
        detail::fail(model, g.ref, "GENEL", g.id, list == &g.ui ? "UIi" : "UDi",
                     dof_text(d) + " is not a dof of the model; expected a GRID with component 1-6 or an SPOINT with 0");
      for (const Eigen::Index other : e.dofs)
        if (other == *dof)
          detail::fail(model, g.ref, "GENEL", g.id, list == &g.ui ? "UIi" : "UDi", dof_text(d) + " is listed twice; expected distinct dofs");
      e.dofs.push_back(*dof);
    }
  Eigen::MatrixXd K = from_lower_columns(g.kz, n);
  if (g.flexibility) {
    Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
    lu.setThreshold(1e-12);
    if (!lu.isInvertible())
      detail::fail(model, g.ref, "GENEL", g.id, "Z", "the flexibility matrix Z is singular; expected an invertible Z (K = Z^-1)");
    K = lu.inverse();
    K = (0.5 * (K + K.transpose())).eval();
  }
  Eigen::MatrixXd S(n, m);
  if (!g.s.empty()) {
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < m; ++j) S(i, j) = g.s[static_cast<std::size_t>(i * m + j)];
  } else if (m > 0) {  // six UD dofs: S from the rigid-body maps about the first UD grid
    const auto axes = grid_cd_axes(model);
    for (const auto* list : {&g.ui, &g.ud})
      for (const Genel::Dof& d : *list)
        if (d.c == 0)
          detail::fail(model, g.ref, "GENEL", g.id, "S",
                       "blank, and " + dof_text(d) + " has no rigid-body motion to compute S from; expected S given on the card");
    auto rows = [&](const std::vector<Genel::Dof>& list, const Eigen::Vector3d& p) {
      Eigen::MatrixXd H(static_cast<Eigen::Index>(list.size()), 6);
      for (std::size_t k = 0; k < list.size(); ++k) {
        const auto gi = static_cast<Eigen::Index>(model.grid_index.at(list[k].point));
        H.row(static_cast<Eigen::Index>(k)) = detail::rigid_map(model, axes, gi, p).row(list[k].c - 1);
      }
      return H;
    };
    const Eigen::Vector3d p = model.grids[model.grid_index.at(g.ud.front().point)].x_basic;
    // rotations scaled by the element's size, so that the rank test of H_d is dimensionless
    double L = 0.0;
    for (const auto* list : {&g.ui, &g.ud})
      for (const Genel::Dof& d : *list) L = std::max(L, (model.grids[model.grid_index.at(d.point)].x_basic - p).norm());
    Eigen::MatrixXd D = Eigen::MatrixXd::Identity(6, 6);
    if (L > 0.0) D.bottomRightCorner<3, 3>() /= L;
    const Eigen::MatrixXd Hd = rows(g.ud, p) * D, Hi = rows(g.ui, p) * D;
    Eigen::FullPivLU<Eigen::MatrixXd> lu(Hd);
    lu.setThreshold(1e-10);
    if (!lu.isInvertible())
      detail::fail(model, g.ref, "GENEL", g.id, "UDi",
                   "the six UD dofs cannot describe every rigid-body motion of the element, so S cannot be computed; expected "
                   "six UD dofs that fix all six rigid-body motions (e.g. 123456 of one grid), or S given on the card");
    S = Hi * lu.inverse();
  }
  e.K.resize(n + m, n + m);
  e.K.topLeftCorner(n, n) = K;
  if (m > 0) {
    const Eigen::MatrixXd KS = K * S;
    e.K.topRightCorner(n, m) = -KS;
    e.K.bottomLeftCorner(m, n) = -KS.transpose();
    e.K.bottomRightCorner(m, m) = S.transpose() * KS;
  }
  return e;
}

}  // namespace seflex::fem
