// RBE2, RBAR, RBE1, CRIGD1-3 and RROD, CRIGDR as dependent-dof rows (constraint_equations.hpp).
//
// All but the rods describe a rigid body: its motion q = (u_p, theta) about a point p maps to each
// grid's six dofs by rigid_map. The six independent dofs fix q (u_n = H_n q, H_n invertible), every
// dependent dof follows: u_m = H_m H_n^{-1} u_n (small rotations; MSC Nastran Reference Manual,
// "Rigid Elements": RBE2 and RBAR equations; RBE1 and CRIGD3 are RBAR's independent set spread over
// up to six grids). RROD/CRIGDR keep one length: n . (u_B - u_A) = 0, solved for one translation.
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
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

std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

/// A grid index and the components it contributes to a rigid body.
struct BodyGrid {
  Index g = 0;
  ComponentMask c = 0;
};

/// The rows of a rigid body whose independent components (six in all) fix its rigid motion q = (u_p,
/// theta L) about basic point p (rotations scaled by the body's size L, so that H_n is dimensionless
/// and its rank test meaningful): u_n = H_n q, u_m = H_m H_n^{-1} u_n. Returns false, adding nothing,
/// if the independent components do not fix every rigid motion (H_n singular).
bool add_rigid_body(const Model& model, const DofMap& dofs, const CdAxes& axes, const std::vector<BodyGrid>& independent,
                    const std::vector<BodyGrid>& dependent, std::uint32_t card, ConstraintEquations& eq) {
  const Eigen::Vector3d p = model.grids[static_cast<std::size_t>(independent.front().g)].x_basic;
  double L = 0.0;
  for (const auto* set : {&independent, &dependent})
    for (const BodyGrid& b : *set) L = std::max(L, (model.grids[static_cast<std::size_t>(b.g)].x_basic - p).norm());
  if (!(L > 0.0)) L = 1.0;  // every grid at one point: rotations and translations have the same scale anyway
  Matrix6 D = Matrix6::Identity();
  D.bottomRightCorner<3, 3>() *= 1.0 / L;
  Matrix6 Hn;
  std::array<Index, 6> columns;
  std::size_t n = 0;
  for (const BodyGrid& b : independent) {
    const Matrix6 R = rigid_map(model, axes, b.g, p) * D;
    for (int c = 1; c <= 6; ++c)
      if (has_component(b.c, c)) {
        SEFLEX_DEMAND(n < 6, "rigid body independent components checked by the reader");
        Hn.row(static_cast<Index>(n)) = R.row(c - 1);
        columns[n++] = dofs.grid_dof(b.g, c);
      }
  }
  SEFLEX_DEMAND(n == 6, "rigid body independent components checked by the reader");
  Eigen::FullPivLU<Matrix6> lu(Hn);
  lu.setThreshold(1e-10);
  if (!lu.isInvertible()) return false;
  const Matrix6 Hn_inv = lu.inverse();
  for (const BodyGrid& b : dependent) add_rows(dofs, b.g, b.c, columns, rigid_map(model, axes, b.g, p) * D * Hn_inv, card, eq);
  return true;
}

void add_rbar(const Model& model, const DofMap& dofs, const CdAxes& axes, const Rbar& e, ConstraintEquations& eq) {
  const std::uint32_t card = eq.add_card("RBAR", e.id, e.ref);
  const Index ga = grid_index(model, e.ga, e.ref, "RBAR", e.id, "3 (GA)");
  const Index gb = grid_index(model, e.gb, e.ref, "RBAR", e.id, "4 (GB)");
  if (!((model.grids[static_cast<std::size_t>(gb)].x_basic - model.grids[static_cast<std::size_t>(ga)].x_basic).norm() > 0.0))
    fail(model, e.ref, "RBAR", e.id, "4 (GB)", "GA and GB are at the same point; expected a bar of nonzero length");
  if (!add_rigid_body(model, dofs, axes, {{ga, e.cna}, {gb, e.cnb}}, {{ga, e.cma}, {gb, e.cmb}}, card, eq))
    fail(model, e.ref, "RBAR", e.id, "5 (CNA)",
         "the independent components CNA = " + component_string(e.cna) + " and CNB = " + component_string(e.cnb) +
             " cannot describe every rigid-body motion of the bar (e.g. 123 at both ends leaves the rotation about "
             "the bar free); expected six components that fix all six rigid-body motions");
}

/// RBE1, CRIGD1, CRIGD2, CRIGD3 (model_constraints.hpp: RigidBody).
void add_general_rigid(const Model& model, const DofMap& dofs, const CdAxes& axes, const RigidBody& e, ConstraintEquations& eq) {
  const char* name = rigid_body_card(e);
  const std::uint32_t card = eq.add_card(name, e.id, e.ref);
  const RigidBodyFields f = rigid_body_fields(e);
  std::vector<BodyGrid> independent, dependent;
  std::string listed;
  for (const auto& g : e.independent) {
    independent.push_back({grid_index(model, g.grid, e.ref, name, e.id, f.independent), g.c});
    listed += (listed.empty() ? "" : ", ") + std::to_string(g.grid) + " " + component_string(g.c);
  }
  for (const auto& g : e.dependent) dependent.push_back({grid_index(model, g.grid, e.ref, name, e.id, f.dependent), g.c});
  if (!add_rigid_body(model, dofs, axes, independent, dependent, card, eq))
    fail(model, e.ref, name, e.id, "",
         "the independent components (grid components: " + listed +
             ") cannot describe every rigid-body motion of the element; expected six components that fix all six "
             "rigid-body motions (e.g. 123 at three grids not on one line)");
}

/// RROD, CRIGDR: a u_cd(GA) + b u_cd(GB) = 0 with a = -A_A^T n, b = A_B^T n over the translations,
/// solved for the dependent translation (model_constraints.hpp: RigidRod).
void add_rigid_rod(const Model& model, const DofMap& dofs, const CdAxes& axes, const RigidRod& e, ConstraintEquations& eq) {
  const char* name = rigid_rod_card(e);
  const RigidRodFields f = rigid_rod_fields(e);
  const std::uint32_t card = eq.add_card(name, e.id, e.ref);
  const std::array<Index, 2> g = {grid_index(model, e.ga, e.ref, name, e.id, f.ga), grid_index(model, e.gb, e.ref, name, e.id, f.gb)};
  const Eigen::Vector3d d =
      model.grids[static_cast<std::size_t>(g[1])].x_basic - model.grids[static_cast<std::size_t>(g[0])].x_basic;
  if (!(d.norm() > 0.0)) fail(model, e.ref, name, e.id, f.gb, "the two grids are at the same point; expected a rod of nonzero length");
  const Eigen::Vector3d n = d.normalized();
  std::array<Eigen::Vector3d, 2> a;  // coefficients of each grid's CD translations
  for (int k = 0; k < 2; ++k)
    a[static_cast<std::size_t>(k)] = (k == 0 ? -1.0 : 1.0) * axes[static_cast<std::size_t>(g[static_cast<std::size_t>(k)])]
                                                                  .value_or(Eigen::Matrix3d::Identity())
                                                                  .transpose() *
                                     n;
  int end = e.cma != 0 ? 0 : 1, comp = e.cma != 0 ? e.cma : e.cmb;
  if (comp == 0) a[1].cwiseAbs().maxCoeff(&comp), ++comp;  // RROD, both blank: GB's translation most along the rod
  const double pivot = a[static_cast<std::size_t>(end)][comp - 1];
  if (std::abs(pivot) < 1e-3)
    fail(model, e.ref, name, e.id, end == 0 ? f.cma : f.cmb,
         "translation " + std::to_string(comp) + " of grid " + std::to_string(end == 0 ? e.ga : e.gb) +
             " is perpendicular to the rod (direction cosine " + short_number(pivot) +
             "); expected a dependent translation along the rod (direction cosine of magnitude >= 1e-3)");
  DependentDof dep;
  dep.dof = dofs.grid_dof(g[static_cast<std::size_t>(end)], comp);
  dep.card = card;
  for (int k = 0; k < 2; ++k)
    for (int c = 1; c <= 3; ++c) {
      if (k == end && c == comp) continue;
      const double coef = -a[static_cast<std::size_t>(k)][c - 1] / pivot;
      if (std::abs(coef) > 1e-14) dep.terms.emplace_back(dofs.grid_dof(g[static_cast<std::size_t>(k)], c), coef);
    }
  eq.dependents.push_back(std::move(dep));
}

}  // namespace

void add_rigid_elements(const Model& model, const DofMap& dofs, const CdAxes& axes, ConstraintEquations& eq) {
  for (const Rbe2& e : model.rbe2) add_rbe2(model, dofs, axes, e, eq);
  for (const Rbar& e : model.rbars) add_rbar(model, dofs, axes, e, eq);
  for (const RigidBody& e : model.rigid_bodies) add_general_rigid(model, dofs, axes, e, eq);
  for (const RigidRod& e : model.rigid_rods) add_rigid_rod(model, dofs, axes, e, eq);
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
