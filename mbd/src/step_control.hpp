#pragma once
// Step-size control, output scheduling and lock-event location shared by the time integrators
// (internal). A formulation supplies its Newton step and state through the Stepper interface; the
// driver (drive_steps) owns the loop: error test, step growth and shrinkage, landing on output
// times, locating lock crossings by Hermite interpolation of the hinge angle, latching, samples.
#include <string>
#include <vector>

#include "seflex/mbd/integrator.hpp"

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
  /// A sample of the current state (the driver sets step, event, Newton count and step size).
  virtual Sample sample() = 0;
  /// Re-evaluate the current state after a failed attempt, before its sample (may throw Error).
  virtual void prepare_failure_sample() {}
  /// "largest residuals: ..." of the last failed attempt.
  virtual std::string describe_residual() const = 0;
};

/// Check the settings (InputError naming the setting).
void validate_settings(const IntegratorSettings& settings, double t0);

/// Local displacement error of a step, WRMS over the coordinates: h^2 |beta - 1/6| |dvdot_i| w_i.
/// `weight_over_tol`: weight of each coordinate divided by its tolerance.
double wrms_error(const Eigen::VectorXd& dvdot, const Eigen::VectorXd& weight_over_tol, double h, const AlphaCoefficients& c);

/// Integrate from stepper.time() to settings.t_end (the caller has set consistent accelerations);
/// ends early, after a final sample, when the observer asks to stop.
RunStats drive_steps(const Model& model, const IntegratorSettings& settings, Stepper& stepper, Observer* observer);

}  // namespace seflex::mbd::detail
