// Linear buckling, SOL 105 (see buckling_solution.hpp).
#include "seflex/solutions/buckling.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>

#include "seflex/common/error.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/fem/geometric_stiffness.hpp"
#include "seflex/solutions/card_usage.hpp"
#include "seflex/solutions/statics.hpp"
#include "solution_errors.hpp"

namespace seflex::solutions {
namespace {

using seflex::solutions::CaseSelection;

// STATSUB(BUCKLING) = n / STATSUB = n of a subcase, if any.
std::optional<int> statsub(const fem::Model& model, const CaseSelection& c) {
  for (const fem::CaseCommand& cmd : c.other) {
    if (cmd.name != "STATSUB" && cmd.name.rfind("STATSUB(", 0) != 0) continue;
    try {
      std::size_t pos = 0;
      const int id = std::stoi(cmd.value, &pos);
      if (pos == cmd.value.size() || cmd.value.find_first_not_of(' ', pos) == std::string::npos) return id;
    } catch (const std::exception&) {
    }
    throw InputError(fem::where(model, cmd.ref),
                     "case control " + cmd.name + " = '" + cmd.value + "': expected a subcase id");
  }
  return std::nullopt;
}

}  // namespace

std::pair<CaseSelection, CaseSelection> buckling_cases(const fem::Model& model) {
  const std::vector<CaseSelection> cases = solutions::select_cases(model);
  std::size_t b = cases.size();
  for (std::size_t k = 0; k < cases.size() && b == cases.size(); ++k)
    if (cases[k].method) b = k;
  if (b == cases.size())
    throw InputError((model.files.empty() ? std::string("deck") : model.files.front()) +
                     ": no subcase selects METHOD: buckling (SOL 105) needs a subcase with METHOD = the SID of an "
                     "EIGRL card (the load factors to find), after the static preload subcase with LOAD");
  const CaseSelection& buckle = cases[b];
  if (const auto id = statsub(model, buckle)) {
    for (const CaseSelection& c : cases)
      if (c.subcase_id == *id && c.subcase_id != buckle.subcase_id) {
        if (!c.load)
          throw InputError(
              fem::where(model, c.ref),
              solutions::case_name(c) + " is the preload of the buckling subcase (STATSUB) but selects no LOAD");
        return {c, buckle};
      }
    throw InputError(fem::where(model, buckle.ref), solutions::case_name(buckle) + ": STATSUB = " +
                                                        std::to_string(*id) + " names no other subcase of the deck");
  }
  for (std::size_t k = 0; k < b; ++k)
    if (cases[k].load) return {cases[k], buckle};
  if (buckle.load) return {buckle, buckle};  // one case with both LOAD and METHOD
  throw InputError(fem::where(model, buckle.ref),
                   solutions::case_name(buckle) + " selects METHOD = " + std::to_string(*buckle.method) +
                       " but no subcase before it selects a LOAD: buckling (SOL 105) needs a static preload subcase "
                       "(SUBCASE 1 with LOAD and SPC) before the METHOD subcase");
}

std::vector<CaseSelection> buckling_case_list(const fem::Model& model) {
  const auto [preload, buckle] = buckling_cases(model);
  std::vector<CaseSelection> cases = {preload};
  if (buckle.subcase_id != preload.subcase_id) cases.push_back(buckle);
  return cases;
}

BucklingSolution solve_buckling(const fem::Model& model, const BucklingOptions& options) {
  BucklingSolution s;
  std::tie(s.preload, s.buckling) = buckling_cases(model);
  const CaseSelection& bc = s.buckling;
  require_usable(model, check_card_usage(model, Solution::Buckling, buckling_case_list(model), kInterfaceNone,
                                         options.ignore_unknown_cards));

  // The EIGRL or EIGB of METHOD (check_card_usage has refused undefined methods).
  const fem::EigenMethod* method = nullptr;
  for (const fem::EigenMethod& e : model.eigen_methods)
    if (e.sid == *bc.method) method = &e;
  if (!method)
    throw InputError(fem::where(model, bc.ref),
                     solutions::case_name(bc) + ": METHOD = " + std::to_string(*bc.method) + " selects no EIGRL or EIGB card");
  if (method->is_eigr)
    throw InputError(fem::where(model, method->ref),
                     "EIGR " + std::to_string(method->sid) +
                         " is selected by METHOD of the buckling subcase; seflex finds buckling load factors with "
                         "EIGRL (ND, V1, V2) or EIGB (L1, L2, NEP, NDP)");
  linalg::EigenOptions eo;
  eo.backend = options.backend;
  eo.count = options.count ? options.count : method->nd;
  if (!eo.count && !method->f2)
    throw InputError(fem::where(model, method->ref),
                     "EIGRL " + std::to_string(method->sid) + ": give ND (number of load factors) or V2 (the largest)");

  // Preload statics.
  solutions::StaticOptions so;
  so.subcase = s.preload.subcase_id ? std::optional<int>(s.preload.subcase_id) : std::nullopt;
  so.ignore_unknown_cards = options.ignore_unknown_cards;
  const solutions::StaticSolution pre = solutions::solve_static(model, so);
  s.u_preload_g = pre.u_g;
  s.dofs = pre.dofs;

  // K and K_sigma on the buckling subcase's f-set.
  const fem::GlobalMatrices g = fem::assemble(model, fem::assembly_options(model));
  fem::ConstraintOptions co;
  co.spc_set = bc.spc;
  co.mpc_set = bc.mpc;
  co.autospc = fem::autospc_enabled(model);
  const fem::ConstrainedSystem c = fem::apply_constraints(model, g, co);
  require_free_dofs(model, g, c, Solution::Buckling);
  s.n_free = c.n_free();
  const Eigen::SparseMatrix<double> Kg = fem::assemble_geometric_stiffness(model, g.dofs, pre.u_g);
  const Eigen::SparseMatrix<double> Tt = c.T.transpose();
  Eigen::SparseMatrix<double> Kg_ff = Tt * Kg * c.T;
  Kg_ff = 0.5 * (Kg_ff + Eigen::SparseMatrix<double>(Kg_ff.transpose()));
  Kg_ff.prune(0.0, 0.0);
  const Eigen::SparseMatrix<double>& K = c.K_ff;
  const double kmax = K.diagonal().cwiseAbs().maxCoeff();
  double gmax = 0;
  for (int k = 0; k < Kg_ff.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(Kg_ff, k); it; ++it) gmax = std::max(gmax, std::abs(it.value()));
  if (!(gmax > 0.0))
    throw InputError(fem::where(model, s.preload.ref),
                     solutions::case_name(s.preload) +
                         " (the preload) stresses no CBAR, CBEAM, CROD, CONROD, CQUAD4 or CTRIA3: the differential "
                         "stiffness is zero and nothing can buckle");

  // alpha: B = K - alpha K_sigma positive definite (see the header).
  double alpha = std::numeric_limits<double>::infinity(), alpha_neg = alpha;
  for (Eigen::Index i = 0; i < K.rows(); ++i) {
    const double kg = Kg_ff.coeff(i, i), k = K.coeff(i, i);
    if (kg > 1e-14 * gmax) alpha = std::min(alpha, k / kg);
    if (kg < -1e-14 * gmax) alpha_neg = std::min(alpha_neg, k / -kg);
  }
  if (!std::isfinite(alpha)) alpha = std::isfinite(alpha_neg) ? alpha_neg : kmax / gmax;
  alpha *= 0.5;
  Eigen::SparseMatrix<double> B;
  for (int attempt = 0;; ++attempt) {
    B = K - alpha * Kg_ff;
    Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt(B);
    if (llt.info() == Eigen::Success) break;
    if (attempt == 30)
      throw ConvergenceError("buckling: K - alpha K_sigma is not positive definite for any alpha tried down to " +
                             std::to_string(alpha) + " (is K itself singular?)");
    alpha /= 10.0;
  }
  s.alpha = alpha;
  auto mu_of = [&](double lambda) { return lambda / (lambda + alpha); };
  if (method->f1 && *method->f1 > 0.0) eo.lambda_min = mu_of(*method->f1);
  if (method->f2) eo.lambda_max = *method->f2 > 0.0 ? mu_of(*method->f2) : 0.0;
  const linalg::EigenSolution es = linalg::solve_eigenproblem(K, B, eo);
  s.stats = es.stats;

  std::vector<std::pair<double, Eigen::VectorXd>> modes;
  for (Eigen::Index k = 0; k < es.eigenvalues.size(); ++k) {
    if (!(es.eigenvalues(k) < 1.0 - 1e-9)) continue;  // lambda = inf (unloaded) or negative
    const Eigen::VectorXd x = es.vectors.col(k);
    const double xKx = x.dot(K * x), xGx = x.dot(Kg_ff * x);
    if (!(xGx < 0.0)) continue;
    const double lambda = -xKx / xGx;
    if (method->f1 && lambda < *method->f1) continue;
    if (method->f2 && lambda > *method->f2) continue;
    modes.emplace_back(lambda, x);
  }
  std::sort(modes.begin(), modes.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  const Eigen::Index m = static_cast<Eigen::Index>(modes.size());
  const std::optional<Eigen::Index> point_dof =
      method->norm == "POINT" ? fem::find_dof(model, g.dofs, method->norm_grid, method->norm_component) : std::nullopt;
  s.load_factors.resize(m);
  s.shapes_g.resize(g.dofs.size(), m);
  s.generalized_stiffness.resize(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    s.load_factors(k) = modes[k].first;
    Eigen::VectorXd phi = c.T * modes[k].second;
    Eigen::Index imax = 0;
    phi.cwiseAbs().maxCoeff(&imax);
    // NORM = POINT (EIGB, EIGR): 1 at that dof, where the shape moves it; otherwise MAX
    if (point_dof && phi(*point_dof) != 0.0) imax = *point_dof;
    const double scale = phi(imax);
    phi /= scale;
    s.shapes_g.col(k) = phi;
    const Eigen::VectorXd xf = modes[k].second / scale;
    s.generalized_stiffness(k) = xf.dot(K * xf);
  }
  return s;
}

}  // namespace seflex::solutions
