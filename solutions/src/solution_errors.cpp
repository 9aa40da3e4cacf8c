// User-facing errors of the solutions (solution_errors.hpp).
#include "solution_errors.hpp"

#include "card_usage_table.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/finalize.hpp"

namespace seflex::solutions {

namespace {

/// The nodes (grids, then scalar points, as DofMap numbers them) connected to node `start` by the
/// stiffness (any nonzero coupling of their dofs in K) or by a constraint (dependent dofs: the
/// columns of T), if none of them has a dof held by an SPC, GRID PS or SUPORT; empty otherwise.
std::vector<Eigen::Index> unheld_part(const fem::GlobalMatrices& g, const fem::ConstrainedSystem& c, Eigen::Index start) {
  const fem::DofMap& dofs = g.dofs;
  if (g.K.nonZeros() == 0) return {};  // the stiffness was released (nothing to tell the parts by)
  std::vector<Eigen::Index> parent(static_cast<std::size_t>(dofs.n_nodes()));
  for (std::size_t n = 0; n < parent.size(); ++n) parent[n] = static_cast<Eigen::Index>(n);
  const auto root = [&](Eigen::Index n) {
    while (parent[static_cast<std::size_t>(n)] != n) {
      Eigen::Index& up = parent[static_cast<std::size_t>(n)];
      up = parent[static_cast<std::size_t>(up)];  // path halving
      n = up;
    }
    return n;
  };
  const auto join = [&](Eigen::Index a, Eigen::Index b) { parent[static_cast<std::size_t>(root(dofs.node_of_dof(a)))] = root(dofs.node_of_dof(b)); };
  for (Eigen::Index j = 0; j < g.K.outerSize(); ++j)
    for (linalg::SparseMatrixd::InnerIterator it(g.K, j); it; ++it)
      if (it.value() != 0.0) join(it.row(), it.col());
  for (Eigen::Index f = 0; f < c.T.outerSize(); ++f) {
    Eigen::Index first = -1;
    for (linalg::SparseMatrixd::InnerIterator it(c.T, f); it; ++it) first < 0 ? void(first = it.row()) : join(first, it.row());
  }
  const Eigen::Index part = root(start);
  std::vector<Eigen::Index> nodes;
  for (Eigen::Index n = 0; n < dofs.n_nodes(); ++n) {
    if (root(n) != part) continue;
    for (int k = 0; k < dofs.node_dof_count(n); ++k) {
      const fem::DofStatus s = c.status[static_cast<std::size_t>(dofs.node_first_dof(n) + k)];
      if (s == fem::DofStatus::Spc || s == fem::DofStatus::Fixed) return {};
    }
    nodes.push_back(n);
  }
  return nodes;
}

}  // namespace

void throw_singular_dof(const fem::Model& model, const fem::GlobalMatrices& g, const fem::ConstrainedSystem& c,
                        const linalg::FactorizationError& e, const std::string& what, const std::string& advice) {
  std::string where = "(dof unknown)";
  const SourceRef deck{model.files.empty() ? std::string() : model.files.front(), 0};
  if (e.column() >= 0 && e.column() < c.n_free()) {
    const Eigen::Index d = c.f_to_g[static_cast<std::size_t>(e.column())];
    const fem::DofLabel label = fem::dof_label(model, g.dofs, d);
    where = label.scalar_point ? "scalar point " + std::to_string(label.point_id)
                               : "grid " + std::to_string(label.point_id) + " component " + std::to_string(label.component);
    // A part that nothing holds (no SPC, and no element or constraint to a held part): say which.
    const std::vector<Eigen::Index> part = unheld_part(g, c, g.dofs.node_of_dof(d));
    if (!part.empty() && static_cast<Eigen::Index>(part.size()) < g.dofs.n_nodes()) {
      std::string ids;
      for (std::size_t k = 0; k < part.size() && k < 6; ++k)
        ids += (k ? ", " : "") +
               std::to_string(fem::dof_label(model, g.dofs, g.dofs.node_first_dof(part[k])).point_id);
      if (part.size() > 6) ids += ", ...";
      const Eigen::Index n0 = part.front();
      const fem::CardRef ref = n0 < g.dofs.n_grids ? model.grids[static_cast<std::size_t>(n0)].ref
                                                   : model.spoints[static_cast<std::size_t>(n0 - g.dofs.n_grids)].ref;
      throw InputError(deck, what + " at " + where + ": it belongs to a part of " + std::to_string(part.size()) +
                                 " points (" + ids + "; the first defined at " + fem::where(model, ref).str() +
                                 ") that no SPC holds and no element or rigid element connects to the rest of the "
                                 "model, so it moves freely; connect it (shared grids, RBE2) or constrain it (SPC/SPC1)");
    }
  }
  throw InputError(deck, what + " at " + where + ": " + advice);
}

void require_free_dofs(const fem::Model& model, const fem::GlobalMatrices& g, const fem::ConstrainedSystem& c,
                       Solution solution) {
  if (c.n_free() > 0) return;
  const SourceRef deck{model.files.empty() ? std::string() : model.files.front(), 0};
  const std::string start = std::string(solution_name(solution)) + " has nothing to solve: no free dof (";
  const Eigen::Index n = g.dofs.size();
  if (n == 0) throw InputError(deck, start + "the model has no GRID or SPOINT)");
  bool stiffness = false;
  for (Eigen::Index k = 0; k < g.K.nonZeros() && !stiffness; ++k) stiffness = g.K.valuePtr()[k] != 0.0;
  if (!stiffness) {
    std::string unknown;
    std::size_t kinds = 0;
    for (const fem::UnsupportedCard& u : model.unsupported)
      if (detail::is_unknown_card(u.name) && ++kinds <= 6)
        unknown += (kinds > 1 ? ", " : "") + u.name;
    if (kinds > 6) unknown += ", ...";
    throw InputError(deck, start + "the model has no element with stiffness: AUTOSPC removed all " + std::to_string(n) +
                               " dofs" +
                               (kinds ? "; the cards seflex does not know (" + unknown + ") were left out" : std::string()) +
                               "); expected elements seflex models (docs/nastran-support.md)");
  }
  if (solution == Solution::Statics) return;  // the SPC forces of the held structure are the answer
  Eigen::Index spc = 0, autospc = 0, dependent = 0, fixed = 0;
  for (const fem::DofStatus s : c.status) {
    spc += s == fem::DofStatus::Spc;
    autospc += s == fem::DofStatus::AutoSpc;
    dependent += s == fem::DofStatus::Dependent;
    fixed += s == fem::DofStatus::Fixed;
  }
  std::string how;
  const auto add = [&](Eigen::Index count, const char* what) {
    if (count > 0) how += (how.empty() ? "" : ", ") + std::to_string(count) + " " + what;
  };
  add(spc, "by SPC/SPC1 or GRID PS");
  add(autospc, "by AUTOSPC (no stiffness)");
  add(dependent, "dependent (MPC, RBE2, RBAR, RBE3)");
  add(fixed, "held (SUPORT or interface)");
  throw InputError(deck, start + "every one of the " + std::to_string(n) + " dofs is constrained: " + how +
                             "); expected a structure that can deform");
}

}  // namespace seflex::solutions
