// Linear statics (statics.hpp).
#include "seflex/solutions/statics.hpp"

#include <algorithm>
#include <optional>

#include "seflex/common/error.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/enforced_motion.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/fem/loads.hpp"
#include "seflex/solutions/card_usage.hpp"
#include "seflex/linalg/matrix_norms.hpp"
#include "solution_errors.hpp"

namespace seflex::solutions {
namespace {

/// g-set dofs of the SUPORT entries and of the SUPORT1 entries of set `suport1` (held at zero in
/// statics).
std::vector<Eigen::Index> suport_dofs(const fem::Model& model, const fem::DofMap& dofs, std::optional<int> suport1) {
  std::vector<Eigen::Index> out;
  auto hold = [&](const fem::DofSetEntry& e) {
    if (model.spoint_index.count(e.grid)) {
      out.push_back(dofs.spoint_dof(model.spoint_index.at(e.grid)));
      return;
    }
    for (int c = 1; c <= 6; ++c)
      if ((e.c >> (c - 1)) & 1u) out.push_back(dofs.grid_dof(model.grid_index.at(e.grid), c));
  };
  for (const fem::DofSetEntry& e : model.suport) hold(e);
  if (suport1)
    for (const fem::Suport1Entry& e : model.suport1)
      if (e.sid == *suport1) hold(e.dofs);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// The first SPCD card naming point `id` (for messages).
fem::CardRef spcd_ref(const fem::Model& model, int id) {
  for (const fem::EnforcedMotion& e : model.enforced_motions)
    if (e.grid == id) return e.ref;
  return {};
}

std::vector<StaticSolution> solve(const fem::Model& model, const std::vector<CaseSelection>& cases,
                                  const StaticOptions& options) {
  require_usable(model, check_card_usage(model, Solution::Statics, cases, kInterfaceNone, options.ignore_unknown_cards));
  const fem::GlobalMatrices g = fem::assemble(model, fem::assembly_options(model));
  std::vector<StaticSolution> out(cases.size());
  std::vector<bool> done(cases.size(), false);
  for (std::size_t first = 0; first < cases.size(); ++first) {
    if (done[first]) continue;
    // every subcase with the same SPC, MPC and SUPORT1 sets shares the constrained system and its factor
    fem::ConstraintOptions co;
    co.spc_set = cases[first].spc;
    co.mpc_set = cases[first].mpc;
    co.fixed_dofs = suport_dofs(model, g.dofs, cases[first].suport1);
    co.autospc = fem::autospc_enabled(model);
    const fem::ConstrainedSystem c = fem::apply_constraints(model, g, co);
    require_free_dofs(model, g, c, Solution::Statics);
    // every dof held by SPCs (require_free_dofs lets statics through): the SPC forces are the answer
    std::unique_ptr<linalg::SparseFactorization> factor;
    double norm_K = 0;
    if (c.n_free() > 0) {
      factor = linalg::make_factorization(options.factorization);
      try {
        factor->factorize(c.K_ff);
      } catch (const linalg::FactorizationError& e) {
        throw_singular_dof(model, g, c, e, "statics: the constrained stiffness matrix is singular",
                           "the model can move without deforming (a rigid-body motion no SPC holds, or a mechanism); "
                           "constrain it with SPC/SPC1 or GRID PS");
      }
      norm_K = linalg::norm1_symmetric(c.K_ff);
    }
    for (std::size_t k = first; k < cases.size(); ++k) {
      if (done[k] || cases[k].spc != co.spc_set || cases[k].mpc != co.mpc_set || cases[k].suport1 != cases[first].suport1)
        continue;
      done[k] = true;
      StaticSolution& s = out[k];
      s.selection = cases[k];
      s.dofs = g.dofs;
      s.n_free = c.n_free();
      s.p_g = s.selection.load ? fem::load_vector(model, g.dofs, *s.selection.load, &g.load_mass())
                               : Eigen::VectorXd::Zero(g.dofs.size());
      if (s.selection.temperature) s.p_g += fem::thermal_load_vector(model, g.dofs, *s.selection.temperature);
      // SPCD of the LOAD set: enforced values on dofs of the SPC set (enforced_motion.hpp)
      Eigen::VectorXd u_g0 = c.u_g0;
      if (s.selection.load)
        for (const auto& [d, value] : fem::enforced_motion_dofs(model, g.dofs, *s.selection.load)) {
          if (c.status[static_cast<std::size_t>(d)] != fem::DofStatus::Spc) {
            const fem::DofLabel lb = fem::dof_label(model, g.dofs, d);
            throw InputError(fem::where(model, spcd_ref(model, lb.point_id)),
                             "SPCD: grid " + std::to_string(lb.point_id) + " component " + std::to_string(lb.component) +
                                 " is not in the subcase's SPC set" +
                                 (s.selection.spc ? " " + std::to_string(*s.selection.spc) : std::string(" (none selected)")) +
                                 "; expected every SPCD component to be constrained by an SPC/SPC1 of the selected set (QRG SPCD)");
          }
          u_g0[d] = value;
        }
      Eigen::VectorXd u_f = c.T.transpose() * (u_g0.isZero(0.0) ? s.p_g : Eigen::VectorXd(s.p_g - g.K * u_g0));
      if (factor) {
        const Eigen::VectorXd p_f = u_f;
        factor->solve_in_place(u_f);
        const double scale = norm_K * u_f.norm() + p_f.norm();
        s.backward_error = scale > 0 ? (c.K_ff * u_f - p_f).norm() / scale : 0.0;
      }
      s.u_g = c.T * u_f + u_g0;
      // Forces of single-point constraint: K u - p on the constrained dofs.
      const Eigen::VectorXd r = g.K * s.u_g - s.p_g;
      s.q_g = Eigen::VectorXd::Zero(r.size());
      for (Eigen::Index d = 0; d < r.size(); ++d) {
        const fem::DofStatus st = c.status[static_cast<std::size_t>(d)];
        if (st == fem::DofStatus::Spc || st == fem::DofStatus::AutoSpc || st == fem::DofStatus::Fixed) s.q_g(d) = r(d);
      }
    }
  }
  return out;
}

}  // namespace

StaticSolution solve_static(const fem::Model& model, const StaticOptions& options) {
  return solve(model, {select_case(model, options.subcase)}, options).front();
}

std::vector<StaticSolution> solve_statics(const fem::Model& model, const StaticOptions& options) {
  return solve(model, select_cases(model, options.subcase), options);
}

}  // namespace seflex::solutions
