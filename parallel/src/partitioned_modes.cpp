// Normal modes on a partitioned assembly (partitioned_modes.hpp).
#include "seflex/parallel/partitioned_modes.hpp"

#include <chrono>
#include <cmath>
#include <numbers>

#include "petsc_support.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/parallel/partitioned_system.hpp"
#include "seflex/parallel/slepc_eigensolver.hpp"
#include "seflex/solutions/card_usage.hpp"

namespace seflex::parallel {
namespace {

using solutions::ModeNormalization;

SourceRef deck(const fem::Model& model) { return SourceRef{model.files.empty() ? std::string() : model.files.front(), 0}; }

SourceRef card_source(const fem::Model& model, const fem::CardRef& ref) {
  return SourceRef{ref.file < model.files.size() ? model.files[ref.file] : std::string(), static_cast<int>(ref.line)};
}

double lambda_of_hz(double f) {
  const double w = 2 * std::numbers::pi * f;
  return std::copysign(w * w, f);
}

/// The eigenproblem options and normalisation the case control asks for (as solve_normal_modes).
linalg::EigenOptions eigen_options(const fem::Model& model, const solutions::ModesOptions& options,
                                      const solutions::CaseSelection& selection, const fem::EigenMethod*& method,
                                      ModeNormalization& norm) {
  method = nullptr;
  if (selection.method) {
    for (const fem::EigenMethod& m : model.eigen_methods)
      if (m.sid == *selection.method) method = &m;
    if (method == nullptr)
      throw InputError(deck(model), "case control METHOD = " + std::to_string(*selection.method) +
                                        ": no EIGRL or EIGR card has SID " + std::to_string(*selection.method));
  } else if (!options.count) {
    throw InputError(deck(model), "case control selects no METHOD (EIGRL/EIGR) for normal modes; add METHOD = <sid> "
                                  "or give the number of modes with --count");
  }
  linalg::EigenOptions eo;
  eo.count = options.count;
  norm = ModeNormalization::Mass;
  if (method == nullptr) return eo;
  const std::string card = std::string(method->is_eigr ? "EIGR " : "EIGRL ") + std::to_string(method->sid);
  if (!eo.count) eo.count = method->nd;
  if (method->f1) eo.lambda_min = lambda_of_hz(*method->f1);
  if (method->f2) eo.lambda_max = lambda_of_hz(*method->f2);
  if (!eo.count && !eo.lambda_max)
    throw InputError(card_source(model, method->ref),
                     card + ": neither ND (number of roots) nor F2 (upper frequency) is given, so nothing bounds the "
                            "number of modes; set one of them or use --count");
  if (method->norm == "MAX") norm = ModeNormalization::Max;
  else if (method->norm == "POINT") norm = ModeNormalization::Point;
  else if (method->norm == "MASS" || method->norm.empty()) norm = ModeNormalization::Mass;
  else throw InputError(card_source(model, method->ref), card + ": NORM '" + method->norm + "' is not MASS, MAX or POINT");
  return eo;
}

/// Scale factor of each mode (f-set vectors) as `norm` asks (solve_normal_modes' rule).
Eigen::VectorXd normalisation(const fem::Model& model, const PartitionedSystem& s, const fem::EigenMethod* method,
                              ModeNormalization norm, const Eigen::MatrixXd& phi_f) {
  std::optional<Eigen::Index> point_f;
  if (norm == ModeNormalization::Point)
    if (const auto g = fem::find_dof(model, s.dofs, method->norm_grid, method->norm_component))
      for (Eigen::Index f = 0; f < s.n_free(); ++f)
        if (s.f_to_g[static_cast<std::size_t>(f)] == *g) point_f = f;
  Eigen::VectorXd scale = Eigen::VectorXd::Ones(phi_f.cols());
  for (Eigen::Index j = 0; j < phi_f.cols(); ++j) {
    double largest = 0;
    for (Eigen::Index f = 0; f < phi_f.rows(); ++f)
      if (std::abs(phi_f(f, j)) > std::abs(largest)) largest = phi_f(f, j);
    if (norm == ModeNormalization::Mass) scale(j) = largest < 0 ? -1.0 : 1.0;
    else if (norm == ModeNormalization::Point && point_f && std::abs(phi_f(*point_f, j)) > 1e-10 * std::abs(largest))
      scale(j) = 1.0 / phi_f(*point_f, j);
    else if (largest != 0) scale(j) = 1.0 / largest;
  }
  return scale;
}

/// diag(Phi^T A Phi) for the distributed A of `s` (Phi: f-set rows, on every rank).
Eigen::VectorXd quadratic_forms(Mat A, const PartitionedSystem& s, const Eigen::MatrixXd& phi_f) {
  detail::OwnedVec x, y;
  SEFLEX_PETSC(MatCreateVecs(A, x.out(), y.out()));
  PetscInt begin = 0, end = 0;
  SEFLEX_PETSC(VecGetOwnershipRange(x.get(), &begin, &end));
  Eigen::VectorXd q(phi_f.cols());
  for (Eigen::Index j = 0; j < phi_f.cols(); ++j) {
    PetscScalar* v = nullptr;
    SEFLEX_PETSC(VecGetArrayWrite(x.get(), &v));
    for (PetscInt p = begin; p < end; ++p) v[p - begin] = phi_f(s.p_to_f[static_cast<std::size_t>(p)], j);
    SEFLEX_PETSC(VecRestoreArrayWrite(x.get(), &v));
    SEFLEX_PETSC(MatMult(A, x.get(), y.get()));
    PetscScalar d = 0;
    SEFLEX_PETSC(VecDot(y.get(), x.get(), &d));
    q(j) = d;
  }
  return q;
}

}  // namespace

solutions::NormalModes solve_normal_modes_partitioned(fem::Model& model, const solutions::ModesOptions& options,
                                                      PartitionStats* stats) {
  using Clock = std::chrono::steady_clock;
  solutions::NormalModes r;
  r.selection = solutions::select_case(model, options.subcase);
  solutions::require_usable(model, solutions::check_card_usage(model, solutions::Solution::NormalModes, {r.selection},
                                                               solutions::kInterfaceNone, options.ignore_unknown_cards));
  const fem::EigenMethod* method = nullptr;
  linalg::EigenOptions eo = eigen_options(model, options, r.selection, method, r.normalization);

  const auto t0 = Clock::now();
  fem::ConstraintOptions co;
  co.spc_set = r.selection.spc;
  co.mpc_set = r.selection.mpc;
  co.fixed_dofs = options.fixed_dofs;
  co.autospc = fem::autospc_enabled(model);
  const PartitionedSystem s = assemble_partitioned(model, co);
  if (stats != nullptr) {
    int rank = 0;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    stats->local_elements = s.local_elements;
    stats->total_elements = s.total_elements;
    stats->local_rows = static_cast<long>(s.row_begin[static_cast<std::size_t>(rank) + 1] - s.row_begin[static_cast<std::size_t>(rank)]);
    stats->total_rows = static_cast<long>(s.n_free());
    stats->seconds_assembly = std::chrono::duration<double>(Clock::now() - t0).count();
  }
  r.dofs = s.dofs;
  r.n_free = s.n_free();

  linalg::EigenSolution e;
  try {
    e = slepc_eigenproblem_partitioned(s, eo);
  } catch (const linalg::FactorizationError&) {
    throw InputError(deck(model), "normal modes: K - sigma M is singular: a motion of some dof has neither stiffness "
                                  "nor mass after the constraints (a massless mechanism or rigid-body motion; MUMPS "
                                  "does not say which dof); constrain it (SPC/SPC1, GRID PS), give it mass (CONM2, "
                                  "PARAM COUPMASS) or connect it");
  }
  r.stats = e.stats;
  r.eigenvalues = e.eigenvalues;
  const Eigen::VectorXd scale = normalisation(model, s, method, r.normalization, e.vectors);
  e.vectors *= scale.asDiagonal();
  r.shapes_g = Eigen::MatrixXd::Zero(s.dofs.size(), e.vectors.cols());
  for (Eigen::Index f = 0; f < s.n_free(); ++f) r.shapes_g.row(s.f_to_g[static_cast<std::size_t>(f)]) = e.vectors.row(f);
  r.generalized_mass = quadratic_forms(s.pencil().M.get(), s, e.vectors);
  r.generalized_stiffness = quadratic_forms(s.pencil().K.get(), s, e.vectors);
  return r;
}

}  // namespace seflex::parallel
