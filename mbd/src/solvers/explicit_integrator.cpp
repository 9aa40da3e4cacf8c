// Runge-Kutta-Munthe-Kaas 4 with located lock crossings and blow-up detection (explicit_integrator.hpp).
#include "seflex/mbd/solvers/explicit_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "solvers/diagnosis.hpp"
#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/assembly/assembly.hpp"

namespace seflex::mbd {

using Eigen::VectorXd;

namespace {

/// True when some flexible body's force depends on the accelerations beyond the mass matrix: the
/// geometric stiffening's load factors are the frame's accelerations (docs/geometric-stiffening.md).
bool acceleration_dependent_stiffness(const Model& model) {
  for (const FlexibleBody& b : model.flexible_bodies)
    if (model.stiffened(b)) return true;
  return false;
}

/// Accelerations at `s`, from the guess in s.vdot (the step's start: the stage states copy it):
/// vdot = guess - M^-1 r(guess), exact when r is linear in vdot (r = M vdot + f); with stiffening f
/// depends on vdot through the load factors, and a second pass on the same factor takes them at the
/// first pass's accelerations (their weight is that of the stress stiffness against the mass).
/// Keeps the frames.
void accelerations(const Model& model, State& s, Data& data, Eigen::SparseMatrix<double>& M, long& factorizations) {
  if (!s.vdot.allFinite()) s.vdot.setZero();
  assemble(model, s, data, AssemblyOptions{});
  if (model.num_dofs == 0) return;  // fully prescribed motion: nothing to solve for
  combine_matrices(model, data, 0.0, 0.0, 1.0, nullptr, M);
  if (!data.factorize(M))
    throw ConvergenceError("the mass matrix at t = " + std::to_string(s.t) + " s is singular (" + detail::describe_singular(model, M) + ")");
  ++factorizations;
  VectorXd delta(model.num_dofs);
  data.solve_negated(data.residual, delta);
  s.vdot += delta;
  if (acceleration_dependent_stiffness(model)) {
    assemble(model, s, data, AssemblyOptions{false, true, 1.0});
    data.solve_negated(data.residual, delta);
    s.vdot += delta;
  }
  s.a = s.vdot;
  for (std::size_t b = 0; b < model.flexible_bodies.size(); ++b) s.frames[b] = data.flex[b].kin.frame;
}

/// u' = dexp_u^-1 v: J_l(u)^-1 omega for the rotations of Free nodes, v for the other dofs.
VectorXd increment_rate(const Model& model, const VectorXd& u, const VectorXd& v) {
  VectorXd du = v;
  for (const int r : model.rotation_dof_starts) du.segment<3>(r) = so3::jl_inv(u.segment<3>(r)) * v.segment<3>(r);
  return du;
}

/// x_0 (+) u at time t0 + dt with velocity v (a stage or the step's end).
void stage_state(const Model& model, const State& s0, const VectorXd& u, const VectorXd& v, double dt, State& s) {
  s = s0;
  s.t = s0.t + dt;
  apply_increment(model, s, u);
  s.v = v;
}

bool finite(const State& s) { return s.v.allFinite() && s.vdot.allFinite() && s.phi.allFinite() && s.eta.allFinite(); }

}  // namespace

RunStats simulate_rk4(const Model& model, State& state, Data& data, const IntegratorSettings& st, Observer* observer) {
  if (!(st.t_end > state.t)) throw InputError("integrator settings: end time must be after the start time");
  if (!(st.h_initial > 0.0) || !(st.h_min > 0.0)) throw InputError("integrator settings: steps must be > 0");
  if (!(st.output_interval >= 0.0) || !(st.event_tol > 0.0)) throw InputError("integrator settings: output interval >= 0, event tolerance > 0");
  RunStats stats;
  Eigen::SparseMatrix<double> M;
  accelerations(model, state, data, M, stats.factorizations);
  stats.factorizations = 0;
  auto emit = [&](bool event) {
    if (!observer) return;
    assemble(model, state, data, AssemblyOptions{false, true, 1.0});  // with the accelerations
    store_derived(model, data, state);
    Sample smp = make_sample(model, state, data);
    smp.step = stats.steps;
    smp.event = event;
    smp.step_size = stats.h_last;
    observer->on_sample(model, smp);
  };
  emit(false);
  auto fail = [&](double h, const std::string& why) {
    std::ostringstream os;
    os.precision(6);
    os << "explicit integration (rk4) stopped at t = " << state.t << " s (step " << stats.steps + 1 << ", h = " << h
       << " s): " << why << "; the step is probably above the stability limit of the explicit method";
    if (observer) {
      try {
        accelerations(model, state, data, M, stats.factorizations);
        emit(false);
      } catch (const Error&) {
      }
    }
    throw ConvergenceError(os.str());
  };
  const double eps = 1e-12 * std::max(1.0, std::abs(st.t_end));
  double next_out = st.output_interval > 0.0 ? state.t + st.output_interval : st.t_end;
  const int n = model.num_dofs;
  State s, trial;
  VectorXd du[4], dv[4];
  double h_event = 0.0;
  int event_retries = 0;
  while (state.t < st.t_end - eps) {
    double h = h_event > 0.0 ? h_event : st.h_initial;
    StepLimit limit = h_event > 0.0 ? StepLimit::Event : StepLimit::Fixed;
    bool hits_output = false;
    const double to_out = std::min(next_out, st.t_end) - state.t;
    if (h >= to_out * (1.0 - 1e-9)) {
      if (h > to_out * (1.0 + 1e-9)) limit = StepLimit::Output;  // shortened by more than round-off
      h = to_out;
      hits_output = true;
    }
    // state.vdot holds the accelerations at the step's start (first stage, shared with the last step).
    VectorXd u = VectorXd::Zero(n);
    VectorXd v = state.v;
    try {
      du[0] = state.v;
      dv[0] = state.vdot;
      const double c[3] = {0.5, 0.5, 1.0};
      for (int k = 1; k < 4; ++k) {
        u = c[k - 1] * h * du[k - 1];
        v = state.v + c[k - 1] * h * dv[k - 1];
        stage_state(model, state, u, v, c[k - 1] * h, s);
        accelerations(model, s, data, M, stats.factorizations);
        if (!finite(s)) fail(h, "the accelerations are not finite");
        du[k] = increment_rate(model, u, v);
        dv[k] = s.vdot;
      }
      u = h / 6.0 * (du[0] + 2.0 * du[1] + 2.0 * du[2] + du[3]);
      v = state.v + h / 6.0 * (dv[0] + 2.0 * dv[1] + 2.0 * dv[2] + dv[3]);
      if (!u.allFinite() || !v.allFinite()) fail(h, "the state is not finite");
      const double moved = (u.cwiseProduct(model.dof_weight)).lpNorm<Eigen::Infinity>();
      if (moved > M_PI) {
        std::ostringstream os;
        os << "a dof moved by " << moved << " (rad, or model length scales) in one step (blow-up)";
        fail(h, os.str());
      }
      stage_state(model, state, u, v, h, trial);
      accelerations(model, trial, data, M, stats.factorizations);
      if (!finite(trial)) fail(h, "the accelerations are not finite");
    } catch (const ConvergenceError& e) {
      if (std::string(e.what()).rfind("explicit integration", 0) == 0) throw;
      fail(h, e.what());
    }
    // Lock crossings: redo the step to end on the first one (linear interpolation of the angle).
    double theta = 1.0;
    bool crossing = false, land = false;
    for (std::size_t i = 0; i < model.force_elements.size(); ++i) {
      const auto* l = std::get_if<HingeLock>(&model.force_elements[i].element);
      if (!l || state.locks[i].latched) continue;
      const auto hi = static_cast<Eigen::Index>(l->hinge.value);
      const double side = state.locks[i].side;
      const double g0 = side * (state.phi[hi] - l->phi_lock), g1 = side * (trial.phi[hi] - l->phi_lock);
      if (g1 < -st.event_tol) continue;
      crossing = true;
      if (g1 <= st.event_tol) {
        land = true;
        continue;
      }
      theta = std::min(theta, g0 < 0.0 ? -g0 / (g1 - g0) : 0.0);
    }
    if (crossing && !land && event_retries < 30 && theta * h > st.h_min) {
      ++event_retries;
      ++stats.event_retries;
      h_event = std::min(theta * h, 0.99 * h);
      continue;
    }
    h_event = 0.0;
    event_retries = 0;
    state = trial;
    ++stats.steps;
    ++stats.steps_set_by[static_cast<std::size_t>(limit)];
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
    if (latched_now) accelerations(model, state, data, M, stats.factorizations);  // the lock acts from now on
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
  }
  return stats;
}

}  // namespace seflex::mbd
