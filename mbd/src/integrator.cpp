// Lie-group generalized-alpha integration with Newton, step-size control and lock-event location.
#include "seflex/mbd/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "diagnosis.hpp"
#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/assembly.hpp"

namespace seflex::mbd {

using Eigen::VectorXd;

namespace {

struct Coefficients {
  double am, af, gamma, beta;
  explicit Coefficients(double rho) {
    am = (2.0 * rho - 1.0) / (rho + 1.0);
    af = rho / (rho + 1.0);
    gamma = 0.5 + af - am;
    beta = 0.25 * (gamma + 0.5) * (gamma + 0.5);
  }
};

struct StepResult {
  bool converged = false;
  int iterations = 0;
  int factorizations = 0;
  double residual = 0.0, scale = 0.0;
  std::string why;
};

/// Configuration and motion at t0 + h for the step increment hDq.
void configure(const Model& model, const State& s0, const Coefficients& c, double h, const VectorXd& hDq, State& s1) {
  s1.t = s0.t + h;
  for (std::size_t k = 0; k < model.nodes.size(); ++k) {
    const Node& n = model.nodes[k];
    if (n.kind != NodeKind::Free) continue;
    s1.p_WN[k] = s0.p_WN[k] + hDq.segment<3>(n.dof);
    s1.R_WN[k] = so3::exp(hDq.segment<3>(n.dof + 3)) * s0.R_WN[k];
  }
  for (std::size_t i = 0; i < model.hinges.size(); ++i)
    if (model.hinges[i].dof >= 0) s1.phi[static_cast<Eigen::Index>(i)] = s0.phi[static_cast<Eigen::Index>(i)] + hDq[model.hinges[i].dof];
  for (const auto& b : model.flexible_bodies) {
    const int m = model.superelement(b.se).m;
    if (m > 0) s1.eta.segment(b.eta_offset, m) = s0.eta.segment(b.eta_offset, m) + hDq.segment(b.eta_dof, m);
  }
  s1.a = (hDq / h - s0.v - h * (0.5 - c.beta) * s0.a) / (c.beta * h);
  s1.v = s0.v + h * (1.0 - c.gamma) * s0.a + h * c.gamma * s1.a;
  s1.vdot = ((1.0 - c.am) * s1.a + c.am * s0.a - c.af * s0.vdot) / (1.0 - c.af);
}

StepResult newton_step(const Model& model, const State& s0, double h, const Coefficients& c,
                       const IntegratorSettings& st, Data& data, State& s1) {
  StepResult out;
  s1 = s0;
  // Predictor: constant acceleration.
  const VectorXd a1 = (s0.vdot - c.am * s0.a) / (1.0 - c.am);
  VectorXd hDq = h * s0.v + h * h * (0.5 - c.beta) * s0.a + h * h * c.beta * a1;
  const double bp = (1.0 - c.am) / ((1.0 - c.af) * c.beta * h * h);
  const double gp = c.gamma / (c.beta * h);
  std::vector<Eigen::Matrix3d> Jl(model.rotation_dof_starts.size());
  Eigen::SparseMatrix<double> S;
  AssemblyOptions opt;
  double inc = std::numeric_limits<double>::infinity();
  double r_prev = std::numeric_limits<double>::infinity();
  bool fresh = false;  // the factorisation belongs to this step
  for (int it = 0; it <= st.newton_max_iterations; ++it) {
    configure(model, s0, c, h, hDq, s1);
    // Modified Newton: keep the iteration matrix while the residual falls fast enough.
    opt.matrices = !fresh || !st.reuse_iteration_matrix;
    try {
      assemble(model, s1, data, opt);
    } catch (const ConvergenceError& e) {
      out.why = e.what();
      return out;
    }
    out.iterations = it;
    out.residual = data.residual.norm();
    out.scale = data.scale.norm();
    if (!std::isfinite(out.residual)) {
      out.why = "the residual is not finite";
      return out;
    }
    const double tol = st.newton_residual_tol * out.scale + data.floor.norm();
    if (out.residual <= tol && inc <= st.newton_increment_tol) {
      out.converged = true;
      return out;
    }
    // Round-off floor: the correction no longer changes the iterate (tiny steps make the
    // accelerations (hDq/h - v)/(beta h) lose digits); accept a residual that is still small.
    if (inc <= 1e-15 && out.residual <= 1e4 * tol) {
      out.converged = true;
      return out;
    }
    if (it == st.newton_max_iterations) break;
    if (!opt.matrices && out.residual > 0.1 * r_prev) {
      // Slow: re-form the matrix at this iterate.
      opt.matrices = true;
      try {
        assemble(model, s1, data, opt);
      } catch (const ConvergenceError& e) {
        out.why = e.what();
        return out;
      }
    }
    r_prev = out.residual;
    if (opt.matrices) {
      for (std::size_t r = 0; r < Jl.size(); ++r) Jl[r] = so3::jl(hDq.segment<3>(model.rotation_dof_starts[r]));
      combine_matrices(model, data, 1.0, gp, bp, &Jl, S);
      if (!data.analyzed) {
        data.lu.analyzePattern(S);
        data.analyzed = true;
      }
      data.lu.factorize(S);
      if (data.lu.info() != Eigen::Success) {
        out.why = "the iteration matrix is singular (" + detail::describe_singular(model, S) + ")";
        return out;
      }
      fresh = true;
      ++out.factorizations;
    }
    const VectorXd d = data.lu.solve(-data.residual);
    inc = detail::weighted_norm(d, model.dof_weight);
    if (!std::isfinite(inc)) {
      out.why = "the Newton increment is not finite";
      return out;
    }
    hDq += d;
    // Keep the frames as warm start.
    for (std::size_t b = 0; b < model.flexible_bodies.size(); ++b) s1.frames[b] = data.flex[b].kin.frame;
  }
  out.why = "no convergence in " + std::to_string(st.newton_max_iterations) + " Newton iterations";
  return out;
}

double error_estimate(const Model& model, const State& s0, const State& s1, double h, const Coefficients& c,
                      const IntegratorSettings& st) {
  // Weighted RMS norm (as in SUNDIALS) of the local displacement error per dof.
  double sum = 0.0;
  const double k = h * h * std::abs(c.beta - 1.0 / 6.0);
  for (int i = 0; i < model.num_dofs; ++i) {
    const char kind = model.dof_kind[static_cast<std::size_t>(i)];
    const double tol = (kind == 't' || kind == 'e') ? st.tol_position : st.tol_angle;
    const double e = k * std::abs(s1.vdot[i] - s0.vdot[i]) * model.dof_weight[i] / tol;
    sum += e * e;
  }
  const double err = std::sqrt(sum / std::max(1, model.num_dofs));
  return std::isfinite(err) ? err : std::numeric_limits<double>::infinity();
}

/// Hermite-interpolated crossing of g(theta) = side (phi(theta) - phi_lock) = 0 on [0, 1].
double crossing_fraction(double p0, double d0, double p1, double d1, double h, double target, double side) {
  auto g = [&](double th) {
    const double t2 = th * th, t3 = t2 * th;
    const double phi = (2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + th) * h * d0 + (-2 * t3 + 3 * t2) * p1 + (t3 - t2) * h * d1;
    return side * (phi - target);
  };
  double lo = 0.0, hi = 1.0;
  if (g(lo) >= 0.0) return 0.0;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) >= 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

void validate(const IntegratorSettings& st, double t0) {
  auto bad = [](const std::string& what) { throw InputError("integrator settings: " + what); };
  if (!(st.t_end > t0)) bad("end time must be after the start time");
  if (!(st.h_initial > 0.0) || !(st.h_min > 0.0) || !(st.h_min <= st.h_initial)) bad("steps must satisfy 0 < h_min <= h_initial");
  if (!(st.h_max >= 0.0)) bad("h_max must be >= 0");
  if (!(st.rho_inf >= 0.0 && st.rho_inf <= 1.0)) bad("rho_inf must lie in [0, 1]");
  if (!(st.tol_position > 0.0) || !(st.tol_angle > 0.0)) bad("error tolerances must be positive");
  if (!(st.output_interval >= 0.0)) bad("output interval must be >= 0");
  if (st.newton_max_iterations < 1 || !(st.newton_residual_tol > 0.0) || !(st.newton_increment_tol > 0.0))
    bad("Newton iterations must be >= 1 and tolerances positive");
  if (!(st.event_tol > 0.0)) bad("event tolerance must be positive");
}

}  // namespace

void initial_accelerations(const Model& model, State& s, Data& data) {
  s.vdot.setZero();
  AssemblyOptions opt;
  assemble(model, s, data, opt);
  Eigen::SparseMatrix<double> S;
  combine_matrices(model, data, 0.0, 0.0, 1.0, nullptr, S);
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  lu.compute(S);
  if (lu.info() != Eigen::Success)
    throw ConvergenceError("the mass matrix at t = " + std::to_string(s.t) + " s is singular (" +
                           detail::describe_singular(model, S) + "): every dof needs mass");
  s.vdot = lu.solve(-data.residual);
  s.a = s.vdot;
  for (std::size_t b = 0; b < model.flexible_bodies.size(); ++b) s.frames[b] = data.flex[b].kin.frame;
  assemble(model, s, data, AssemblyOptions{false, true, 1.0});
  store_derived(model, data, s);
}

RunStats simulate(const Model& model, State& state, Data& data, const IntegratorSettings& st, Observer* observer) {
  validate(st, state.t);
  const Coefficients c(st.rho_inf);
  RunStats stats;
  initial_accelerations(model, state, data);
  long step = 0;
  auto emit = [&](bool event) {
    if (!observer) return;
    Sample smp = make_sample(model, state, data);
    smp.step = step;
    smp.event = event;
    smp.newton_iterations = stats.newton_iterations;
    smp.step_size = stats.h_last;
    observer->on_sample(model, smp);
  };
  emit(false);
  const double eps = 1e-12 * std::max(1.0, std::abs(st.t_end));
  double next_out = st.output_interval > 0.0 ? state.t + st.output_interval : st.t_end;
  double h_nat = st.h_initial;
  int event_retries = 0;
  bool just_rejected = false;  // the last attempt failed the error test: no growth on the next success
  double h_event = 0.0;  // > 0: the next attempt is an event retry with this step
  State trial;
  while (state.t < st.t_end - eps) {
    double h = h_event > 0.0 ? h_event : h_nat;
    if (st.h_max > 0.0) h = std::min(h, st.h_max);
    bool hits_output = false;
    const double to_out = std::min(next_out, st.t_end) - state.t;
    if (h >= to_out / 1.05) {  // stretch a little rather than leave a sliver
      h = to_out;
      hits_output = true;
    } else if (h > 0.5 * to_out) {
      h = 0.5 * to_out;
    }
    const StepResult r = newton_step(model, state, h, c, st, data, trial);
    if (!r.converged) {
      ++stats.rejected_newton;
      h_event = 0.0;
      h_nat = h * 0.25;
      if (h_nat < st.h_min) {
        std::ostringstream os;
        os.precision(6);
        os << "time integration stopped at t = " << state.t << " s (step " << step + 1 << ", h = " << h
           << " s, minimum step " << st.h_min << " s reached): " << r.why;
        os.precision(3);
        os << "; residual norm " << r.residual << " (relative " << (r.scale > 0 ? r.residual / r.scale : r.residual)
           << ", tolerance " << st.newton_residual_tol << ") after " << r.iterations << " iterations; largest residuals: "
           << detail::describe_residual(model, data);
        // Deliver the last accepted state before reporting.
        if (observer) {
          try {
            assemble(model, state, data, AssemblyOptions{false, true, 1.0});
            emit(false);
          } catch (const Error&) {
          }
        }
        throw ConvergenceError(os.str());
      }
      continue;
    }
    const double err = st.adaptive ? error_estimate(model, state, trial, h, c, st) : 0.0;
    if (st.adaptive && err > 1.0 && h > st.h_min * 1.0001) {
      ++stats.rejected_error;
      just_rejected = true;
      h_event = 0.0;
      h_nat = std::max(st.h_min, h * std::clamp(0.9 * std::pow(err, -1.0 / 3.0), 0.2, 0.9));
      continue;
    }
    // Lock events.
    double theta = 1.0;
    bool crossing = false, land = false;
    for (std::size_t i = 0; i < model.force_elements.size(); ++i) {
      const auto* l = std::get_if<HingeLock>(&model.force_elements[i].element);
      if (!l || state.locks[i].latched) continue;
      const double side = state.locks[i].side;
      const auto hi = static_cast<Eigen::Index>(l->hinge.value);
      const double g1 = side * (trial.phi[hi] - l->phi_lock);
      if (g1 < -st.event_tol) continue;
      crossing = true;
      if (g1 <= st.event_tol) {
        land = true;
        continue;
      }
      const int dof = model.hinge(l->hinge).dof;
      const double d0 = dof >= 0 ? state.v[dof] : data.hinges[static_cast<std::size_t>(hi)].phidot;
      const double d1 = dof >= 0 ? trial.v[dof] : d0;
      theta = std::min(theta, crossing_fraction(state.phi[hi], d0, trial.phi[hi], d1, h, l->phi_lock, side));
    }
    if (crossing && !land && event_retries < 30 && theta * h > st.h_min) {
      ++stats.event_retries;
      ++event_retries;
      h_event = theta * h;
      if (h_event >= h) h_event = 0.5 * h;
      continue;
    }
    // Accept.
    const bool was_event_retry = h_event > 0.0;
    const bool after_rejection = just_rejected;
    just_rejected = false;
    h_event = 0.0;
    event_retries = 0;
    state = trial;
    store_derived(model, data, state);
    ++step;
    ++stats.steps;
    stats.newton_iterations += r.iterations;
    stats.factorizations += r.factorizations;
    stats.max_newton_iterations = std::max(stats.max_newton_iterations, r.iterations);
    stats.h_last = h;
    bool latched_now = false;
    for (std::size_t i = 0; i < model.force_elements.size(); ++i) {
      const auto* l = std::get_if<HingeLock>(&model.force_elements[i].element);
      if (!l || state.locks[i].latched) continue;
      if (state.locks[i].side * (state.phi[l->hinge.value] - l->phi_lock) >= -st.event_tol) {
        state.locks[i].latched = true;
        state.locks[i].t_latch = state.t;
        latched_now = true;
      }
    }
    if (latched_now) emit(true);
    if ((hits_output || st.output_interval <= 0.0) && !latched_now) emit(false);
    if (hits_output) next_out = st.output_interval > 0.0 ? next_out + st.output_interval : st.t_end;
    if (st.output_interval > 0.0)
      while (next_out <= state.t + eps) next_out += st.output_interval;
    if (observer) {
      observer->on_progress(state.t, st.t_end);
      if (observer->stop_requested()) {
        if (!(hits_output || st.output_interval <= 0.0) && !latched_now) emit(false);
        break;
      }
    }
    if (st.adaptive) {
      if (!was_event_retry && !hits_output) {
        const double f = err > 0.0 ? 0.9 * std::pow(err, -1.0 / 3.0) : 2.0;
        h_nat = h * std::clamp(f, 0.2, after_rejection ? 1.0 : 1.5);
      }
      h_nat = std::max(h_nat, st.h_min);
    } else {
      h_nat = st.h_initial;
    }
  }
  return stats;
}

}  // namespace seflex::mbd
