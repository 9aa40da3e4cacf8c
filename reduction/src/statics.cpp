// Linear statics (statics.hpp).
#include "seflex/reduction/statics.hpp"

#include "seflex/common/error.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/loads.hpp"
#include "matrix_norms.hpp"
#include "solution_errors.hpp"

namespace seflex::reduction {

StaticSolution solve_static(const fem::Model& model, const StaticOptions& options) {
  StaticSolution s;
  s.selection = select_case(model, options.subcase);
  if (!s.selection.load)
    throw InputError(SourceRef{model.files.empty() ? std::string() : model.files.front(), 0},
                     "case control: no LOAD = <set> selected" +
                         (s.selection.subcase_id ? " in SUBCASE " + std::to_string(s.selection.subcase_id) : std::string()) +
                         " (statics needs a load set)");
  const fem::GlobalMatrices g = fem::assemble(model, fem::assembly_options(model));
  const fem::ConstrainedSystem c = fem::apply_constraints(model, g, s.selection.spc);
  s.dofs = g.dofs;
  s.n_free = c.n_free();
  s.p_g = fem::load_vector(model, g.dofs, *s.selection.load);
  Eigen::VectorXd u_f = fem::reduce_load(c, g, s.p_g);
  const double p_norm = u_f.norm();
  if (s.n_free > 0) {
    auto factor = make_factorization(options.factorization);
    try {
      factor->factorize(c.K_ff);
    } catch (const FactorizationError& e) {
      throw_singular_dof(model, g, c, e, "statics: the constrained stiffness matrix is singular",
                         "the model can move without deforming (a rigid-body motion no SPC holds, or a mechanism); "
                         "constrain it with SPC/SPC1 or GRID PS");
    }
    const Eigen::VectorXd p_f = u_f;
    factor->solve_in_place(u_f);
    const double scale = norm1_symmetric(c.K_ff) * u_f.norm() + p_norm;
    s.backward_error = scale > 0 ? (c.K_ff * u_f - p_f).norm() / scale : 0.0;
  }
  s.u_g = fem::expand(c, u_f);
  // Forces of single-point constraint: K u - p on the constrained dofs.
  const Eigen::VectorXd r = g.K * s.u_g - s.p_g;
  s.q_g = Eigen::VectorXd::Zero(r.size());
  for (Eigen::Index d = 0; d < r.size(); ++d) {
    const fem::DofStatus st = c.status[static_cast<std::size_t>(d)];
    if (st == fem::DofStatus::Spc || st == fem::DofStatus::AutoSpc || st == fem::DofStatus::Fixed) s.q_g(d) = r(d);
  }
  return s;
}

}  // namespace seflex::reduction
