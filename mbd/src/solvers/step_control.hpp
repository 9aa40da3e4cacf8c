#pragma once
// Step-size control, output scheduling and lock-event location shared by the time integrators
// (internal). A formulation supplies its Newton step and state through the Stepper interface; the
// driver (drive_steps) owns the loop: error test, step growth and shrinkage, landing on output
// times, locating lock crossings by Hermite interpolation of the hinge angle, latching, samples.
#include <algorithm>
#include <string>
#include <vector>

#include "seflex/mbd/solvers/integrator.hpp"

namespace seflex::mbd::detail {

/// Generalized-alpha coefficients for a spectral radius at infinity rho (Chung-Hulbert values).
struct AlphaCoefficients {
  double am, af, gamma, beta;
  explicit AlphaCoefficients(double rho) {
    am = (2.0 * rho - 1.0) / (rho + 1.0);
    af = rho / (rho + 1.0);
    gamma = 0.5 + af - am;
    beta = 0.25 * (gamma + 0.5) * (gamma + 0.5);
  }
};

/// Outcome of one Newton solve of a step.
struct StepResult {
  bool converged = false;
  int iterations = 0;
  int factorizations = 0;
  double residual = 0.0, scale = 0.0;
  std::string why;
  /// The formulation's data hold the evaluation at the result (false: Newton stopped on the
  /// contraction of its corrections without evaluating the corrected iterate).
  bool evaluated = true;
  /// Not converged: the next attempt's step is h times this.
  double retry_factor = 0.25;
};

/// What the driver needs from a formulation. `current` is the last accepted state, `trial` the
/// result of the last attempt.
class Stepper {
 public:
  virtual ~Stepper() = default;
  virtual double time() const = 0;
  /// Newton solve of the step current -> trial of size h.
  virtual StepResult attempt(double h) = 0;
  /// Local error of the trial relative to the tolerances (WRMS; <= 1 accepts).
  virtual double error_estimate(double h) const = 0;
  virtual double hinge_angle(int hinge, bool trial) const = 0;
  virtual double hinge_rate(int hinge, bool trial) const = 0;
  /// Latch states of the current state (per force element).
  virtual std::vector<LockState>& locks() = 0;
  /// The trial becomes the current state.
  virtual void accept() = 0;
  /// The sample of the current state into `out`, its storage reused from the previous sample (the
  /// driver sets step, event, Newton count and step size).
  virtual void sample(Sample& out) = 0;
  /// Re-evaluate the current state after a failed attempt, before its sample (may throw Error).
  virtual void prepare_failure_sample() {}
  /// "largest residuals: ..." of the last failed attempt.
  virtual std::string describe_residual() const = 0;

  // A formulation may bring its own step-size rules and a continuous output (Radau IIA: radau5.cpp);
  // the defaults are those of the generalized-alpha integrators (local error ~ h^3).
  /// The next step after an accepted one of size h with error err (h was not cut to an event or
  /// landed on an output time, but may have been halved before one; h_wanted: the step the
  /// controller had asked for).
  virtual double step_after_accept(double h, double h_wanted, double err, bool after_rejection);
  /// What set the step the last step_after_accept returned (Error, Growth; radau5 also Newton, Kept).
  StepLimit accepted_limit() const { return accepted_limit_; }
  /// The next step after the error test rejected a step of size h with error err > 1.
  virtual double step_after_rejection(double h, double err);
  /// True when sample_at can sample any time of the last accepted step: steps then do not land on
  /// output times (only on t_end and on lock crossings).
  virtual bool dense_output() const { return false; }
  /// The sample at time t inside the last accepted step, from the continuous output.
  virtual void sample_at(double /*t*/, Sample& /*out*/) {}
  /// Fraction theta in (0, 1] of the trial step of size h at which side (phi(theta) - target) first
  /// reaches 0 (it is < 0 at the start). Default: the cubic Hermite interpolant of the hinge angle
  /// and rate at both ends, where it is >= 0 at the end. A formulation with a continuous output
  /// looks inside the step and returns a value >= 1 when the angle does not reach the target.
  virtual double crossing_fraction(int hinge, double target, double side, double h) const;
  /// A lock has just latched at the current state (its stiffness now acts).
  virtual void on_latch() {}

 protected:
  StepLimit accepted_limit_ = StepLimit::Error;
};

/// Root in [lo, hi] of a function g with g(lo) < 0 <= g(hi), by bisection to round-off (returns lo
/// if g(lo) >= 0).
template <class G>
double first_crossing(const G& g, double lo = 0.0, double hi = 1.0) {
  if (g(lo) >= 0.0) return lo;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) >= 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

/// Newton convergence from the contraction of the corrections (Hairer and Wanner, Solving ODEs II,
/// sec. IV.8; SUNDIALS IDA): after the k-th correction dx_k the iterate is about
/// eta |dx_k| from the solution, eta = theta / (1 - theta), theta = |dx_k| / |dx_{k-1}|. For k = 1
/// theta is the last rate measured (in an earlier step; at least `theta_floor`, and 1/2 before any
/// rate is known). The norm is the caller's (weighted: relative to the length scale, rad).
class NewtonRate {
 public:
  explicit NewtonRate(double theta_floor = 1e-3) : floor_(theta_floor) {}
  /// A new step: forget the corrections of the last one (its rate is kept).
  void start_step() {
    k_ = 0;
    prev_inc_ = 0.0;
  }
  /// Record the norm of the correction just applied; true when the estimated distance to the
  /// solution is at most `bound`. Corrections that do not shrink (theta >= 1) never converge.
  bool converged(double inc, double bound) {
    ++k_;
    if (k_ >= 2) theta_ = prev_inc_ > 0.0 ? inc / prev_inc_ : 0.0;
    prev_inc_ = inc;
    if (!(theta_ < 1.0)) return false;
    const double theta = std::max(theta_, floor_);
    return theta / (1.0 - theta) * inc <= bound;
  }
  /// Last measured contraction rate.
  double theta() const { return theta_; }

 private:
  double floor_;
  double theta_ = 0.5;
  double prev_inc_ = 0.0;
  int k_ = 0;
};

/// Per dof of the model: its weight (Model::dof_weight) over its local-error tolerance (tol_position for
/// translations and modes, tol_angle for rotations and hinge angles).
Eigen::VectorXd error_weights(const Model& model, const IntegratorSettings& settings);

/// Check the settings (InputError naming the setting).
void validate_settings(const IntegratorSettings& settings, double t0);

/// Local displacement error of a step, WRMS over the coordinates: h^2 |beta - 1/6| |dvdot_i| w_i.
/// `weight_over_tol`: weight of each coordinate divided by its tolerance.
double wrms_error(const Eigen::VectorXd& dvdot, const Eigen::VectorXd& weight_over_tol, double h, const AlphaCoefficients& c);

/// Integrate from stepper.time() to settings.t_end (the caller has set consistent accelerations);
/// ends early, after a final sample, when the observer asks to stop.
RunStats drive_steps(const Model& model, const IntegratorSettings& settings, Stepper& stepper, Observer* observer);

}  // namespace seflex::mbd::detail
