// Lie-group generalized-alpha integration with Newton, step-size control and lock-event location.
#include "seflex/mbd/solvers/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "solvers/condensed_lu.hpp"
#include "solvers/diagnosis.hpp"
#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/assembly/assembly.hpp"
#include "solvers/step_control.hpp"

namespace seflex::mbd {

using Eigen::VectorXd;

namespace {

using Coefficients = detail::AlphaCoefficients;
using detail::StepResult;

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
  follow_leaders(model, s1);
  for (const auto& b : model.flexible_bodies) {
    const int m = model.superelement(b.se).m;
    if (m > 0) s1.eta.segment(b.eta_offset, m) = s0.eta.segment(b.eta_offset, m) + hDq.segment(b.eta_dof, m);
  }
  s1.a = (hDq / h - s0.v - h * (0.5 - c.beta) * s0.a) / (c.beta * h);
  s1.v = s0.v + h * (1.0 - c.gamma) * s0.a + h * c.gamma * s1.a;
  s1.vdot = ((1.0 - c.am) * s1.a + c.am * s0.a - c.af * s0.vdot) / (1.0 - c.af);
}

/// Storage of one Newton solve, sized at the first step and reused (no allocation per step).
struct NewtonScratch {
  VectorXd a1, hDq, d;
  std::vector<Eigen::Matrix3d> Jl;
  Eigen::SparseMatrix<double> S;
  detail::CondensedLu lu;  // modal dofs condensed (used while the retained dofs fit a dense LU)
  bool condensed = false;
};

StepResult newton_step(const Model& model, const State& s0, double h, const Coefficients& c,
                       const IntegratorSettings& st, Data& data, State& s1, detail::NewtonRate& rate,
                       const VectorXd& vdot1_predicted, NewtonScratch& ws) {
  StepResult out;
  rate.start_step();
  // Iteration error admitted: a fraction of the local error tolerance (weighted like the increment).
  // Residual and increment tests only with a constant step (the tolerance controls nothing there)
  // and with rho_inf = 1 (no numerical damping: iteration errors accumulate in the energy; the
  // energy-conservation test T11 drifts by 1.2 % instead of 0.02 % with the contraction test).
  const bool use_rate = st.adaptive && st.rho_inf < 1.0;
  const double rate_bound = use_rate ? st.newton_error_fraction * std::min(st.tol_position, st.tol_angle) : 0.0;
  bool rate_converged = false;
  s1 = s0;
  // Predictor: vdot_{n+1} as predicted by the caller, a_{n+1} from (1 - alpha_m) a_{n+1} + alpha_m a_n =
  // (1 - alpha_f) vdot_{n+1} + alpha_f vdot_n.
  VectorXd& a1 = ws.a1;
  VectorXd& hDq = ws.hDq;
  a1 = ((1.0 - c.af) * vdot1_predicted + c.af * s0.vdot - c.am * s0.a) / (1.0 - c.am);
  hDq = h * s0.v + h * h * (0.5 - c.beta) * s0.a + h * h * c.beta * a1;
  const double bp = (1.0 - c.am) / ((1.0 - c.af) * c.beta * h * h);
  const double gp = c.gamma / (c.beta * h);
  std::vector<Eigen::Matrix3d>& Jl = ws.Jl;
  Jl.resize(model.rotation_dof_starts.size());
  Eigen::SparseMatrix<double>& S = ws.S;
  AssemblyOptions opt;
  opt.inertia_velocity_tangent = st.inertia_velocity_tangent;
  // The iteration matrix K T + gp C + bp M: the flexible bodies add their share in one pass. T (Jl)
  // belongs to the iterate's rotation increments and is set before each assembly with matrices.
  const IterationMatrix iteration{1.0, gp, bp, &Jl};
  opt.iteration = &iteration;
  auto set_rotation_jacobians = [&] {
    for (std::size_t r = 0; r < Jl.size(); ++r) Jl[r] = so3::jl(hDq.segment<3>(model.rotation_dof_starts[r]));
  };
  double inc = std::numeric_limits<double>::infinity();
  double r_prev = std::numeric_limits<double>::infinity();
  bool fresh = false;  // the factorisation belongs to this step
  if (model.num_dofs == 0) {
    // Fully prescribed motion (e.g. a rigid body on a driven hinge): the configuration is the
    // drives' at t0 + h; assembling evaluates it and the drive torques (inverse dynamics).
    configure(model, s0, c, h, hDq, s1);
    opt.matrices = false;
    assemble(model, s1, data, opt);
    out.converged = true;
    return out;
  }
  for (int it = 0; it <= st.newton_max_iterations; ++it) {
    configure(model, s0, c, h, hDq, s1);
    // Modified Newton: keep the iteration matrix while the residual falls fast enough.
    opt.matrices = !fresh || !st.reuse_iteration_matrix;
    if (opt.matrices) set_rotation_jacobians();
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
    if ((out.residual <= tol && inc <= st.newton_increment_tol) || rate_converged) {
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
      set_rotation_jacobians();
      try {
        assemble(model, s1, data, opt);
      } catch (const ConvergenceError& e) {
        out.why = e.what();
        return out;
      }
    }
    r_prev = out.residual;
    if (opt.matrices) {
      combine_matrices(model, data, iteration.cK, iteration.cC, iteration.cM, iteration.rotation_jacobians, S);
      ws.condensed = ws.lu.applicable(model, S, Data::kDenseDofs);
      if (!(ws.condensed ? ws.lu.factorize(model, S) : data.factorize(S))) {
        out.why = "the iteration matrix is singular (" + detail::describe_singular(model, S) + ")";
        return out;
      }
      fresh = true;
      ++out.factorizations;
    }
    VectorXd& d = ws.d;
    if (ws.condensed)
      ws.lu.solve_negated(data.residual, d);
    else
      data.solve_negated(data.residual, d);
    inc = detail::weighted_norm(d, model.dof_weight);
    rate_converged = rate_bound > 0.0 && rate.converged(inc, rate_bound);
    if (!std::isfinite(inc)) {
      out.why = "the Newton increment is not finite";
      return out;
    }
    hDq += d;
    // Keep the frames as warm start.
    for (std::size_t b = 0; b < model.flexible_bodies.size(); ++b) s1.frames[b] = data.flex[b].kin.frame;
    if (rate_converged) {
      // Converged on the contraction of the corrections: the corrected iterate is the solution; no
      // evaluation there (it would change nothing but `data`, SUNDIALS IDA does the same). The node
      // and hinge kinematics are brought to it (node poses and hinge rates of the accepted state);
      // the bodies and force elements are evaluated when a sample needs them (AicStepper::sample).
      configure(model, s0, c, h, hDq, s1);
      update_kinematics(model, s1, data, true);
      out.iterations = it + 1;
      out.converged = true;
      out.evaluated = false;
      return out;
    }
  }
  out.why = "no convergence in " + std::to_string(st.newton_max_iterations) + " Newton iterations";
  return out;
}

/// The AIC formulation as seen by the step driver.
class AicStepper final : public detail::Stepper {
 public:
  AicStepper(const Model& model, State& state, Data& data, const IntegratorSettings& st)
      : model_(model), state_(state), data_(data), st_(st), c_(st.rho_inf), trial_(state),
        error_weights_(detail::error_weights(model, st)), vdot_prev_(state.vdot), vdot_predicted_(state.vdot) {
    for (const Hinge& h : model.hinges) has_drives_ = has_drives_ || static_cast<bool>(h.drive);
  }
  double time() const override { return state_.t; }
  StepResult attempt(double h) override {
    // Predicted vdot_{n+1}: extrapolated linearly from the last two accepted steps (the ratio of
    // the steps capped at 2); constant at the first step. Only Newton's starting point: the
    // converged step depends on it within the Newton tolerance only.
    if (h_prev_ > 0.0)
      vdot_predicted_ = state_.vdot + std::min(h / h_prev_, 2.0) * (state_.vdot - vdot_prev_);  // same size: no allocation
    else
      vdot_predicted_ = state_.vdot;
    at_state_ = Evaluated::None;  // data_ now belongs to the trial
    StepResult r = newton_step(model_, state_, h, c_, st_, data_, trial_, rate_, vdot_predicted_, newton_);
    last_evaluated_ = r.evaluated;
    return r;
  }
  double error_estimate(double h) const override {
    dvdot_ = trial_.vdot - state_.vdot;
    const double err = detail::wrms_error(dvdot_, error_weights_, h, c_);
    if (dvdot_.size() > 0) {  // its largest term, for the diagnosis of a failure (describe_residual)
      Eigen::Index i = 0;
      dvdot_.cwiseAbs().cwiseProduct(error_weights_).maxCoeff(&i);
      trial_error_ = {static_cast<int>(i), dvdot_[i]};
    }
    return err;
  }
  double hinge_angle(int hinge, bool trial) const override { return (trial ? trial_ : state_).phi[hinge]; }
  double hinge_rate(int hinge, bool trial) const override {
    const int dof = model_.hinges[static_cast<std::size_t>(hinge)].dof;
    return dof >= 0 ? (trial ? trial_ : state_).v[dof] : data_.hinges[static_cast<std::size_t>(hinge)].phidot;
  }
  std::vector<LockState>& locks() override { return state_.locks; }
  void accept() override {
    sawtooth_.accepted(trial_error_);
    vdot_prev_ = state_.vdot;
    h_prev_ = trial_.t - state_.t;
    state_ = trial_;
    at_state_ = last_evaluated_ ? Evaluated::Full : Evaluated::None;
    store_derived(model_, data_, state_);
  }
  void sample(Sample& out) override {
    // A sample reads energies, frames and force elements, not the residual: the light evaluation
    // (AssemblyOptions::energies_only) unless a driven hinge's sample needs its joint torque.
    if (at_state_ == Evaluated::None) {
      AssemblyOptions opt{false, true, 1.0};
      opt.energies_only = !has_drives_;
      assemble(model_, state_, data_, opt);
      at_state_ = opt.energies_only ? Evaluated::Light : Evaluated::Full;
    }
    make_sample(model_, state_, data_, out);
  }
  /// `data` evaluated at the accepted state (the last Newton iterate may have skipped it).
  void evaluate_current() {
    if (at_state_ == Evaluated::Full) return;
    assemble(model_, state_, data_, AssemblyOptions{false, true, 1.0});
    at_state_ = Evaluated::Full;
  }
  void prepare_failure_sample() override {
    evaluate_current();  // the failed attempt left data_ at a trial state (attempt: Evaluated::None)
  }
  std::string describe_residual() const override {
    return detail::describe_residual(model_, data_) + sawtooth_.describe(model_, st_.rho_inf);
  }

 private:
  const Model& model_;
  State& state_;
  Data& data_;
  const IntegratorSettings& st_;
  Coefficients c_;
  State trial_;
  VectorXd error_weights_;   // per dof: weight / tolerance of the local error estimate
  detail::NewtonRate rate_;  // contraction rate of Newton, carried from step to step
  VectorXd vdot_prev_;       // vdot of the accepted state before the current one
  VectorXd vdot_predicted_;
  mutable VectorXd dvdot_;
  mutable detail::ErrorTerm trial_error_;  // the largest term of the last attempt's error estimate
  detail::SawtoothWatch sawtooth_;         // ... and whether it alternates in sign over the accepted steps
  NewtonScratch newton_;
  double h_prev_ = 0.0;      // the last accepted step (0: none yet)
  // What data_ holds at state_: nothing (a trial's evaluation), a sample's energies_only evaluation,
  // or the full one (bodies and force elements; initial_accelerations leaves it).
  enum class Evaluated { None, Light, Full } at_state_ = Evaluated::Full;
  bool last_evaluated_ = true;  // the last attempt left data_ evaluated at trial_
  bool has_drives_ = false;       // some hinge is driven: samples need the full evaluation (joint torques)
};

}  // namespace

void initial_accelerations(const Model& model, State& s, Data& data) {
  s.vdot.setZero();
  AssemblyOptions opt;
  assemble(model, s, data, opt);
  Eigen::SparseMatrix<double> S;
  if (model.num_dofs > 0) {  // else: fully prescribed motion, no accelerations to solve for
    combine_matrices(model, data, 0.0, 0.0, 1.0, nullptr, S);
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
    lu.compute(S);
    if (lu.info() != Eigen::Success)
      throw ConvergenceError("the mass matrix at t = " + std::to_string(s.t) + " s is singular (" +
                             detail::describe_singular(model, S) + "): every dof needs mass");
    s.vdot = lu.solve(-data.residual);
  }
  s.a = s.vdot;
  for (std::size_t b = 0; b < model.flexible_bodies.size(); ++b) s.frames[b] = data.flex[b].kin.frame;
  assemble(model, s, data, AssemblyOptions{false, true, 1.0});
  store_derived(model, data, s);
}

const char* step_limit_name(StepLimit limit) {
  switch (limit) {
    case StepLimit::Initial: return "initial";
    case StepLimit::Error: return "error";
    case StepLimit::Growth: return "growth";
    case StepLimit::Newton: return "newton";
    case StepLimit::Kept: return "kept";
    case StepLimit::Largest: return "max_step";
    case StepLimit::Output: return "output";
    case StepLimit::Event: return "lock_crossing";
    case StepLimit::Retry: return "retry";
    case StepLimit::Fixed: return "fixed";
    case StepLimit::Count: break;
  }
  return "?";
}

RunStats simulate(const Model& model, State& state, Data& data, const IntegratorSettings& st, Observer* observer) {
  detail::validate_settings(st, state.t);
  initial_accelerations(model, state, data);
  AicStepper stepper(model, state, data, st);
  const RunStats stats = detail::drive_steps(model, st, stepper, observer);
  stepper.evaluate_current();  // the caller's `data` belongs to the final state
  return stats;
}

}  // namespace seflex::mbd
