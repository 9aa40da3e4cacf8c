// RBE2 and RBAR as dependent-dof rows (constraint_equations.hpp).
//
// Both describe a rigid body: its motion q = (u_p, theta) about a point p maps to each grid's six
// dofs by rigid_map. The six independent dofs fix q (u_n = H_n q, H_n invertible), every dependent
// dof follows: u_m = H_m H_n^{-1} u_n (small rotations; MSC Nastran Reference Manual, "Rigid
// Elements": RBE2 and RBAR equations).
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "constraint_equations.hpp"
#include "model_lookup.hpp"
#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/fem/components.hpp"
#include "seflex/fem/finalize.hpp"

namespace seflex::fem::detail {

using Index = Eigen::Index;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

Matrix6 rigid_map(const Model& model, const CdAxes& axes, Index gi, const Eigen::Vector3d& p) {
  const Eigen::Matrix3d At = axes[static_cast<std::size_t>(gi)].value_or(Eigen::Matrix3d::Identity()).transpose();
  Matrix6 R = Matrix6::Zero();
  R.topLeftCorner<3, 3>() = At;
  R.topRightCorner<3, 3>() = -At * so3::skew(model.grids[static_cast<std::size_t>(gi)].x_basic - p);
  R.bottomRightCorner<3, 3>() = At;
  return R;
}

std::string dof_name(const Model& model, const DofMap& dofs, Index dof) {
  const DofLabel l = dof_label(model, dofs, dof);
  return l.scalar_point ? "scalar point " + std::to_string(l.point_id)
                        : "grid " + std::to_string(l.point_id) + " component " + std::to_string(l.component);
}

namespace {

/// Dependent rows u_m = G u_n for the components `cm` of grid gm, G (6 x 6) over the six
/// independent dofs `independent`; coefficients below 1e-14 are round-off of exact zeros.
void add_rows(const DofMap& dofs, Index gm, ComponentMask cm, const std::array<Index, 6>& independent, const Matrix6& G,
              std::uint32_t card, ConstraintEquations& eq) {
  for (int c = 1; c <= 6; ++c) {
    if (!has_component(cm, c)) continue;
    DependentDof d;
    d.dof = dofs.grid_dof(gm, c);
    d.card = card;
    for (int k = 0; k < 6; ++k)
      if (std::abs(G(c - 1, k)) > 1e-14) d.terms.emplace_back(independent[static_cast<std::size_t>(k)], G(c - 1, k));
    eq.dependents.push_back(std::move(d));
  }
}

void add_rbe2(const Model& model, const DofMap& dofs, const CdAxes& axes, const Rbe2& e, ConstraintEquations& eq) {
  const std::uint32_t card = eq.add_card("RBE2", e.id, e.ref);
  const Index gn = grid_index(model, e.gn, e.ref, "RBE2", e.id, "3 (GN)");
  const Eigen::Vector3d p = model.grids[static_cast<std::size_t>(gn)].x_basic;
  // H_n = rigid_map(gn, p) = blockdiag(A_n^T): its inverse is blockdiag(A_n).
  Matrix6 Hn_inv = Matrix6::Zero();
  Hn_inv.topLeftCorner<3, 3>() = Hn_inv.bottomRightCorner<3, 3>() =
      axes[static_cast<std::size_t>(gn)].value_or(Eigen::Matrix3d::Identity());
  std::array<Index, 6> independent;
  for (int k = 0; k < 6; ++k) independent[static_cast<std::size_t>(k)] = dofs.grid_dof(gn, k + 1);
  for (const int gm_id : e.gm) {
    const Index gm = grid_index(model, gm_id, e.ref, "RBE2", e.id, "GMi");
    if (gm == gn) fail(model, e.ref, "RBE2", e.id, "GMi", "GRID " + std::to_string(gm_id) + " is also GN");
    add_rows(dofs, gm, e.cm, independent, rigid_map(model, axes, gm, p) * Hn_inv, card, eq);
  }
}

void add_rbar(const Model& model, const DofMap& dofs, const CdAxes& axes, const Rbar& e, ConstraintEquations& eq) {
  const std::uint32_t card = eq.add_card("RBAR", e.id, e.ref);
  const Index ga = grid_index(model, e.ga, e.ref, "RBAR", e.id, "3 (GA)");
  const Index gb = grid_index(model, e.gb, e.ref, "RBAR", e.id, "4 (GB)");
  const Eigen::Vector3d p = model.grids[static_cast<std::size_t>(ga)].x_basic;
  const double L = (model.grids[static_cast<std::size_t>(gb)].x_basic - p).norm();
  if (!(L > 0.0))
    fail(model, e.ref, "RBAR", e.id, "4 (GB)", "GA and GB are at the same point; expected a bar of nonzero length");
  // Rotations scaled by L so that H_n is dimensionless and its rank test meaningful.
  Matrix6 D = Matrix6::Identity();
  D.bottomRightCorner<3, 3>() *= 1.0 / L;
  const Matrix6 Ra = rigid_map(model, axes, ga, p) * D, Rb = rigid_map(model, axes, gb, p) * D;
  Matrix6 Hn;
  std::array<Index, 6> independent;
  std::size_t n = 0;
  for (const auto& [g, R, cn] : {std::tuple{ga, &Ra, e.cna}, std::tuple{gb, &Rb, e.cnb}})
    for (int c = 1; c <= 6; ++c)
      if (has_component(cn, c)) {
        SEFLEX_DEMAND(n < 6, "RBAR independent components checked by the reader");
        Hn.row(static_cast<Index>(n)) = R->row(c - 1);
        independent[n++] = dofs.grid_dof(g, c);
      }
  SEFLEX_DEMAND(n == 6, "RBAR independent components checked by the reader");
  Eigen::FullPivLU<Matrix6> lu(Hn);
  lu.setThreshold(1e-10);
  if (!lu.isInvertible())
    fail(model, e.ref, "RBAR", e.id, "5 (CNA)",
         "the independent components CNA = " + component_string(e.cna) + " and CNB = " + component_string(e.cnb) +
             " cannot describe every rigid-body motion of the bar (e.g. 123 at both ends leaves the rotation about "
             "the bar free); expected six components that fix all six rigid-body motions");
  const Matrix6 Hn_inv = lu.inverse();
  add_rows(dofs, ga, e.cma, independent, Ra * Hn_inv, card, eq);
  add_rows(dofs, gb, e.cmb, independent, Rb * Hn_inv, card, eq);
}

}  // namespace

void add_rigid_elements(const Model& model, const DofMap& dofs, const CdAxes& axes, ConstraintEquations& eq) {
  for (const Rbe2& e : model.rbe2) add_rbe2(model, dofs, axes, e, eq);
  for (const Rbar& e : model.rbars) add_rbar(model, dofs, axes, e, eq);
}

std::optional<std::vector<SparseRow>> solve_for_dependents(const Eigen::MatrixXd& R, const std::vector<Index>& columns,
                                                           const std::vector<Index>& dependent) {
  const Index k = R.rows();
  SEFLEX_DEMAND(static_cast<Index>(dependent.size()) == k && R.cols() == static_cast<Index>(columns.size()),
                "solve_for_dependents: sizes");
  std::vector<Index> m_col, n_col;
  for (Index j = 0; j < R.cols(); ++j) {
    const bool dep = std::find(dependent.begin(), dependent.end(), columns[static_cast<std::size_t>(j)]) != dependent.end();
    (dep ? m_col : n_col).push_back(j);
  }
  if (static_cast<Index>(m_col.size()) != k) return std::nullopt;
  Eigen::MatrixXd Rm(k, k), Rn(k, static_cast<Index>(n_col.size()));
  // order the dependent columns as `dependent`
  for (Index i = 0; i < k; ++i) {
    const auto it = std::find(columns.begin(), columns.end(), dependent[static_cast<std::size_t>(i)]);
    Rm.col(i) = R.col(it - columns.begin());
  }
  for (std::size_t j = 0; j < n_col.size(); ++j) Rn.col(static_cast<Index>(j)) = R.col(n_col[j]);
  Eigen::FullPivLU<Eigen::MatrixXd> lu(Rm);
  lu.setThreshold(1e-10);
  if (!lu.isInvertible()) return std::nullopt;
  const Eigen::MatrixXd G = -lu.solve(Rn);
  const double scale = G.size() > 0 ? G.cwiseAbs().maxCoeff() : 0.0;
  std::vector<SparseRow> out(static_cast<std::size_t>(k));
  for (Index i = 0; i < k; ++i)
    for (std::size_t j = 0; j < n_col.size(); ++j)
      if (std::abs(G(i, static_cast<Index>(j))) > 1e-14 * scale)
        out[static_cast<std::size_t>(i)].emplace_back(columns[static_cast<std::size_t>(n_col[j])], G(i, static_cast<Index>(j)));
  return out;
}

}  // namespace seflex::fem::detail
