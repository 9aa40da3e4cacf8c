// SPC, MPC and rigid-element elimination (see constraints.hpp).
#include "seflex/fem/constraints.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <functional>
#include <set>
#include <string_view>

#include "constraint_equations.hpp"
#include "model_lookup.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/components.hpp"

namespace seflex::fem {
namespace {

using Index = Eigen::Index;
using Row = std::vector<std::pair<Index, double>>;  // sparse row: (g dof, coefficient)

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

std::set<int> expand_sets(int sid, const std::vector<SetCombination>& combinations, bool* combined) {
  std::set<int> out;
  std::vector<int> todo{sid};
  if (combined) *combined = false;
  while (!todo.empty()) {
    const int s = todo.back();
    todo.pop_back();
    if (!out.insert(s).second) continue;
    for (const SetCombination& c : combinations)
      if (c.sid == s) {
        if (combined) *combined = true;
        todo.insert(todo.end(), c.sets.begin(), c.sets.end());
      }
  }
  return out;
}

std::vector<std::pair<Eigen::Index, double>> spc_set_dofs(const Model& model, const DofMap& dofs, int spc_set) {
  bool defined = false;
  const std::set<int> sets = expand_sets(spc_set, model.spcadds, &defined);
  std::vector<std::pair<Index, double>> out;
  for (const SpcEntry& e : model.spcs) {
    if (!sets.count(e.sid)) continue;
    defined = true;
    if (model.spoint_index.count(e.grid) && (e.c == 0 || e.c == 1)) {
      out.emplace_back(dofs.spoint_dof(model.spoint_index.at(e.grid)), e.d);
      continue;
    }
    const auto it = model.grid_index.find(e.grid);
    if (it == model.grid_index.end() && e.from_thru) continue;  // QRG SPC1: grids of a THRU range need not exist
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

namespace {

/// The card that constrains g dof d (GRID PS or an entry of the SPC set), for conflict messages.
std::string constraint_source(const Model& model, const DofMap& dofs, const ConstraintOptions& o, Index d,
                              DofStatus status) {
  if (status == DofStatus::Fixed) return "a dof held fixed by the solution (SUPORT or a superelement interface)";
  if (d < 6 * dofs.n_grids) {
    const Grid& grid = model.grids[static_cast<std::size_t>(d / 6)];
    const int c = static_cast<int>(d % 6) + 1;
    if (has_component(grid.ps, c)) return "PS on GRID " + std::to_string(grid.id) + " (" + where(model, grid.ref).str() + ")";
    if (o.spc_set)
      for (const SpcEntry& e : model.spcs)
        if (e.grid == grid.id && has_component(e.c, c))
          return "SPC/SPC1 set " + std::to_string(e.sid) + " (" + where(model, e.ref).str() + ")";
  } else if (o.spc_set) {
    const int id = model.spoints[static_cast<std::size_t>(d - 6 * dofs.n_grids)].id;
    for (const SpcEntry& e : model.spcs)
      if (e.grid == id) return "SPC/SPC1 set " + std::to_string(e.sid) + " (" + where(model, e.ref).str() + ")";
  }
  return "a single-point constraint";
}

}  // namespace

namespace {
/// "RBE3 5" / "MPC set 2".
std::string label(const ConstraintCard& card) {
  const bool set = std::string_view(card.card) == "MPC";
  return std::string(card.card) + (set ? " set " : " ") + std::to_string(card.id);
}
}  // namespace

std::string describe(const Model& model, const ConstraintCard& card) {
  return label(card) + " (" + where(model, card.ref).str() + ")";
}

bool autospc_enabled(const Model& model) {
  for (const Param& p : model.params)
    if (p.name == "AUTOSPC") return p.values.empty() || p.values[0] != "NO";
  return true;
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

  // m-set: rigid elements, RBE3s and the selected MPC set, each dependent dof as a combination of others.
  detail::ConstraintEquations eq;
  if (has_rigid_elements(model) || options.mpc_set) {
    const auto axes = grid_cd_axes(model);
    detail::add_rigid_elements(model, dofs, axes, eq);
    detail::add_rbe3_elements(model, dofs, axes, eq);
    if (options.mpc_set) detail::add_mpc_set(model, dofs, *options.mpc_set, eq);
  }
  const bool any_dependent = !eq.dependents.empty();
  std::vector<std::int32_t> dep(any_dependent ? static_cast<std::size_t>(n) : 0, -1);  // index into eq.dependents
  for (std::size_t k = 0; k < eq.dependents.size(); ++k) {
    const detail::DependentDof& d = eq.dependents[k];
    const ConstraintCard& card = eq.cards[d.card];
    if (dep[d.dof] >= 0) {
      const ConstraintCard& first = eq.cards[eq.dependents[static_cast<std::size_t>(dep[d.dof])].card];
      throw InputError(where(model, card.ref),
                       label(card) + ": " + detail::dof_name(model, dofs, d.dof) + " is made dependent here and by " + describe(model, first) +
                           "; expected each dependent dof in one rigid element or MPC equation (Nastran's m-set)");
    }
    if (out.status[d.dof] != DofStatus::Free)
      throw InputError(where(model, card.ref),
                       label(card) + ": " + detail::dof_name(model, dofs, d.dof) + " is dependent here but also constrained by " +
                           constraint_source(model, dofs, options, d.dof, out.status[d.dof]) +
                           "; expected a dependent dof not to be constrained (the m-set and the s-set do not overlap)");
    dep[d.dof] = static_cast<std::int32_t>(k);
    out.status[d.dof] = DofStatus::Dependent;
  }
  if (any_dependent) {
    out.constraint_cards = eq.cards;
    out.dependent_card.assign(static_cast<std::size_t>(n), -1);
    for (Index m = 0; m < n; ++m)
      if (dep[m] >= 0) out.dependent_card[m] = static_cast<std::int32_t>(eq.dependents[static_cast<std::size_t>(dep[m])].card);
  }

  // Resolve chains: express every dependent dof through non-dependent dofs only (iteratively, so
  // that long chains cannot overflow the stack).
  std::vector<Row> resolved(any_dependent ? static_cast<std::size_t>(n) : 0);
  if (any_dependent) {
    std::vector<unsigned char> state(static_cast<std::size_t>(n), 0);  // 0 new, 1 in progress, 2 done
    std::vector<Index> stack;
    for (Index root = 0; root < n; ++root) {
      if (dep[root] < 0 || state[root] == 2) continue;
      stack.push_back(root);
      while (!stack.empty()) {
        const Index m = stack.back();
        const detail::DependentDof& d = eq.dependents[static_cast<std::size_t>(dep[m])];
        if (state[m] == 0) {
          state[m] = 1;
          for (const auto& [k, a] : d.terms) {
            if (dep[k] < 0 || state[k] == 2) continue;
            if (state[k] == 1) {
              const ConstraintCard& here = eq.cards[d.card];
              const ConstraintCard& there = eq.cards[eq.dependents[static_cast<std::size_t>(dep[k])].card];
              throw InputError(where(model, here.ref),
                               label(here) + ": its dependent " +
                                   detail::dof_name(model, dofs, m) + " depends on " + detail::dof_name(model, dofs, k) +
                                   ", which depends back on it through " + describe(model, there) +
                                   "; expected no closed loop of dependencies");
            }
            stack.push_back(k);
          }
          continue;
        }
        stack.pop_back();
        if (state[m] == 2) continue;
        Row row;
        for (const auto& [k, a] : d.terms) {
          if (dep[k] >= 0)
            for (const auto& [kk, b] : resolved[k]) row.emplace_back(kk, a * b);
          else
            row.emplace_back(k, a);
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
      }
    }
  }

  // Columns of T before AUTOSPC: for each independent dof j, the dependents that use it.
  std::vector<Row> users(any_dependent ? static_cast<std::size_t>(n) : 0);
  if (any_dependent)
    for (Index m = 0; m < n; ++m)
      if (dep[m] >= 0)
        for (const auto& [k, a] : resolved[m]) users[k].emplace_back(m, a);

  // AUTOSPC on the per-grid 3 x 3 blocks of T^T K T (computed from the columns of T, without the product).
  if (options.autospc) {
    auto column = [&](Index j) {
      Row t;
      if (any_dependent) t = users[j];
      t.emplace_back(j, 1.0);
      return t;
    };
    auto kbar = [&](const Row& a, const Row& b) {
      double s = 0.0;
      for (const auto& [p, tp] : a)
        for (const auto& [q, tq] : b) s += tp * tq * lookup(g.K, p, q);
      return s;
    };
    std::vector<bool> exempt(static_cast<std::size_t>(n), false);
    for (const Index d : options.no_autospc) {
      SEFLEX_DEMAND(d >= 0 && d < n, "no_autospc dof out of range");
      exempt[static_cast<std::size_t>(d)] = true;
    }
    for (Index i = 0; i < dofs.n_grids; ++i)
      for (int h = 0; h < 2; ++h) {
        std::vector<Index> free;
        for (int c = 0; c < 3; ++c)
          if (out.status[6 * i + 3 * h + c] == DofStatus::Free && !exempt[static_cast<std::size_t>(6 * i + 3 * h + c)])
            free.push_back(6 * i + 3 * h + c);
        if (free.empty()) continue;
        const Index k = static_cast<Index>(free.size());
        std::vector<Row> cols;
        for (const Index d : free) cols.push_back(column(d));
        Eigen::MatrixXd B(k, k);
        for (Index p = 0; p < k; ++p)
          for (Index q = p; q < k; ++q) B(p, q) = B(q, p) = kbar(cols[p], cols[q]);
        const double dmax = B.diagonal().cwiseAbs().maxCoeff();
        if (!(dmax > 0.0)) {
          for (const Index d : free) out.status[d] = DofStatus::AutoSpc;
          continue;
        }
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(B);
        std::vector<bool> taken(static_cast<std::size_t>(k), false);
        for (Index e = 0; e < k; ++e) {
          if (es.eigenvalues()(e) > 1e-8 * dmax) continue;
          const Eigen::VectorXd v = es.eigenvectors().col(e);
          Index best = -1;
          for (Index p = 0; p < k; ++p)
            if (!taken[static_cast<std::size_t>(p)] && (best < 0 || std::abs(v(p)) > std::abs(v(best)))) best = p;
          if (best < 0) break;
          taken[static_cast<std::size_t>(best)] = true;
          out.status[free[static_cast<std::size_t>(best)]] = DofStatus::AutoSpc;
        }
      }
    for (Index d = 6 * dofs.n_grids; d < n; ++d)
      if (out.status[d] == DofStatus::Free && !exempt[static_cast<std::size_t>(d)] && kbar(column(d), column(d)) == 0.0)
        out.status[d] = DofStatus::AutoSpc;
  }

  // Dofs an external superelement lists but gives no stiffness (zero rows of its KAA: the rotations of
  // solid grids in its a-set) and nothing else holds: removed even with AUTOSPC off. This matches one
  // MSC run, not a documented rule. MSC Nastran 2017.1's se_test_n11 (case control AUTOSPC(NOPRINT) =
  // NO and PARAM,AUTOSPC,NO; five boundary grids' rotations without stiffness) solves, and its f06
  // (pyNastran models/superelements/se_test_static) prints no singularity message and decomposes KLL
  // with a largest matrix-to-factor-diagonal ratio of 27.7 (SIM 4159): those null columns were not in
  // its l-set. No manual we could read states why: the PARAM AUTOSPC text (NX Nastran QRG, quoted at
  // eng-tips.com/threads/param-cards-in-nastran.348205) says AUTOSPC = NO leaves singularities
  // unconstrained and "AUTOSPC provides the correct action for Superelements in all contexts"; nothing
  // found on SEBULK EXTOP4, external-superelement a-sets or null columns says more (searched: MSC QRG,
  // Superelements User's Guide, DMAP GPSP). OptiStruct documents a like rule for solids only (PARAM
  // AUTOSPC remark 2: rotations of grids connected only to solid elements are removed even with AUTOSPC
  // off). Whether MSC does the same for a K2GG DMIG's null columns is unknown; seflex does not (with
  // AUTOSPC off they stay free).
  if (!options.autospc)
    for (const ExternalMatrices& x : model.external_parts)
      for (std::size_t i = 0; i < x.dofs.size(); ++i) {
        const auto ii = static_cast<Index>(i);
        if (x.K.row(ii).cwiseAbs().maxCoeff() != 0.0) continue;
        const auto d = find_dof(model, dofs, x.dofs[i].first, x.dofs[i].second);
        if (d && out.status[*d] == DofStatus::Free && (!any_dependent || users[*d].empty()) && lookup(g.K, *d, *d) == 0.0)
          out.status[*d] = DofStatus::AutoSpc;
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
      if (dep[m] < 0) continue;
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
