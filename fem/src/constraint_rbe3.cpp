// RBE3 as dependent-dof rows (constraint_equations.hpp).
//
// The reference grid's motion is the weighted least-squares rigid-body fit to the independent
// motions (MSC Nastran Reference Manual, "RBE3"; QRG RBE3): with q = (u_r, theta_r) the rigid
// motion about the reference point and h_e the row of rigid_map giving independent entry
// e = (grid G_ij, component c in C_i) from q,
//
//   q = N^{-1} sum_e w_e h_e^T u_e,   N = sum_e w_e h_e^T h_e,   u_ref = A_r^T q  (REFC rows kept)
//
// w_e = WT_i for translations and WT_i Lc^2 for rotations, Lc the root-mean-square distance of the
// independent grids from their centroid (Lc = 1 if they coincide): the rotational weights are made
// commensurate with the translational ones (NX/Simcenter Nastran RBE3 documentation; as in
// smdogroup/tacs src/elements/TACSRBE3.cpp). The transpose gives the load distribution: a force F at
// the reference point reaches the independent grids as w_e h_e N^{-1} F, i.e. forces proportional
// to the weights plus the force couples that balance F's moment about the weighted centroid.
//
// UM: the dependent set redefined: the REFC equations u_ref,c - sum_e C_ce u_e = 0 are solved for the
// UM dofs instead (as many as REFC has components).
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <map>

#include "constraint_equations.hpp"
#include "model_lookup.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/components.hpp"
#include "seflex/fem/finalize.hpp"

namespace seflex::fem::detail {
namespace {

using Index = Eigen::Index;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

struct Entry {
  Index grid = 0;  ///< grid index
  int c = 0;       ///< component 1..6
  double w = 0;    ///< WT_i (rotations: times Lc^2)
};

void add_rbe3(const Model& model, const DofMap& dofs, const CdAxes& axes, const Rbe3& e, ConstraintEquations& eq) {
  const std::uint32_t card = eq.add_card("RBE3", e.id, e.ref);
  const Index gr = grid_index(model, e.refgrid, e.ref, "RBE3", e.id, "4 (REFGRID)");
  const Eigen::Vector3d x_r = model.grids[static_cast<std::size_t>(gr)].x_basic;

  std::vector<Entry> entries;
  std::map<Index, double> grid_weight;  // distinct independent grids -> their translational weight
  for (const Rbe3::Group& g : e.groups)
    for (const int id : g.grids) {
      const Index gi = grid_index(model, id, e.ref, "RBE3", e.id, "Gi,j");
      if (gi == gr)
        fail(model, e.ref, "RBE3", e.id, "Gi,j", "REFGRID " + std::to_string(id) +
                                                     " is also an independent grid; expected the reference grid only "
                                                     "in field 4 (use UM to make some of its components independent)");
      for (int c = 1; c <= 6; ++c)
        if (has_component(g.c, c)) entries.push_back({gi, c, g.weight});
      grid_weight[gi] += (g.c & 7u) ? g.weight : 0.0;
    }
  // Lc: RMS distance of the independent grids from their (translational-weight) centroid.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double wsum = 0;
  for (const auto& [gi, w] : grid_weight) {
    centroid += w * model.grids[static_cast<std::size_t>(gi)].x_basic;
    wsum += w;
  }
  if (wsum > 0) {
    centroid /= wsum;
  } else {
    centroid.setZero();
    for (const auto& [gi, w] : grid_weight) centroid += model.grids[static_cast<std::size_t>(gi)].x_basic;
    centroid /= static_cast<double>(grid_weight.size());
  }
  double Lc2 = 0;
  for (const auto& [gi, w] : grid_weight) Lc2 += (model.grids[static_cast<std::size_t>(gi)].x_basic - centroid).squaredNorm();
  Lc2 /= static_cast<double>(grid_weight.size());
  double size = 0;
  for (const auto& [gi, w] : grid_weight) size = std::max(size, (model.grids[static_cast<std::size_t>(gi)].x_basic - x_r).norm());
  const double Lc = Lc2 > 1e-24 * std::max(1.0, size * size) ? std::sqrt(Lc2) : 1.0;
  for (Entry& en : entries)
    if (en.c >= 4) en.w *= Lc * Lc;

  // Least squares in scaled coordinates q' = D q, D = diag(1, 1, 1, Lc, Lc, Lc): rows h' = h D^-1.
  Matrix6 D_inv = Matrix6::Identity();
  D_inv.bottomRightCorner<3, 3>() *= 1.0 / Lc;
  const Index n = static_cast<Index>(entries.size());
  Eigen::MatrixXd H(n, 6);  // scaled rows
  std::map<Index, Matrix6> maps;
  for (Index k = 0; k < n; ++k) {
    const Entry& en = entries[static_cast<std::size_t>(k)];
    auto it = maps.find(en.grid);
    if (it == maps.end()) it = maps.emplace(en.grid, rigid_map(model, axes, en.grid, x_r) * D_inv).first;
    H.row(k) = it->second.row(en.c - 1);
  }
  Eigen::VectorXd w(n);
  for (Index k = 0; k < n; ++k) w(k) = entries[static_cast<std::size_t>(k)].w;
  const Matrix6 N = H.transpose() * w.asDiagonal() * H;
  Eigen::SelfAdjointEigenSolver<Matrix6> es(N);
  const Vector6 lambda = es.eigenvalues();
  const double lmax = lambda.cwiseAbs().maxCoeff();
  if (!(lmax > 0.0))
    fail(model, e.ref, "RBE3", e.id, "6 (WT1)", "all weights are zero; expected positive weighting factors");
  Matrix6 N_pinv = Matrix6::Zero();
  std::vector<Vector6> null_vectors;
  for (int k = 0; k < 6; ++k) {
    const Vector6 v = es.eigenvectors().col(k);
    if (lambda(k) > 1e-10 * lmax)
      N_pinv += v * v.transpose() / lambda(k);
    else
      null_vectors.push_back(v);
  }
  // Reference rows: u_ref(CD) = A_r^T q = A_r^T D^-1 q'.
  const Matrix6 R_r = rigid_map(model, axes, gr, x_r) * D_inv;
  for (int c = 1; c <= 6; ++c) {
    if (!has_component(e.refc, c)) continue;
    for (const Vector6& v : null_vectors)
      if (std::abs(R_r.row(c - 1).dot(v)) > 1e-8 * R_r.row(c - 1).norm())
        fail(model, e.ref, "RBE3", e.id, "5 (REFC)",
             "component " + std::to_string(c) + " of REFGRID " + std::to_string(e.refgrid) +
                 " is not determined by the independent components (e.g. translations only at grids on one line "
                 "leave the rotation about that line free); expected components Ci at the grids Gi,j that can "
                 "react every rigid-body motion REFC needs (QRG RBE3 remark 1)");
  }
  const Eigen::MatrixXd C = R_r * N_pinv * H.transpose() * w.asDiagonal();  // 6 x n: u_ref = C u_entries

  // The REFC equations over the dofs they involve: column 0.. the REFC dofs, then the entries' dofs.
  std::vector<Index> columns;
  auto column = [&](Index dof) {
    const auto it = std::find(columns.begin(), columns.end(), dof);
    if (it != columns.end()) return static_cast<Index>(it - columns.begin());
    columns.push_back(dof);
    return static_cast<Index>(columns.size() - 1);
  };
  std::vector<int> refc;
  for (int c = 1; c <= 6; ++c)
    if (has_component(e.refc, c)) refc.push_back(c);
  for (const int c : refc) column(dofs.grid_dof(gr, c));
  std::vector<Index> entry_col(static_cast<std::size_t>(n));
  for (Index k = 0; k < n; ++k) {
    const Entry& en = entries[static_cast<std::size_t>(k)];
    entry_col[static_cast<std::size_t>(k)] = column(dofs.grid_dof(en.grid, en.c));
  }

  if (e.um.empty()) {
    for (const int c : refc) {
      DependentDof d;
      d.dof = dofs.grid_dof(gr, c);
      d.card = card;
      std::map<Index, double> terms;
      for (Index k = 0; k < n; ++k) terms[columns[static_cast<std::size_t>(entry_col[static_cast<std::size_t>(k)])]] += C(c - 1, k);
      const double scale = C.row(c - 1).cwiseAbs().maxCoeff();
      for (const auto& [dof, a] : terms)
        if (std::abs(a) > 1e-14 * scale) d.terms.emplace_back(dof, a);
      eq.dependents.push_back(std::move(d));
    }
    return;
  }

  // UM: solve the same equations for the listed dofs.
  const Index k_eq = static_cast<Index>(refc.size());
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(k_eq, static_cast<Index>(columns.size()));
  for (Index i = 0; i < k_eq; ++i) {
    R(i, i) = 1.0;
    for (Index k = 0; k < n; ++k) R(i, entry_col[static_cast<std::size_t>(k)]) -= C(refc[static_cast<std::size_t>(i)] - 1, k);
  }
  std::vector<Index> um;
  for (const Rbe3::Dependent& d : e.um) {
    const Index gi = grid_index(model, d.grid, e.ref, "RBE3", e.id, "GMi (UM)");
    for (int c = 1; c <= 6; ++c) {
      if (!has_component(d.c, c)) continue;
      const Index dof = dofs.grid_dof(gi, c);
      if (std::find(columns.begin(), columns.end(), dof) == columns.end())
        fail(model, e.ref, "RBE3", e.id, "CMi (UM)",
             "component " + std::to_string(c) + " of grid " + std::to_string(d.grid) +
                 " is not in the element (neither a REFC component of REFGRID nor a component Ci of a grid Gi,j); "
                 "expected UM to list dofs of the element");
      if (std::find(um.begin(), um.end(), dof) != um.end())
        fail(model, e.ref, "RBE3", e.id, "CMi (UM)",
             "component " + std::to_string(c) + " of grid " + std::to_string(d.grid) + " is listed twice");
      um.push_back(dof);
    }
  }
  if (static_cast<Index>(um.size()) != k_eq)
    fail(model, e.ref, "RBE3", e.id, "UM",
         std::to_string(um.size()) + " dependent components listed after UM; expected as many as REFC has (" +
             std::to_string(k_eq) + ")");
  const auto rows = solve_for_dependents(R, columns, um);
  if (!rows)
    fail(model, e.ref, "RBE3", e.id, "UM",
         "the averaging equations cannot be solved for the UM components (they do not determine them independently); "
         "expected UM components that the equations fix, e.g. the REFC components of REFGRID or translations of "
         "independent grids off the reference point");
  for (std::size_t i = 0; i < um.size(); ++i) {
    DependentDof d;
    d.dof = um[i];
    d.card = card;
    d.terms = (*rows)[i];
    eq.dependents.push_back(std::move(d));
  }
}

}  // namespace

void add_rbe3_elements(const Model& model, const DofMap& dofs, const CdAxes& axes, ConstraintEquations& eq) {
  for (const Rbe3& e : model.rbe3) add_rbe3(model, dofs, axes, e, eq);
}

}  // namespace seflex::fem::detail
