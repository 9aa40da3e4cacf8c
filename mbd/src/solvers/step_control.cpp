// The step driver shared by the integrators: error test and step-size control, output times,
// lock-event location (Hermite interpolation of the hinge angle, step redone to end there).
#include "solvers/step_control.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "seflex/common/error.hpp"

namespace seflex::mbd::detail {

double Stepper::crossing_fraction(int hinge, double target, double side, double h) const {
  // Cubic Hermite interpolant of the hinge angle on [0, 1] from the angles and rates at both ends.
  const double p0 = hinge_angle(hinge, false), d0 = hinge_rate(hinge, false);
  const double p1 = hinge_angle(hinge, true), d1 = hinge_rate(hinge, true);
  return first_crossing([&](double th) {
    const double t2 = th * th, t3 = t2 * th;
    const double phi = (2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + th) * h * d0 + (-2 * t3 + 3 * t2) * p1 + (t3 - t2) * h * d1;
    return side * (phi - target);
  });
}

double Stepper::step_after_accept(double h, double h_wanted, double err, bool after_rejection) {
  // The growth limit applies to the step the control asked for, not to one shortened to land on an
  // output time: otherwise a step halved before an output (h_wanted in (0.5, 0.95] of the interval)
  // could only grow to 0.75 of the interval, and the steps stayed at half the output interval
  // whatever the tolerance (sync-3d: 2.5 ms at a local error of 1e-2 as at 1e-5).
  const double f = err > 0.0 ? 0.9 * std::pow(err, -1.0 / 3.0) : 2.0;
  const double base = std::max(h, h_wanted);
  const double most = (after_rejection ? 1.0 : 1.5) * base;
  accepted_limit_ = h * f >= most ? StepLimit::Growth : StepLimit::Error;
  return std::clamp(h * f, 0.2 * h, most);
}

double Stepper::step_after_rejection(double h, double err) { return h * std::clamp(0.9 * std::pow(err, -1.0 / 3.0), 0.2, 0.9); }


Eigen::VectorXd error_weights(const Model& model, const IntegratorSettings& st) {
  Eigen::VectorXd w(model.num_dofs);
  for (int i = 0; i < model.num_dofs; ++i) {
    const char kind = model.dof_kind[static_cast<std::size_t>(i)];
    w[i] = model.dof_weight[i] / ((kind == 't' || kind == 'e') ? st.tol_position : st.tol_angle);
  }
  return w;
}

void validate_settings(const IntegratorSettings& st, double t0) {
  auto bad = [](const std::string& what) { throw InputError("integrator settings: " + what); };
  if (!(st.t_end > t0)) bad("end time must be after the start time");
  if (!(st.h_initial > 0.0) || !(st.h_min > 0.0) || !(st.h_min <= st.h_initial)) bad("steps must satisfy 0 < h_min <= h_initial");
  if (!(st.h_max >= 0.0)) bad("h_max must be >= 0");
  if (!(st.rho_inf >= 0.0 && st.rho_inf <= 1.0)) bad("rho_inf must lie in [0, 1]");
  if (!(st.tol_position > 0.0) || !(st.tol_angle > 0.0)) bad("error tolerances must be positive");
  if (!(st.output_interval >= 0.0)) bad("output interval must be >= 0");
  if (st.newton_max_iterations < 1 || !(st.newton_residual_tol > 0.0) || !(st.newton_increment_tol > 0.0))
    bad("Newton iterations must be >= 1 and tolerances positive");
  if (!(st.newton_error_fraction >= 0.0 && st.newton_error_fraction < 1.0)) bad("Newton error fraction must lie in [0, 1)");
  if (!(st.event_tol > 0.0)) bad("event tolerance must be positive");
  if (st.radau.newton_max_iterations < 2) bad("radau: Newton iterations must be >= 2");
  if (!(st.radau.newton_fraction >= 0.0 && st.radau.newton_fraction < 1.0)) bad("radau: Newton fraction must lie in [0, 1)");
  if (!(st.radau.jacobian_theta >= 0.0 && st.radau.jacobian_theta < 1.0)) bad("radau: Jacobian theta must lie in [0, 1)");
}

double wrms_error(const Eigen::VectorXd& dvdot, const Eigen::VectorXd& weight_over_tol, double h, const AlphaCoefficients& c) {
  // Weighted RMS norm (as in SUNDIALS) of the local displacement error per coordinate.
  const double k = h * h * std::abs(c.beta - 1.0 / 6.0);
  const auto n = dvdot.size();
  const double sum = (k * dvdot.cwiseAbs().cwiseProduct(weight_over_tol)).squaredNorm();
  const double err = std::sqrt(sum / static_cast<double>(std::max<Eigen::Index>(1, n)));
  return std::isfinite(err) ? err : std::numeric_limits<double>::infinity();
}

RunStats drive_steps(const Model& model, const IntegratorSettings& st, Stepper& stepper, Observer* observer) {
  RunStats stats;
  long step = 0;
  Sample smp;  // reused: no allocation per sample once filled
  auto deliver = [&](bool event) {
    smp.step = step;
    smp.event = event;
    smp.newton_iterations = stats.newton_iterations;
    smp.step_size = stats.h_last;
    observer->on_sample(model, smp);
  };
  auto emit = [&](bool event) {
    if (!observer) return;
    stepper.sample(smp);
    deliver(event);
  };
  emit(false);
  const double t0 = stepper.time();
  const double eps = 1e-12 * std::max(1.0, std::abs(st.t_end));
  // Steps land on output times unless the formulation interpolates its samples (dense output).
  const bool dense = stepper.dense_output() && st.output_interval > 0.0;
  double next_out = st.output_interval > 0.0 ? t0 + st.output_interval : st.t_end;
  double h_nat = st.h_initial;
  StepLimit nat_limit = st.adaptive ? StepLimit::Initial : StepLimit::Fixed;  // what set h_nat
  int event_retries = 0;
  bool just_rejected = false;  // the last attempt failed the error test: no growth on the next success
  double h_event = 0.0;        // > 0: the next attempt is an event retry with this step
  while (stepper.time() < st.t_end - eps) {
    const double t = stepper.time();
    double h = h_event > 0.0 ? h_event : h_nat;
    StepLimit limit = h_event > 0.0 ? StepLimit::Event : nat_limit;
    if (st.h_max > 0.0 && h > st.h_max) {
      h = st.h_max;
      limit = StepLimit::Largest;
    }
    const double h_wanted = h;  // before landing on the next output time
    bool hits_output = false;
    const double to_out = (dense ? st.t_end : std::min(next_out, st.t_end)) - t;
    const bool lands = h >= to_out / 1.05;
    // (The output schedule counts as what set the step only where it shortened it by more than
    // round-off: a 2.5 ms max_step landing on 5 ms outputs stays a max_step.)
    if (lands) {  // stretch a little rather than leave a sliver
      if (h > to_out * (1.0 + 1e-9)) limit = StepLimit::Output;
      h = to_out;
      hits_output = true;
    } else if (h > 0.5 * to_out) {
      if (h > 0.5 * to_out * (1.0 + 1e-9)) limit = StepLimit::Output;
      h = 0.5 * to_out;
    }
    const StepResult r = stepper.attempt(h);
    if (!r.converged) {
      ++stats.rejected_newton;
      h_event = 0.0;
      h_nat = h * r.retry_factor;
      nat_limit = StepLimit::Retry;
      if (h_nat < st.h_min) {
        std::ostringstream os;
        os.precision(6);
        os << "time integration stopped at t = " << t << " s (step " << step + 1 << ", h = " << h
           << " s, minimum step " << st.h_min << " s reached): " << r.why;
        os.precision(3);
        os << "; residual norm " << r.residual;
        if (r.scale > 0) os << " (relative " << r.residual / r.scale << ", tolerance " << st.newton_residual_tol << ")";
        os << " after " << r.iterations << " iterations; largest residuals: " << stepper.describe_residual();
        // Deliver the last accepted state before reporting.
        if (observer) {
          try {
            stepper.prepare_failure_sample();
            emit(false);
          } catch (const Error&) {
          }
        }
        throw ConvergenceError(os.str());
      }
      continue;
    }
    const double err = st.adaptive ? stepper.error_estimate(h) : 0.0;
    if (st.adaptive && err > 1.0 && h > st.h_min * 1.0001) {
      ++stats.rejected_error;
      just_rejected = true;
      h_event = 0.0;
      h_nat = std::max(st.h_min, stepper.step_after_rejection(h, err));
      nat_limit = StepLimit::Retry;
      continue;
    }
    // Lock events: a lock whose angle reaches phi_lock in the step (at its end, or inside it where the
    // formulation has a continuous output) makes the step end there.
    std::vector<LockState>& locks = stepper.locks();
    double theta = 1.0;
    bool crossing = false, land = false;
    for (std::size_t i = 0; i < model.force_elements.size(); ++i) {
      const auto* l = std::get_if<HingeLock>(&model.force_elements[i].element);
      if (!l || locks[i].latched) continue;
      const double side = locks[i].side;
      const int hi = l->hinge.value;
      const double g1 = side * (stepper.hinge_angle(hi, true) - l->phi_lock);
      if (g1 < -st.event_tol) {
        if (!dense) continue;
        const double th = stepper.crossing_fraction(hi, l->phi_lock, side, h);  // reached and left inside the step?
        if (th >= 1.0) continue;
        crossing = true;
        theta = std::min(theta, th);
        continue;
      }
      crossing = true;
      if (g1 <= st.event_tol) {
        land = true;
        continue;
      }
      theta = std::min(theta, stepper.crossing_fraction(hi, l->phi_lock, side, h));
    }
    if (crossing && !land && event_retries < 30) {
      if (theta * h > st.h_min) {
        ++stats.event_retries;
        ++event_retries;
        h_event = theta * h;
        if (h_event >= h) h_event = 0.5 * h;
        continue;
      }
      // The crossing is less than h_min ahead (the last step landed just short of it): the lock
      // latches at the current state, and the step is tried again with it.
      bool latched_here = false;
      for (std::size_t i = 0; i < model.force_elements.size(); ++i) {
        const auto* l = std::get_if<HingeLock>(&model.force_elements[i].element);
        if (!l || locks[i].latched) continue;
        const int hi = l->hinge.value;
        if (locks[i].side * (stepper.hinge_angle(hi, true) - l->phi_lock) > st.event_tol &&
            stepper.crossing_fraction(hi, l->phi_lock, locks[i].side, h) * h <= st.h_min) {
          locks[i].latched = true;
          locks[i].t_latch = t;
          latched_here = true;
        }
      }
      if (latched_here) {
        h_event = 0.0;
        stepper.on_latch();
        emit(true);
        continue;
      }
    }
    // Accept.
    const bool was_event_retry = h_event > 0.0;
    const bool after_rejection = just_rejected;
    just_rejected = false;
    h_event = 0.0;
    event_retries = 0;
    stepper.accept();
    ++step;
    ++stats.steps;
    ++stats.steps_set_by[static_cast<std::size_t>(limit)];
    stats.newton_iterations += r.iterations;
    stats.factorizations += r.factorizations;
    stats.max_newton_iterations = std::max(stats.max_newton_iterations, r.iterations);
    stats.h_last = h;
    // Samples inside the step, from the continuous output.
    if (dense) {
      for (; next_out < stepper.time() - eps; next_out += st.output_interval)
        if (observer) {
          stepper.sample_at(next_out, smp);
          deliver(false);
        }
      if (std::abs(next_out - stepper.time()) <= eps) hits_output = true;
    }
    bool latched_now = false;
    std::vector<LockState>& now = stepper.locks();
    for (std::size_t i = 0; i < model.force_elements.size(); ++i) {
      const auto* l = std::get_if<HingeLock>(&model.force_elements[i].element);
      if (!l || now[i].latched) continue;
      if (now[i].side * (stepper.hinge_angle(l->hinge.value, false) - l->phi_lock) >= -st.event_tol) {
        now[i].latched = true;
        now[i].t_latch = stepper.time();
        latched_now = true;
      }
    }
    if (latched_now) {
      stepper.on_latch();
      emit(true);
    }
    if ((hits_output || st.output_interval <= 0.0) && !latched_now) emit(false);
    if (hits_output) next_out = st.output_interval > 0.0 ? next_out + st.output_interval : st.t_end;
    if (st.output_interval > 0.0)
      while (next_out <= stepper.time() + eps) next_out += st.output_interval;
    if (observer) {
      observer->on_progress(stepper.time(), st.t_end);
      if (observer->stop_requested()) {
        if (!(hits_output || st.output_interval <= 0.0) && !latched_now) emit(false);
        break;
      }
    }
    if (st.adaptive) {
      // A step cut to an event or landed on an output time keeps the controller's step.
      if (!was_event_retry && !lands) {
        h_nat = stepper.step_after_accept(h, h_wanted, err, after_rejection);
        nat_limit = stepper.accepted_limit();
      }
      h_nat = std::max(h_nat, st.h_min);
    } else {
      h_nat = st.h_initial;
      nat_limit = StepLimit::Fixed;
    }
  }
  return stats;
}

}  // namespace seflex::mbd::detail
