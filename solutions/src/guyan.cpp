// Static (Guyan) condensation to the a-set (guyan.hpp).
#include "guyan.hpp"

#include <string>

#include "seflex/common/error.hpp"
#include "seflex/fem/components.hpp"
#include "seflex/fem/finalize.hpp"
#include "solution_errors.hpp"

namespace seflex::solutions::detail {
namespace {

using Index = Eigen::Index;

/// The g-set dofs of ASET/OMIT entries with the card each came from.
void entry_dofs(const fem::Model& model, const fem::DofMap& dofs, const std::vector<fem::DofSetEntry>& entries,
                std::vector<std::pair<Index, const fem::DofSetEntry*>>& out) {
  for (const fem::DofSetEntry& e : entries) {
    if (const auto s = model.spoint_index.find(e.grid); s != model.spoint_index.end()) {
      out.emplace_back(dofs.spoint_dof(s->second), &e);
      continue;
    }
    const Index gi = model.grid_index.at(e.grid);
    for (int c = 1; c <= 6; ++c)
      if (fem::has_component(e.c, c)) out.emplace_back(dofs.grid_dof(gi, c), &e);
  }
}

[[noreturn]] void conflict(const fem::Model& model, const fem::DofMap& dofs, const fem::ConstrainedSystem& c,
                           const char* card, const fem::DofSetEntry& e, Index d) {
  const fem::DofLabel l = fem::dof_label(model, dofs, d);
  const std::string dof = l.scalar_point ? "scalar point " + std::to_string(l.point_id)
                                         : "grid " + std::to_string(l.point_id) + " component " + std::to_string(l.component);
  std::string why;
  if (c.status[static_cast<std::size_t>(d)] == fem::DofStatus::Dependent) {
    why = "dependent";
    if (!c.dependent_card.empty() && c.dependent_card[static_cast<std::size_t>(d)] >= 0)
      why += " in " + fem::describe(model, c.constraint_cards[static_cast<std::size_t>(c.dependent_card[static_cast<std::size_t>(d)])]);
  } else {
    why = "constrained (GRID PS, SPC/SPC1 of the selected set or a held dof)";
  }
  throw InputError(fem::where(model, e.ref), std::string(card) + ": " + dof + " is in the " +
                                                 (std::string(card).rfind("ASET", 0) == 0 ? "a-set" : "o-set") +
                                                 " but also " + why +
                                                 "; expected the a-set, o-set, s-set and m-set to be disjoint (as Nastran)");
}

}  // namespace

Eigen::MatrixXd GuyanReduction::expand(const Eigen::MatrixXd& x_a, Index n_f) const {
  Eigen::MatrixXd x_f = Eigen::MatrixXd::Zero(n_f, x_a.cols());
  for (std::size_t i = 0; i < a.size(); ++i) x_f.row(a[i]) = x_a.row(static_cast<Index>(i));
  const Eigen::MatrixXd x_o = G_oa * x_a;
  for (std::size_t i = 0; i < o.size(); ++i) x_f.row(o[i]) = x_o.row(static_cast<Index>(i));
  return x_f;
}

std::optional<GuyanReduction> guyan_reduction(const fem::Model& model, const fem::GlobalMatrices& g,
                                              const fem::ConstrainedSystem& c, linalg::FactorizationBackend backend) {
  if (model.aset.empty() && model.omit.empty()) return std::nullopt;
  const fem::DofMap& dofs = g.dofs;
  std::vector<std::pair<Index, const fem::DofSetEntry*>> aset, omit;
  entry_dofs(model, dofs, model.aset, aset);
  entry_dofs(model, dofs, model.omit, omit);
  const Index nf = c.n_free();
  std::vector<signed char> in_a(static_cast<std::size_t>(nf), model.aset.empty() ? 1 : 0);
  for (const auto& [d, e] : aset) {
    const fem::DofStatus st = c.status[static_cast<std::size_t>(d)];
    if (st == fem::DofStatus::AutoSpc) continue;
    if (st != fem::DofStatus::Free) conflict(model, dofs, c, "ASET/ASET1", *e, d);
    in_a[static_cast<std::size_t>(c.g_to_f[static_cast<std::size_t>(d)])] = 1;
  }
  for (const auto& [d, e] : omit) {
    const fem::DofStatus st = c.status[static_cast<std::size_t>(d)];
    if (st == fem::DofStatus::AutoSpc) continue;
    if (st != fem::DofStatus::Free) conflict(model, dofs, c, "OMIT/OMIT1", *e, d);
    const Index f = c.g_to_f[static_cast<std::size_t>(d)];
    if (!model.aset.empty() && in_a[static_cast<std::size_t>(f)])
      throw InputError(fem::where(model, e->ref),
                       "OMIT/OMIT1: a dof is also on an ASET/ASET1 card; expected the a-set and o-set to be disjoint");
    in_a[static_cast<std::size_t>(f)] = 0;
  }
  GuyanReduction r;
  r.from_aset = !model.aset.empty();
  std::vector<Index> local(static_cast<std::size_t>(nf));
  for (Index f = 0; f < nf; ++f) {
    auto& set = in_a[static_cast<std::size_t>(f)] ? r.a : r.o;
    local[static_cast<std::size_t>(f)] = static_cast<Index>(set.size());
    set.push_back(f);
  }
  if (r.o.empty()) return std::nullopt;
  const SourceRef deck{model.files.empty() ? std::string() : model.files.front(), 0};
  if (r.a.empty())
    throw InputError(deck, std::string(r.from_aset ? "ASET/ASET1" : "OMIT/OMIT1") +
                               ": no free dof is left in the a-set (all are omitted, constrained or without stiffness); "
                               "expected at least one a-set dof for the Guyan reduction");

  // Partitions of K_ff, M_ff (both triangles stored).
  const Index na = static_cast<Index>(r.a.size()), no = static_cast<Index>(r.o.size());
  auto split = [&](const linalg::SparseMatrixd& A, Eigen::MatrixXd& Aaa, linalg::SparseMatrixd& Aoa, linalg::SparseMatrixd& Aoo) {
    Aaa = Eigen::MatrixXd::Zero(na, na);
    std::vector<Eigen::Triplet<double>> oa, oo;
    for (Index j = 0; j < A.outerSize(); ++j) {
      const bool ja = in_a[static_cast<std::size_t>(j)];
      const Index lj = local[static_cast<std::size_t>(j)];
      for (linalg::SparseMatrixd::InnerIterator it(A, j); it; ++it) {
        const Index i = it.row();
        const bool ia = in_a[static_cast<std::size_t>(i)];
        const Index li = local[static_cast<std::size_t>(i)];
        if (ia && ja) Aaa(li, lj) = it.value();
        else if (!ia && ja) oa.emplace_back(li, lj, it.value());
        else if (!ia && !ja) oo.emplace_back(li, lj, it.value());
      }
    }
    Aoa.resize(no, na);
    Aoa.setFromTriplets(oa.begin(), oa.end());
    Aoo.resize(no, no);
    Aoo.setFromTriplets(oo.begin(), oo.end());
  };
  Eigen::MatrixXd Kaa, Maa;
  linalg::SparseMatrixd Koa, Koo, Moa, Moo;
  split(c.K_ff, Kaa, Koa, Koo);
  split(c.M_ff, Maa, Moa, Moo);

  auto factor = linalg::make_factorization(backend);
  try {
    factor->factorize(Koo);
  } catch (const linalg::FactorizationError& e) {
    std::string where = "(dof unknown)";
    if (e.column() >= 0 && e.column() < no) {
      const fem::DofLabel l = fem::dof_label(model, dofs, c.f_to_g[static_cast<std::size_t>(r.o[static_cast<std::size_t>(e.column())])]);
      where = l.scalar_point ? "scalar point " + std::to_string(l.point_id)
                             : "grid " + std::to_string(l.point_id) + " component " + std::to_string(l.component);
    }
    throw InputError(deck, "Guyan reduction (ASET/OMIT): the stiffness of the omitted dofs K_oo is singular at " + where +
                               ": the o-set can move without deforming while the a-set is held; put a dof that holds "
                               "it in the a-set (ASET) or constrain it");
  }
  r.G_oa = Eigen::MatrixXd(Koa);
  factor->solve_in_place(r.G_oa);
  r.G_oa *= -1.0;
  Eigen::MatrixXd Kbar = Kaa + Koa.transpose() * r.G_oa;
  const Eigen::MatrixXd MoaG = Moa.transpose() * r.G_oa;
  Eigen::MatrixXd Mbar = Maa + MoaG + MoaG.transpose() + r.G_oa.transpose() * (Moo * r.G_oa);
  Kbar = 0.5 * (Kbar + Kbar.transpose()).eval();
  Mbar = 0.5 * (Mbar + Mbar.transpose()).eval();
  r.K_aa = Kbar.sparseView(0.0, 0.0);
  r.M_aa = Mbar.sparseView(0.0, 0.0);
  return r;
}

}  // namespace seflex::solutions::detail
