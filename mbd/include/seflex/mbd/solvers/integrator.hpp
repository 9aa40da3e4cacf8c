#pragma once
// Implicit time integration: the Lie-group generalized-alpha method of Arnold and Bruls (2007) on
// R^3 x SO(3) per Free node (spatial form, R_{n+1} = exp(h Dq~) R_n) and on R for hinge angles and
// modal coordinates:
//   h Dq    = h v_n + h^2 (1/2 - beta) a_n + h^2 beta a_{n+1}
//   v_{n+1} = v_n + h (1 - gamma) a_n + h gamma a_{n+1}
//   (1 - alpha_m) a_{n+1} + alpha_m a_n = (1 - alpha_f) vdot_{n+1} + alpha_f vdot_n
//   r(q_{n+1}, v_{n+1}, vdot_{n+1}, t_{n+1}) = 0
// alpha_m = (2 rho - 1)/(rho + 1), alpha_f = rho/(rho + 1), gamma = 1/2 + alpha_f - alpha_m,
// beta = (gamma + 1/2)^2 / 4. Newton on h Dq with S = K J_l(h Dq) + gamma/(beta h) C + beta' M,
// beta' = (1 - alpha_m)/((1 - alpha_f) beta h^2), started from vdot_{n+1} extrapolated linearly from
// the last two steps. Newton has converged when the residual and the increment are below their
// tolerances, or when the distance to the solution estimated from the contraction of the
// corrections (Hairer-Wanner IV.8) is below a fraction of the local error tolerance; the matrix is
// kept over the iterations of a step while the residual falls by 10 per iteration.
// Step-size control from the local error estimate h^2 |beta - 1/6| |vdot_{n+1} - vdot_n|; lock
// crossings located by Hermite interpolation of the hinge angle and the step redone to end there.
#include <array>

#include "seflex/mbd/data.hpp"
#include "seflex/mbd/output.hpp"

namespace seflex::mbd {

struct IntegratorSettings {
  double t_end = 1.0;
  double h_initial = 1e-3;
  double h_min = 1e-10;
  double h_max = 0.0;             ///< 0: no limit (other than output times)
  bool adaptive = true;           ///< false: constant step h_initial (events still located)
  double rho_inf = 0.8;           ///< spectral radius at infinity, 0..1 (1: no numerical damping)
  double tol_position = 1e-6;     ///< local error per step, relative to the model's length scale
  double tol_angle = 1e-6;        ///< local error per step [rad]
  double output_interval = 0.0;   ///< 0: every accepted step
  int newton_max_iterations = 15;
  double newton_residual_tol = 1e-8;   ///< relative to the residual scale
  double newton_increment_tol = 1e-9;  ///< weighted (m / length scale, rad)
  /// Newton also stops when theta/(1 - theta) |dx| <= this fraction of the local error tolerance
  /// (theta: contraction rate of the weighted corrections dx; 0: residual and increment tests only).
  /// The iteration error then stays 1000x below what the step-size control admits per step.
  /// Used only when `adaptive` and rho_inf < 1 (a constant step or no numerical damping: off).
  double newton_error_fraction = 1e-3;
  bool reuse_iteration_matrix = true;  ///< modified Newton: re-form only when convergence is slow
  /// The iteration matrix holds the flexible bodies' gyroscopic/Coriolis tangent (the velocity
  /// derivative of the full inertia). It weighs about h |Omega| against the mass term and costs a
  /// third of a body's matrices. Without it Newton takes a few more iterations and, through other
  /// iterates and hence other adaptive steps, the results move at the level of the integration
  /// error, not of round-off (docs/benchmarks.md: 13 % less CPU on the demo; hinge angles moved by
  /// up to 0.03 deg in the lock ringing; as accurate against a tight reference). Keep it where
  /// h |Omega| is not small.
  bool inertia_velocity_tangent = true;
  double event_tol = 1e-9;        ///< located lock crossing: |phi - phi_lock| [rad]
  /// Radau IIA only (radau5.hpp): its simplified Newton iteration.
  struct Radau {
    int newton_max_iterations = 7;  ///< per step (Hairer and Wanner's NIT)
    /// Newton stops when its estimated distance to the solution, theta/(1 - theta) |dW| (weighted
    /// like the error estimate), is below this fraction of the local error tolerance. 0: a tenth of
    /// their rule, 0.1 min(0.03, sqrt(tol)) with tol the smaller of tol_position and tol_angle (their
    /// rule's remainder accumulated over the steps into most of the global error: radau5.cpp).
    double newton_fraction = 0.0;
    /// The Jacobian (K, C, M) is kept for the next step while Newton's contraction rate theta stays
    /// at most this (their THET; 0.001 re-forms it almost every step, 0.1 suits Jacobians that cost
    /// as much as several residuals, as here); a faster rate also keeps the step when the controller
    /// asks for 1 to 1.2 times it (no new factorisation).
    double jacobian_theta = 0.1;
  } radau;
};

/// What set the size of an accepted step (RunStats::steps_set_by): the answer to "would a looser
/// tolerance make this run cheaper?" (only for the steps the error estimate set).
enum class StepLimit : int {
  Initial,  ///< the first step (`step`)
  Error,    ///< the error estimate (the step-size controller)
  Growth,   ///< the controller's largest growth per step (or none after a rejection)
  Newton,   ///< radau5: the step may grow only while simplified Newton contracts fast enough
  Kept,     ///< radau5: kept at the last step's size to reuse its factorised iteration matrices
  Largest,  ///< `max_step`
  Output,   ///< landing on (or halved before) an output time or the end of the run
  Event,    ///< cut to end at a lock crossing
  Retry,    ///< cut after Newton failed or the error estimate rejected the step
  Fixed,    ///< the constant step of a run that is not adaptive
  Count
};
inline constexpr int kStepLimits = static_cast<int>(StepLimit::Count);
/// "error", "newton", ...: the key of each StepLimit in summary.json and summary.txt.
const char* step_limit_name(StepLimit limit);

struct RunStats {
  long steps = 0;              ///< accepted steps
  std::array<long, kStepLimits> steps_set_by{};  ///< accepted steps by what set their size
  long rejected_error = 0;     ///< steps rejected by the error estimate
  long rejected_newton = 0;    ///< steps retried because Newton failed
  long event_retries = 0;      ///< steps redone to land on a lock crossing
  long newton_iterations = 0;  ///< over accepted steps
  long factorizations = 0;     ///< iteration matrices formed and factorised, over accepted steps
  int max_newton_iterations = 0;
  double h_last = 0.0;
  long jacobians = 0;          ///< radau5: Jacobians (K, C, M) evaluated, over all attempts (else 0)
  long evaluations = 0;        ///< radau5: residual evaluations (3 per Newton iteration), over all attempts (else 0)
};

/// Integrate from state.t to settings.t_end. Starts by computing consistent accelerations.
/// Samples go to `observer` (may be null) at t0, every output time and every lock latch. On
/// failure (Newton not converging at h_min) the last accepted state is sent and a
/// ConvergenceError says when, where and why. Ends early (after a final sample) when the observer
/// asks to stop (Observer::stop_requested).
RunStats simulate(const Model& model, State& state, Data& data, const IntegratorSettings& settings,
                  Observer* observer = nullptr);

/// Consistent accelerations at `state` (vdot = a = -M^-1 r(vdot = 0)); leaves data assembled.
void initial_accelerations(const Model& model, State& state, Data& data);

}  // namespace seflex::mbd
