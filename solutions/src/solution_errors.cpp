// User-facing errors of the solutions (solution_errors.hpp).
#include "solution_errors.hpp"

#include "seflex/common/error.hpp"

namespace seflex::solutions {

void throw_singular_dof(const fem::Model& model, const fem::GlobalMatrices& g, const fem::ConstrainedSystem& c,
                        const linalg::FactorizationError& e, const std::string& what, const std::string& advice) {
  std::string where = "(dof unknown)";
  if (e.column() >= 0 && e.column() < c.n_free()) {
    const fem::DofLabel label = fem::dof_label(model, g.dofs, c.f_to_g[static_cast<std::size_t>(e.column())]);
    where = label.scalar_point ? "scalar point " + std::to_string(label.point_id)
                               : "grid " + std::to_string(label.point_id) + " component " + std::to_string(label.component);
  }
  throw InputError(SourceRef{model.files.empty() ? std::string() : model.files.front(), 0},
                   what + " at " + where + ": " + advice);
}

}  // namespace seflex::solutions
