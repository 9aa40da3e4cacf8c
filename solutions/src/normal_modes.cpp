// Normal modes (normal_modes.hpp).
#include "seflex/solutions/normal_modes.hpp"

#include <cmath>
#include <numbers>

#include "seflex/common/error.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/solutions/card_usage.hpp"
#include "guyan.hpp"
#include "solution_errors.hpp"

namespace seflex::solutions {
namespace {

SourceRef deck(const fem::Model& model) { return SourceRef{model.files.empty() ? std::string() : model.files.front(), 0}; }

SourceRef card_source(const fem::Model& model, const fem::CardRef& ref) {
  return SourceRef{ref.file < model.files.size() ? model.files[ref.file] : std::string(), static_cast<int>(ref.line)};
}

const fem::EigenMethod* find_method(const fem::Model& model, int sid) {
  for (const fem::EigenMethod& m : model.eigen_methods)
    if (m.sid == sid) return &m;
  return nullptr;
}

double lambda_of_hz(double f) {
  const double w = 2 * std::numbers::pi * f;
  return std::copysign(w * w, f);
}

/// Scale each column of phi (g-set) as `norm` asks; returns nothing, modifies phi.
void normalise(const fem::Model& model, const fem::GlobalMatrices& g, const fem::ConstrainedSystem& c,
               const fem::EigenMethod* method, ModeNormalization norm, Eigen::MatrixXd& phi_g) {
  std::optional<Eigen::Index> point_dof;
  // NORM = POINT on a point that is not a dof of the model: MAX (check_card_usage warns), as when
  // the component is ~0 in a mode.
  if (norm == ModeNormalization::Point) point_dof = fem::find_dof(model, g.dofs, method->norm_grid, method->norm_component);
  for (Eigen::Index j = 0; j < phi_g.cols(); ++j) {
    // the largest f-set component (by magnitude), signed
    double largest = 0;
    for (Eigen::Index d : c.f_to_g)
      if (std::abs(phi_g(d, j)) > std::abs(largest)) largest = phi_g(d, j);
    // Divided, not multiplied by the reciprocal: the normalising component becomes exactly 1 (x / x),
    // as Nastran prints it (x * (1 / x) can be 1 - 1 ulp).
    double divisor = 1.0;
    if (norm == ModeNormalization::Mass) {
      divisor = largest < 0 ? -1.0 : 1.0;  // modes arrive mass-normalised
    } else if (norm == ModeNormalization::Point && point_dof && std::abs(phi_g(*point_dof, j)) > 1e-10 * std::abs(largest)) {
      divisor = phi_g(*point_dof, j);
    } else if (largest != 0) {
      divisor = largest;
    }
    phi_g.col(j) /= divisor;
  }
}

}  // namespace

Eigen::VectorXd NormalModes::radians() const { return eigenvalues.cwiseAbs().cwiseSqrt(); }
Eigen::VectorXd NormalModes::cycles() const { return radians() / (2 * std::numbers::pi); }

NormalModes solve_normal_modes(const fem::Model& model, const ModesOptions& options) {
  NormalModes r;
  r.selection = select_case(model, options.subcase);
  require_usable(model, check_card_usage(model, Solution::NormalModes, {r.selection}, kInterfaceNone, options.ignore_unknown_cards));
  const fem::EigenMethod* method = nullptr;
  if (r.selection.method) {
    method = find_method(model, *r.selection.method);
    if (method == nullptr)
      throw InputError(deck(model), "case control METHOD = " + std::to_string(*r.selection.method) +
                                        ": no EIGRL or EIGR card has SID " + std::to_string(*r.selection.method));
  } else if (!options.count) {
    throw InputError(deck(model), "case control selects no METHOD (EIGRL/EIGR) for normal modes; add METHOD = <sid> "
                                  "or give the number of modes with --count");
  }

  linalg::EigenOptions eo;
  eo.backend = options.backend;
  eo.block_size = options.block_size;
  eo.factorization = options.factorization;
  eo.check_completeness = options.check_completeness;
  eo.external = options.external;
  eo.count = options.count;
  if (method != nullptr) {
    if (!eo.count) eo.count = method->nd;
    if (method->f1) eo.lambda_min = lambda_of_hz(*method->f1);
    if (method->f2) eo.lambda_max = lambda_of_hz(*method->f2);
    if (!eo.count && !eo.lambda_max)
      throw InputError(card_source(model, method->ref),
                       std::string(fem::method_card(*method)) + " " + std::to_string(method->sid) +
                           ": neither ND (number of roots) nor F2 (upper frequency) is given, so nothing bounds the "
                           "number of modes; set one of them or use --count");
    if (method->norm == "MAX") r.normalization = ModeNormalization::Max;
    else if (method->norm == "POINT") r.normalization = ModeNormalization::Point;
    else if (method->norm == "MASS" || method->norm.empty()) r.normalization = ModeNormalization::Mass;
    else
      throw InputError(card_source(model, method->ref),
                       std::string(fem::method_card(*method)) + " " + std::to_string(method->sid) + ": NORM '" +
                           method->norm + "' is not MASS, MAX or POINT");
  }

  const fem::GlobalMatrices g = fem::assemble(model, fem::assembly_options(model));
  fem::ConstraintOptions co;
  co.spc_set = r.selection.spc;
  co.mpc_set = r.selection.mpc;
  co.fixed_dofs = options.fixed_dofs;
  co.autospc = fem::autospc_enabled(model);
  const fem::ConstrainedSystem c = fem::apply_constraints(model, g, co);
  require_free_dofs(model, g, c, Solution::NormalModes);
  r.dofs = g.dofs;
  r.n_free = c.n_free();
  std::optional<detail::GuyanReduction> guyan;
  if (options.guyan) guyan = detail::guyan_reduction(model, g, c, options.factorization);
  if (guyan) r.guyan = GuyanInfo{static_cast<Eigen::Index>(guyan->a.size()), static_cast<Eigen::Index>(guyan->o.size()),
                                 guyan->from_aset};

  linalg::EigenSolution s;
  try {
    s = guyan ? linalg::solve_eigenproblem(guyan->K_aa, guyan->M_aa, eo) : linalg::solve_eigenproblem(c.K_ff, c.M_ff, eo);
    if (guyan) s.vectors = guyan->expand(s.vectors, c.n_free());
  } catch (const linalg::FactorizationError& e) {
    if (guyan)
      throw InputError(deck(model), "normal modes on the Guyan-reduced a-set (ASET/OMIT): K_aa - sigma M_aa is singular: "
                                    "an a-set motion has neither stiffness nor mass; constrain it or give it mass");
    throw_singular_dof(model, g, c, e, "normal modes: K - sigma M is singular",
                       "a motion of this dof has neither stiffness nor mass after the constraints (a massless "
                       "mechanism or rigid-body motion, e.g. a free beam's rotation about its axis with lumped mass); "
                       "constrain it (SPC/SPC1, GRID PS), give it mass (CONM2, PARAM COUPMASS) or connect it");
  }
  r.stats = s.stats;
  r.eigenvalues = s.eigenvalues;
  r.shapes_g = c.T * s.vectors;
  normalise(model, g, c, method, r.normalization, r.shapes_g);
  const Eigen::MatrixXd phi_f = [&] {
    Eigen::MatrixXd p(c.n_free(), r.shapes_g.cols());
    for (Eigen::Index i = 0; i < c.n_free(); ++i) p.row(i) = r.shapes_g.row(c.f_to_g[static_cast<std::size_t>(i)]);
    return p;
  }();
  r.generalized_mass = (phi_f.transpose() * (c.M_ff * phi_f)).diagonal();
  r.generalized_stiffness = (phi_f.transpose() * (c.K_ff * phi_f)).diagonal();
  return r;
}

}  // namespace seflex::solutions
