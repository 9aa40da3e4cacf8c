// Quasi-static Newton with load stepping and cut-backs.
#include "seflex/mbd/solvers/statics.hpp"

#include <cmath>
#include <sstream>

#include "solvers/diagnosis.hpp"
#include "seflex/common/error.hpp"
#include "seflex/mbd/assembly/assembly.hpp"

namespace seflex::mbd {

namespace {

struct NewtonOutcome {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0, scale = 0.0;
  std::string why;
};

NewtonOutcome newton(const Model& model, State& s, Data& data, const StaticSettings& st, double lambda) {
  NewtonOutcome out;
  AssemblyOptions opt;
  opt.dynamics = false;
  opt.load_factor = lambda;
  Eigen::SparseMatrix<double> S;
  double inc = std::numeric_limits<double>::infinity();
  for (int it = 0; it <= st.max_iterations; ++it) {
    try {
      assemble(model, s, data, opt);
    } catch (const ConvergenceError& e) {
      out.why = e.what();
      return out;
    }
    out.residual = data.residual.norm();
    out.scale = data.scale.norm();
    out.iterations = it;
    if (!std::isfinite(out.residual)) {
      out.why = "the residual is not finite";
      return out;
    }
    if (out.residual <= st.residual_tol * out.scale + data.floor.norm() && inc <= st.increment_tol) {
      out.converged = true;
      return out;
    }
    if (it == st.max_iterations) break;
    combine_matrices(model, data, 1.0, 0.0, 0.0, nullptr, S);
    if (!data.factorize(S)) {
      out.why = "the tangent stiffness is singular (" + detail::describe_singular(model, S) + ")";
      return out;
    }
    Eigen::VectorXd dx;
    data.solve_negated(data.residual, dx);
    inc = detail::weighted_norm(dx, model.dof_weight);
    if (!std::isfinite(inc)) {
      out.why = "the Newton increment is not finite";
      return out;
    }
    apply_increment(model, s, dx);
    for (std::size_t b = 0; b < model.flexible_bodies.size(); ++b) s.frames[b] = data.flex[b].kin.frame;
  }
  out.why = "no convergence in " + std::to_string(st.max_iterations) + " iterations";
  return out;
}

}  // namespace

StaticStats solve_static(const Model& model, State& state, Data& data, const StaticSettings& st, Observer* observer) {
  if (st.load_steps < 1 || st.max_iterations < 1 || !(st.residual_tol > 0.0) || !(st.increment_tol > 0.0))
    throw InputError("static solver settings: load steps and iterations must be >= 1 and tolerances positive");
  StaticStats stats;
  double lambda = 0.0, dl = 1.0 / st.load_steps;
  long step = 0;
  while (lambda < 1.0 - 1e-12) {
    const double target = std::min(1.0, lambda + dl);
    State trial = state;
    const NewtonOutcome r = newton(model, trial, data, st, target);
    if (!r.converged) {
      if (stats.cutbacks >= st.max_cutbacks) {
        std::ostringstream os;
        os.precision(4);
        os << "static solution did not converge at load factor " << target << " (from " << lambda << ", after "
           << stats.cutbacks << " load cut-backs): " << r.why << "; residual norm " << r.residual << " (scale "
           << r.scale << ", tolerance " << st.residual_tol << "); largest residuals: " << detail::describe_residual(model, data);
        throw ConvergenceError(os.str());
      }
      ++stats.cutbacks;
      dl *= 0.5;
      continue;
    }
    state = trial;
    store_derived(model, data, state);
    lambda = target;
    stats.iterations.push_back(r.iterations);
    if (observer) {
      Sample smp = make_sample(model, state, data);
      smp.load_factor = lambda;
      smp.step = ++step;
      observer->on_sample(model, smp);
    }
  }
  return stats;
}

}  // namespace seflex::mbd
