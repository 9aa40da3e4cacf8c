// SPC and RBE2 elimination (see constraints.hpp).
#include "seflex/fem/constraints.hpp"

#include <algorithm>
#include <functional>
#include <set>

#include "model_lookup.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/components.hpp"

namespace seflex::fem {
namespace {

using Index = Eigen::Index;
using Row = std::vector<std::pair<Index, double>>;  // sparse row: (g dof, coefficient)

// Where a dependent dof came from, for messages.
struct Dependency {
  std::size_t rbe2 = 0;
  Index independent_grid = 0;  // grid index of GN
  Row terms;                   // over the six dofs of GN (before chain resolution)
};

double lookup(const Eigen::SparseMatrix<double>& A, Index row, Index col) {
  const int* inner = A.innerIndexPtr();
  const int b = A.outerIndexPtr()[col], e = A.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(inner + b, inner + e, static_cast<int>(row));
  return (it != inner + e && *it == row) ? A.valuePtr()[it - inner] : 0.0;
}

// B = principal submatrix A(keep, keep) with keep given by g_to_f (monotonic), built in place.
void select(const Eigen::SparseMatrix<double>& A, const std::vector<Index>& f_to_g, const std::vector<Index>& g_to_f,
            Eigen::SparseMatrix<double>& B) {
  const Index nf = static_cast<Index>(f_to_g.size());
  B.resize(nf, nf);
  std::vector<int> outer(static_cast<std::size_t>(nf + 1), 0);
  std::int64_t nnz = 0;
  for (Index j = 0; j < nf; ++j) {
    const Index c = f_to_g[j];
    for (int k = A.outerIndexPtr()[c]; k < A.outerIndexPtr()[c + 1]; ++k)
      if (g_to_f[A.innerIndexPtr()[k]] >= 0) ++nnz;
    outer[j + 1] = static_cast<int>(nnz);
  }
  B.resizeNonZeros(static_cast<Index>(nnz));
  std::copy(outer.begin(), outer.end(), B.outerIndexPtr());
  std::int64_t pos = 0;
  for (Index j = 0; j < nf; ++j) {
    const Index c = f_to_g[j];
    for (int k = A.outerIndexPtr()[c]; k < A.outerIndexPtr()[c + 1]; ++k) {
      const Index r = g_to_f[A.innerIndexPtr()[k]];
      if (r < 0) continue;
      B.innerIndexPtr()[pos] = static_cast<int>(r);
      B.valuePtr()[pos] = A.valuePtr()[k];
      ++pos;
    }
  }
}

}  // namespace

std::vector<std::pair<Eigen::Index, double>> spc_set_dofs(const Model& model, const DofMap& dofs, int spc_set) {
  // Expand SPCADD (guarding against cycles).
  std::set<int> sets;
  bool defined = false;
  std::function<void(int)> expand_set = [&](int sid) {
    if (!sets.insert(sid).second) return;
    for (const SpcAdd& a : model.spcadds)
      if (a.sid == sid) {
        defined = true;
        for (int s : a.sets) expand_set(s);
      }
  };
  expand_set(spc_set);
  std::vector<std::pair<Index, double>> out;
  for (const SpcEntry& e : model.spcs) {
    if (!sets.count(e.sid)) continue;
    defined = true;
    if (model.spoint_index.count(e.grid) && (e.c == 0 || e.c == 1)) {
      out.emplace_back(dofs.spoint_dof(model.spoint_index.at(e.grid)), e.d);
      continue;
    }
    const auto it = model.grid_index.find(e.grid);
    if (it == model.grid_index.end())
      throw InputError(where(model, e.ref), "SPC/SPC1 set " + std::to_string(e.sid) + ": references GRID " +
                                                            std::to_string(e.grid) + ", which is not defined");
    if (e.c == 0)
      throw InputError(where(model, e.ref), "SPC/SPC1 set " + std::to_string(e.sid) + ", GRID " +
                                                            std::to_string(e.grid) +
                                                            ": expected components (digits 1-6)");
    for (int c = 1; c <= 6; ++c)
      if (has_component(e.c, c)) out.emplace_back(dofs.grid_dof(it->second, c), e.d);
  }
  if (!defined)
    throw InputError(SourceRef{model.files.empty() ? std::string() : model.files.front(), 0},
                     "case control SPC = " + std::to_string(spc_set) +
                         ": no SPC, SPC1 or SPCADD bulk data card has SID " + std::to_string(spc_set));
  return out;
}

ConstrainedSystem apply_constraints(const Model& model, const GlobalMatrices& g, std::optional<int> spc_set,
                                    const std::vector<Eigen::Index>& fixed_dofs) {
  ConstraintOptions o;
  o.spc_set = spc_set;
  o.fixed_dofs = fixed_dofs;
  return apply_constraints(model, g, o);
}

ConstrainedSystem apply_constraints(const Model& model, const GlobalMatrices& g, const ConstraintOptions& options) {
  const DofMap& dofs = g.dofs;
  const Index n = dofs.size();
  SEFLEX_DEMAND(g.K.rows() == n && g.M.rows() == n, "matrices do not match the model's dofs");
  ConstrainedSystem out;
  out.status.assign(static_cast<std::size_t>(n), DofStatus::Free);
  out.u_g0 = Eigen::VectorXd::Zero(n);

  // s-set: GRID PS, then the SPC set.
  for (std::size_t i = 0; i < model.grids.size(); ++i)
    for (int c = 1; c <= 6; ++c)
      if (has_component(model.grids[i].ps, c)) out.status[dofs.grid_dof(static_cast<Index>(i), c)] = DofStatus::Spc;
  if (options.spc_set)
    for (const auto& [d, value] : spc_set_dofs(model, dofs, *options.spc_set)) {
      out.status[d] = DofStatus::Spc;
      out.u_g0[d] = value;
    }
  for (Index d : options.fixed_dofs) {
    SEFLEX_DEMAND(d >= 0 && d < n, "fixed dof out of range");
    if (out.status[d] == DofStatus::Free) out.status[d] = DofStatus::Fixed;
  }

  // m-set: RBE2 dependents, each as a combination of its independent grid's six dofs.
  const auto axes = grid_cd_axes(model);
  std::vector<std::optional<Dependency>> dep(static_cast<std::size_t>(n));
  bool any_dependent = false;
  for (std::size_t r = 0; r < model.rbe2.size(); ++r) {
    const Rbe2& e = model.rbe2[r];
    const Index gn = detail::grid_index(model, e.gn, e.ref, "RBE2", e.id, "3 (GN)");
    const Eigen::Matrix3d An = axes[gn].value_or(Eigen::Matrix3d::Identity());
    for (int gm_id : e.gm) {
      const Index gm = detail::grid_index(model, gm_id, e.ref, "RBE2", e.id, "GMi");
      if (gm == gn) detail::fail(model, e.ref, "RBE2", e.id, "GMi", "GRID " + std::to_string(gm_id) + " is also GN");
      const Eigen::Matrix3d Am = axes[gm].value_or(Eigen::Matrix3d::Identity());
      const Eigen::Vector3d d = model.grids[gm].x_basic - model.grids[gn].x_basic;
      Matrix6 G = Matrix6::Zero();  // q_m(CD) = G q_n(CD)
      G.topLeftCorner<3, 3>() = Am.transpose() * An;
      G.topRightCorner<3, 3>() = -Am.transpose() * so3::skew(d) * An;
      G.bottomRightCorner<3, 3>() = Am.transpose() * An;
      for (int c = 1; c <= 6; ++c) {
        if (!has_component(e.cm, c)) continue;
        const Index m = dofs.grid_dof(gm, c);
        if (dep[m])
          detail::fail(model, e.ref, "RBE2", e.id, "GMi",
                       "component " + std::to_string(c) + " of GRID " + std::to_string(gm_id) +
                           " is already dependent in RBE2 " + std::to_string(model.rbe2[dep[m]->rbe2].id));
        if (out.status[m] != DofStatus::Free)
          detail::fail(model, e.ref, "RBE2", e.id, "GMi",
                       "component " + std::to_string(c) + " of GRID " + std::to_string(gm_id) +
                           " is dependent here but also constrained (GRID PS, SPC/SPC1 or a held dof)");
        Dependency dp;
        dp.rbe2 = r;
        dp.independent_grid = gn;
        for (int k = 0; k < 6; ++k)
          if (G(c - 1, k) != 0.0) dp.terms.emplace_back(dofs.grid_dof(gn, k + 1), G(c - 1, k));
        dep[m] = std::move(dp);
        out.status[m] = DofStatus::Dependent;
        any_dependent = true;
      }
    }
  }

  // Resolve chains: express every dependent dof through non-dependent dofs only.
  std::vector<Row> resolved(any_dependent ? static_cast<std::size_t>(n) : 0);
  if (any_dependent) {
    std::vector<unsigned char> state(static_cast<std::size_t>(n), 0);  // 0 new, 1 in progress, 2 done
    std::function<void(Index)> resolve = [&](Index m) {
      if (state[m] == 2) return;
      if (state[m] == 1) {
        const Rbe2& e = model.rbe2[dep[m]->rbe2];
        detail::fail(model, e.ref, "RBE2", e.id, "", "RBE2 dependencies form a closed loop");
      }
      state[m] = 1;
      Row row;
      for (const auto& [k, a] : dep[m]->terms) {
        if (dep[k]) {
          resolve(k);
          for (const auto& [kk, b] : resolved[k]) row.emplace_back(kk, a * b);
        } else {
          row.emplace_back(k, a);
        }
      }
      std::sort(row.begin(), row.end());
      Row merged;
      for (const auto& t : row) {
        if (!merged.empty() && merged.back().first == t.first)
          merged.back().second += t.second;
        else
          merged.push_back(t);
      }
      resolved[m] = std::move(merged);
      state[m] = 2;
    };
    for (Index m = 0; m < n; ++m)
      if (dep[m]) resolve(m);
  }

  // Columns of T before AUTOSPC: for each independent dof j, the dependents that use it.
  std::vector<Row> users(any_dependent ? static_cast<std::size_t>(n) : 0);
  if (any_dependent)
    for (Index m = 0; m < n; ++m)
      if (dep[m])
        for (const auto& [k, a] : resolved[m]) users[k].emplace_back(m, a);

  // AUTOSPC on the diagonal of T^T K T (computed column by column, without the product).
  if (options.autospc) {
    std::vector<double> diag(static_cast<std::size_t>(n), 0.0);
    for (Index j = 0; j < n; ++j) {
      if (out.status[j] != DofStatus::Free) continue;
      if (!any_dependent || users[j].empty()) {
        diag[j] = lookup(g.K, j, j);
        continue;
      }
      Row t = users[j];
      t.emplace_back(j, 1.0);
      double s = 0.0;
      for (const auto& [a, ta] : t)
        for (const auto& [b, tb] : t) s += ta * tb * lookup(g.K, a, b);
      diag[j] = s;
    }
    for (Index i = 0; i < dofs.n_grids; ++i)
      for (int h = 0; h < 2; ++h) {
        double dmax = 0.0;
        for (int c = 0; c < 3; ++c) {
          const Index d = 6 * i + 3 * h + c;
          if (out.status[d] == DofStatus::Free) dmax = std::max(dmax, std::abs(diag[d]));
        }
        for (int c = 0; c < 3; ++c) {
          const Index d = 6 * i + 3 * h + c;
          if (out.status[d] == DofStatus::Free && std::abs(diag[d]) <= 1e-8 * dmax) out.status[d] = DofStatus::AutoSpc;
        }
      }
    for (Index d = 6 * dofs.n_grids; d < n; ++d)
      if (out.status[d] == DofStatus::Free && diag[d] == 0.0) out.status[d] = DofStatus::AutoSpc;
  }

  // f-set numbering.
  out.g_to_f.assign(static_cast<std::size_t>(n), -1);
  for (Index d = 0; d < n; ++d)
    if (out.status[d] == DofStatus::Free) {
      out.g_to_f[d] = static_cast<Index>(out.f_to_g.size());
      out.f_to_g.push_back(d);
    }
  const Index nf = out.n_free();

  // T and the enforced displacements of dependents.
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(static_cast<std::size_t>(nf));
  for (Index j = 0; j < nf; ++j) trip.emplace_back(out.f_to_g[j], j, 1.0);
  if (any_dependent)
    for (Index m = 0; m < n; ++m) {
      if (!dep[m]) continue;
      double u0 = 0.0;
      for (const auto& [k, a] : resolved[m]) {
        if (out.g_to_f[k] >= 0) trip.emplace_back(m, out.g_to_f[k], a);
        u0 += a * out.u_g0[k];
      }
      out.u_g0[m] = u0;
    }
  out.T.resize(n, nf);
  out.T.setFromTriplets(trip.begin(), trip.end());

  if (!any_dependent) {
    select(g.K, out.f_to_g, out.g_to_f, out.K_ff);
    select(g.M, out.f_to_g, out.g_to_f, out.M_ff);
  } else {
    const Eigen::SparseMatrix<double> Tt = out.T.transpose();
    out.K_ff = Tt * (g.K * out.T);
    out.M_ff = Tt * (g.M * out.T);
    out.K_ff.prune(0.0, 0.0);
    out.M_ff.prune(0.0, 0.0);
  }
  return out;
}

Eigen::VectorXd reduce_load(const ConstrainedSystem& c, const GlobalMatrices& g, const Eigen::VectorXd& p_g) {
  SEFLEX_DEMAND(p_g.size() == g.K.rows(), "load vector size does not match the g-set");
  if (c.u_g0.isZero(0.0)) return c.T.transpose() * p_g;
  const Eigen::VectorXd r = p_g - g.K * c.u_g0;
  return c.T.transpose() * r;
}

Eigen::VectorXd expand(const ConstrainedSystem& c, const Eigen::VectorXd& u_f) {
  SEFLEX_DEMAND(u_f.size() == c.n_free(), "f-set vector has the wrong size");
  return c.T * u_f + c.u_g0;
}

}  // namespace seflex::fem
