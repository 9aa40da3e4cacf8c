// MPC and MPCADD as dependent-dof rows (constraint_equations.hpp).
//
// MPC SID G1 C1 A1 G2 C2 A2 ...: sum_j A_j u_j = 0 (components in the grids' CD systems), the first
// dof dependent (QRG MPC): u_1 = -sum_{j>1} (A_j / A_1) u_j. MPCADD SID S1 S2 ... unions MPC sets;
// case control MPC = SID selects an MPC or MPCADD set.
#include <set>

#include "constraint_equations.hpp"
#include "model_lookup.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/finalize.hpp"

namespace seflex::fem::detail {

void add_mpc_set(const Model& model, const DofMap& dofs, int sid, ConstraintEquations& eq) {
  bool defined = false;
  const std::set<int> sets = expand_sets(sid, model.mpcadds, &defined);
  for (const MpcEquation& e : model.mpcs) {
    if (!sets.count(e.sid)) continue;
    defined = true;
    const std::uint32_t card = eq.add_card("MPC", e.sid, e.ref);
    std::vector<std::pair<Eigen::Index, double>> terms;
    for (std::size_t k = 0; k < e.terms.size(); ++k) {
      const MpcTerm& t = e.terms[k];
      const auto dof = find_dof(model, dofs, t.grid, t.component);
      if (!dof) {
        const bool grid = model.grid_index.count(t.grid) > 0, spoint = model.spoint_index.count(t.grid) > 0;
        std::string what;
        if (!grid && !spoint) {
          what = "references point ";
          what += std::to_string(t.grid);
          what += ", which is not defined; expected the id of a GRID or SPOINT";
        } else {
          what = grid ? "grid " : "scalar point ";
          what += std::to_string(t.grid);
          what += " with component ";
          what += std::to_string(t.component);
          what += grid ? "; expected one component 1-6 for a grid" : "; expected 0 or blank for a scalar point";
        }
        std::string field = "G";
        field += std::to_string(k + 1);
        fail(model, e.ref, "MPC", e.sid, field, what);
      }
      terms.emplace_back(*dof, t.a);
    }
    DependentDof d;
    d.dof = terms.front().first;
    d.card = card;
    const double a1 = terms.front().second;
    for (std::size_t k = 1; k < terms.size(); ++k) {
      std::string field = "G";
      field += std::to_string(k + 1);
      if (terms[k].first == d.dof)
        fail(model, e.ref, "MPC", e.sid, field,
             "the dependent dof (G1, C1) appears again in its own equation; expected it once");
      if (terms[k].second != 0.0) d.terms.emplace_back(terms[k].first, -terms[k].second / a1);
    }
    eq.dependents.push_back(std::move(d));
  }
  if (!defined)
    throw InputError(SourceRef{model.files.empty() ? std::string() : model.files.front(), 0},
                     "case control MPC = " + std::to_string(sid) + ": no MPC or MPCADD bulk data card has SID " +
                         std::to_string(sid) + "; expected the id of an MPC set");
}

}  // namespace seflex::fem::detail
