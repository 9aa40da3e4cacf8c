// Radau IIA-5 on the rotation group for the AIC formulation (radau5.hpp): stages, simplified Newton
// on one real and one complex system, error estimate, step-size control, dense output.
#include "seflex/mbd/solvers/radau5.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <sstream>

#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/assembly/assembly.hpp"
#include "solvers/condensed_lu.hpp"
#include "solvers/diagnosis.hpp"
#include "solvers/radau_tableau.hpp"
#include "solvers/step_control.hpp"

namespace seflex::mbd {

using Eigen::MatrixXd;
using Eigen::VectorXcd;
using Eigen::VectorXd;
using Complex = std::complex<double>;

namespace {

constexpr double kRoundoff = std::numeric_limits<double>::epsilon();
// Step-size control (Hairer and Wanner's values): safety factor, and the bounds of h_new / h.
constexpr double kSafe = 0.9, kMinRatio = 0.2, kMaxRatio = 8.0;
// The step is kept (no new factorisation) when the controller asks for 1 to 1.2 times it.
constexpr double kKeepLow = 1.0, kKeepHigh = 1.2;
// The step may grow until simplified Newton is predicted to contract at this rate (step_after_accept).
constexpr double kThetaTarget = 0.05;
// Newton stops at this share of Hairer and Wanner's distance to the solution, min(0.03, sqrt(tol)) of
// the local error tolerance. Their rule left a distance that accumulates over the steps: simplified
// Newton approaches the stage solution from the predictor's side, so what it leaves has one sign
// from step to step and dominated the global error. Measured on sync-3d (2026-12-07, largest step
// 50 ms, against Radau IIA-5 at local error 1e-9 with three more Newton iterations per step, which
// agrees with 1e-8 to 7e-10 s in the lock times): at local error 1e-4 their rule gave lock times
// 1.65e-4 s, peak lock torques 0.31 %, hinge angles 0.077 deg to the last lock and 0.17 deg over the
// whole run; three more iterations per step, from the same step sequence logic, 1.0e-5 s, 0.019 %,
// 0.012 and 0.026 deg. A tenth of their fraction: 1.8e-5 s, 0.018 %, 0.011 and 0.017 deg for 23 %
// more residual evaluations (8,577 against 6,978); at 1e-5, 1.0e-5 s, 0.002 %, 0.0045 and 0.010 deg
// against 2.1e-5 s, 0.018 %, 0.0081 and 0.017 deg for 18 % more.
constexpr double kNewtonShare = 0.1;
// Newton's too-slow test waits for a second ratio of increments while the iteration's later ratios
// have been this fast (newton): twice the rate the step control aims at.
constexpr double kSecondRatio = 2.0 * kThetaTarget;

/// One of the two transformed Newton systems: the modal dofs condensed while the retained dofs fit
/// a dense LU (condensed_lu.hpp), else a sparse LU.
template <class Scalar>
class StageSystem {
 public:
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  using Sparse = Eigen::SparseMatrix<Scalar>;
  bool factorize(const Model& model, const Sparse& S) {
    condensed_ = condensed_lu_.applicable(model, S, Data::kDenseDofs);
    if (condensed_) return condensed_lu_.factorize(model, S);
    if (!analyzed_) {
      sparse_lu_.analyzePattern(S);
      analyzed_ = true;
    }
    sparse_lu_.factorize(S);
    return sparse_lu_.info() == Eigen::Success;
  }
  /// x = -S^-1 r with the last factorisation.
  void solve_negated(const Vector& r, Vector& x) {
    if (condensed_) {
      condensed_lu_.solve_negated(r, x);
      return;
    }
    x = sparse_lu_.solve(r);
    x = -x;
  }

 private:
  detail::CondensedLuT<Scalar> condensed_lu_;
  Eigen::SparseLU<Sparse, Eigen::COLAMDOrdering<int>> sparse_lu_;
  bool condensed_ = false, analyzed_ = false;
};

/// The AIC formulation integrated by Radau IIA-5, as seen by the step driver.
class RadauStepper final : public detail::Stepper {
 public:
  RadauStepper(const Model& model, State& state, Data& data, const IntegratorSettings& st)
      : model_(model), state_(state), data_(data), st_(st), rk_(detail::radau_iia5()), w_(detail::error_weights(model, st)),
        n_(model.num_dofs), nit_(st.radau.newton_max_iterations) {
    for (const Hinge& h : model.hinges) has_drives_ = has_drives_ || static_cast<bool>(h.drive);
    const double tol = std::min(st.tol_position, st.tol_angle);
    fnewt_ = st.radau.newton_fraction > 0.0 ? st.radau.newton_fraction
                                             : std::max(10.0 * kRoundoff / tol, kNewtonShare * std::min(0.03, std::sqrt(tol)));
    // A distance of 10 eps / tol asks for round-off, which the round-off floor of newton() ends; a
    // slower assumed rate there only iterates in round-off noise (the fifth-order test at tol 1e-12:
    // rotation slope 4.81 -> 4.59).
    faccon_floor_ = fnewt_ > 10.0 * kRoundoff / tol ? kThetaTarget / (1.0 - kThetaTarget) : 0.0;
    for (MatrixXd* m : {&U_, &Up_, &V_, &A_, &R_, &F_, &Rt_, &U_acc_, &V_acc_, &A_acc_}) m->setZero(n_, 3);
    R_J_ = state.R_WN;
    for (const Node& nd : model.nodes) has_free_ = has_free_ || nd.kind == NodeKind::Free;
    for (VectorXd* v : {&r1_, &dw1_, &u_, &cu_, &cv_, &rhs_, &eu_, &ev_, &tmp_}) v->setZero(n_);
    rc_.setZero(n_);
    dwc_.setZero(n_);
    for (State& s : stage_) s = state;
    prev_ = state;
    dense_ = state;
    opt_residual_.matrices = false;
  }

  double time() const override { return state_.t; }
  detail::StepResult attempt(double h) override;
  double error_estimate(double h) const override;
  double hinge_angle(int hinge, bool trial) const override { return (trial ? stage_[2] : state_).phi[hinge]; }
  double hinge_rate(int hinge, bool trial) const override {
    const int dof = model_.hinges[static_cast<std::size_t>(hinge)].dof;
    return dof >= 0 ? (trial ? stage_[2] : state_).v[dof] : data_.hinges[static_cast<std::size_t>(hinge)].phidot;
  }
  std::vector<LockState>& locks() override { return state_.locks; }
  void accept() override;
  void sample(Sample& out) override { sample_state(state_, out); }
  std::string describe_residual() const override { return detail::describe_residual(model_, data_); }

  double step_after_accept(double h, double h_wanted, double err, bool after_rejection) override;
  double step_after_rejection(double h, double err) override;
  bool dense_output() const override { return true; }
  void sample_at(double t, Sample& out) override;
  double crossing_fraction(int hinge, double target, double side, double h) const override;
  void on_latch() override { need_jacobian_ = true; }  // the lock's stiffness enters K

  long jacobians() const { return jacobians_; }
  long evaluations() const { return evaluations_; }

 private:
  void evaluate_jacobian(const State& at);
  /// Simplified Newton on the stages of a step of size h; `transported`: on each stage's residuals
  /// and increments with the Free nodes' blocks turned to the Jacobian's axes (transport).
  detail::StepResult newton(double h, bool transported);
  /// Each Free node's rows (back: residuals, Q^T) or increments (Q) of stage i turned by
  /// Q = R_WN(stage i) R_WN(Jacobian)^T: the node's rotation since the Jacobian's configuration.
  void transport(MatrixXd& X, bool back) const;
  bool factorize(double h);
  void predict(double h);
  void form_stages(double h);
  void configure(State& s, const State& origin, const Eigen::Ref<const VectorXd>& u, double t) const;
  double error_norm(double h) const;
  void sample_state(const State& s, Sample& out);
  /// Controller's h_new / h from the error (err^(1/4): the estimate is O(h^4)).
  double ratio(double err) const {
    const double fac = std::min(kSafe, kSafe * (1 + 2 * nit_) / (newt_ + 2 * nit_));
    return std::clamp(fac / std::pow(std::max(err, 1e-10), 0.25), kMinRatio, kMaxRatio);
  }
  detail::StepResult failed(detail::StepResult& out, const std::string& why, double retry_factor) {
    out.converged = false;
    out.why = why;
    reject_ = true;
    // An old Jacobian may be why: a new one for the retry, which keeps a constant step at its size.
    out.retry_factor = !caljac_ && !st_.adaptive ? 1.0 : retry_factor;
    if (!caljac_) need_jacobian_ = true;
    return out;
  }

  const Model& model_;
  State& state_;
  Data& data_;
  const IntegratorSettings& st_;
  const detail::RadauIIA5& rk_;
  VectorXd w_;  // per dof: weight / tolerance
  const int n_;
  const int nit_;
  double fnewt_ = 0.03;
  double faccon_floor_ = 0.0;  // Newton's stop: the smallest theta / (1 - theta) it assumes
  bool has_drives_ = false;
  bool has_free_ = false;  // the model has Free nodes (the transport can change something)
  bool newton_ran_ = false;  // the last newton() reached its iterations
  bool transported_ = false; // the transport rescued a step: every later step uses it
  AssemblyOptions opt_residual_;

  // Jacobian and the two factorised systems.
  Eigen::SparseMatrix<double> K_, C_, M_, S_;
  Eigen::SparseMatrix<Complex> Sc_;
  mutable StageSystem<double> real_;
  StageSystem<Complex> complex_;
  double h_factored_ = 0.0;     // step of the factorisations (0: none valid)
  bool need_jacobian_ = true;   // evaluate K, C, M at the next attempt's start
  bool caljac_ = false;         // the Jacobian was evaluated for the current step

  // Newton and controller state.
  MatrixXd U_, Up_, V_, A_, R_, F_;  // n x 3: stage increments, their rates, velocities, accelerations, residuals
  MatrixXd Rt_;                      // n x 3: the residuals with each Free node's rows turned back (transport)
  std::vector<Eigen::Matrix3d> R_J_; // per node: its rotation at the Jacobian's configuration
  VectorXd r1_, dw1_, u_;
  VectorXcd rc_, dwc_;
  State stage_[3];
  int newt_ = 0;                // Newton iterations of the last attempt
  double faccon_ = 1.0;         // theta / (1 - theta) of the last contraction measured
  double later_rate_ = 1.0;     // the last ratio of increments after the first that an attempt measured (newton)
  double theta_ = 0.0;          // Newton's contraction rate of the last attempt
  bool theta_measured_ = false; // ... measured (at least two iterations)
  bool first_ = true;           // no step accepted yet
  bool reject_ = false;         // the last attempt was rejected (error or Newton)
  long naccpt_ = 0;             // steps accepted by the controller
  double h_accepted_ctrl_ = 0.0, err_accepted_ = 0.0;  // Gustafsson: the last accepted step and its error

  // The last accepted step: its start, collocation polynomial and size (dense output, predictor).
  State prev_;
  mutable State dense_;  // a state inside the last step (samples; the error estimate's perturbed start)
  MatrixXd U_acc_, V_acc_, A_acc_;
  double h_acc_ = 0.0;

  // Error estimate scratch.
  mutable VectorXd cu_, cv_, rhs_, eu_, ev_, tmp_;
  mutable long evaluations_ = 0;
  long jacobians_ = 0;
};

void RadauStepper::evaluate_jacobian(const State& at) {
  AssemblyOptions opt;
  opt.inertia_velocity_tangent = st_.inertia_velocity_tangent;
  assemble(model_, at, data_, opt);
  ++jacobians_;
  combine_matrices(model_, data_, 1.0, 0.0, 0.0, nullptr, K_);
  combine_matrices(model_, data_, 0.0, 1.0, 0.0, nullptr, C_);
  combine_matrices(model_, data_, 0.0, 0.0, 1.0, nullptr, M_);
  R_J_ = at.R_WN;
  need_jacobian_ = false;
  caljac_ = true;
  h_factored_ = 0.0;
}

bool RadauStepper::factorize(double h) {
  if (S_.nonZeros() != K_.nonZeros()) {
    S_ = K_;
    Sc_ = K_.cast<Complex>();
  }
  const double g = rk_.gamma / h;
  const Complex mu(rk_.alpha / h, rk_.beta / h), mu2 = mu * mu;
  const double *k = K_.valuePtr(), *c = C_.valuePtr(), *m = M_.valuePtr();
  double* s = S_.valuePtr();
  Complex* sc = Sc_.valuePtr();
  for (Eigen::Index i = 0; i < K_.nonZeros(); ++i) {
    s[i] = k[i] + g * c[i] + g * g * m[i];
    sc[i] = k[i] + mu * c[i] + mu2 * m[i];
  }
  if (!real_.factorize(model_, S_) || !complex_.factorize(model_, Sc_)) return false;
  h_factored_ = h;
  return true;
}

void RadauStepper::transport(MatrixXd& X, bool back) const {
  for (std::size_t k = 0; k < model_.nodes.size(); ++k) {
    const Node& nd = model_.nodes[k];
    if (nd.kind != NodeKind::Free) continue;
    for (int i = 0; i < 3; ++i) {
      const Eigen::Matrix3d Q = stage_[i].R_WN[k] * R_J_[k].transpose();
      for (const int d : {nd.dof, nd.dof + 3}) {
        const Eigen::Vector3d x = X.block<3, 1>(d, i);
        X.block<3, 1>(d, i) = back ? Eigen::Vector3d(Q.transpose() * x) : Eigen::Vector3d(Q * x);
      }
    }
  }
}

void RadauStepper::configure(State& s, const State& origin, const Eigen::Ref<const VectorXd>& u, double t) const {
  s.t = t;
  for (std::size_t k = 0; k < model_.nodes.size(); ++k)
    if (model_.nodes[k].kind == NodeKind::Free) {
      s.p_WN[k] = origin.p_WN[k];
      s.R_WN[k] = origin.R_WN[k];
    }
  s.phi = origin.phi;
  s.eta = origin.eta;
  apply_increment(model_, s, u);
}

void RadauStepper::predict(double h) {
  const VectorXd& v0 = state_.v;
  const VectorXd& a0 = state_.vdot;
  // Extrapolate the last step's collocation polynomial (as RADAU5), unless that step was much
  // shorter (cut to a lock crossing: its cubic says little 3 steps ahead): then Taylor's second order.
  if (h_acc_ <= 0.0 || h > 3.0 * h_acc_) {
    for (int i = 0; i < 3; ++i) {
      const double dt = rk_.c[i] * h;
      U_.col(i) = dt * v0 + (0.5 * dt * dt) * a0;
    }
    return;
  }
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d l = rk_.basis(1.0 + rk_.c[i] * h / h_acc_);
    u_ = l[0] * U_acc_.col(0) + l[1] * U_acc_.col(1) + l[2] * U_acc_.col(2);
    U_.col(i) = u_ - U_acc_.col(2);
    // Rotations: R(t) = exp(u(s)~) R_prev = exp(U~) R_0 with R_0 = exp(U_3~) R_prev.
    for (const int r : model_.rotation_dof_starts)
      U_.block<3, 1>(r, i) = so3::log(so3::exp(u_.segment<3>(r)) * so3::exp(-U_acc_.block<3, 1>(r, 2)));
  }
}

void RadauStepper::form_stages(double h) {
  const Eigen::Matrix3d& Ai = rk_.Ainv;
  for (int i = 0; i < 3; ++i) Up_.col(i) = (Ai(i, 0) * U_.col(0) + Ai(i, 1) * U_.col(1) + Ai(i, 2) * U_.col(2)) / h;
  V_ = Up_;
  for (const int r : model_.rotation_dof_starts)
    for (int i = 0; i < 3; ++i) V_.block<3, 1>(r, i) = so3::jl(U_.block<3, 1>(r, i)) * Up_.block<3, 1>(r, i);
  const VectorXd& v0 = state_.v;
  for (int i = 0; i < 3; ++i)
    A_.col(i) = (Ai(i, 0) * V_.col(0) + Ai(i, 1) * V_.col(1) + Ai(i, 2) * V_.col(2) - Ai.row(i).sum() * v0) / h;
  for (int i = 0; i < 3; ++i) {
    State& s = stage_[i];
    configure(s, state_, U_.col(i), state_.t + rk_.c[i] * h);
    s.v = V_.col(i);
    s.vdot = A_.col(i);
    s.a = s.vdot;
  }
}

detail::StepResult RadauStepper::attempt(double h) {
  // The transport (newton) as a fallback: Newton runs on the stages as they are until it diverges,
  // contracts too slowly or runs out of iterations; then the same step is tried with the transport
  // before it is cut, and once that rescued a step, every later step uses it (a body that made one
  // iteration matrix fail keeps turning). Measured (2026-12-07): the fifth-order test on the flexible
  // 3-D pendulum (radau5_test.cpp) never needs it and is unchanged (slopes 4.769 / 4.814 / 4.894);
  // the spin-up beam (bench/study/spinup.yaml, largest step 50 ms) switches once and then at local
  // error 1e-3 / 1e-4 / 1e-5 took 402 / 409 / 651 steps with deflection errors 0.020 / 0.0022 /
  // 0.00012 deg against Radau at 1e-8 (402 / 452 / 648 steps since the too-slow test in newton()
  // waits for a second ratio; docs/benchmarks.md has today's errors). Without the transport:
  // 4,974 / 7,499 / 1,297 steps; with Hairer and Wanner's looser Newton stop, which main used: stops
  // at t = 11.5 s / 5,482 steps, 0.043 deg / 1,187 steps, 0.00098 deg. The fallback for the failing
  // step alone, without keeping it, left 1.39 / 0.029 / 0.0035 deg (640 / 504 / 553 steps, with their
  // stop): plain Newton's fast but poor convergence on the other steps. sync-3d switches at t =
  // 1.0-1.8 s (before the first lock); with their stop the transport changed the Newton remainder
  // that dominated its errors (lock times at 1e-4: 1.65e-4 -> 3.6e-4 s), with a tenth of it every
  // error is smaller than main's (kNewtonShare).
  if (transported_) return newton(h, true);
  const bool reject = reject_;
  detail::StepResult out = newton(h, false);
  if (out.converged || !has_free_ || !newton_ran_) return out;
  reject_ = reject;
  const int factorizations = out.factorizations;
  detail::StepResult retry = newton(h, true);
  retry.factorizations += factorizations;
  if (retry.converged) transported_ = true;
  return retry;
}

detail::StepResult RadauStepper::newton(double h, bool transported) {
  detail::StepResult out;
  newton_ran_ = false;
  out.scale = 0.0;  // the driver's message: no relative residual test here
  for (State& s : stage_) {
    s.locks = state_.locks;
    s.frames = state_.frames;
  }
  if (n_ == 0) {  // fully prescribed motion: the drives' configuration at t0 + h
    State& s = stage_[2];
    s.t = state_.t + h;
    assemble(model_, s, data_, opt_residual_);
    ++evaluations_;
    out.converged = true;
    return out;
  }
  predict(h);
  try {
    // A new Jacobian at the predicted second stage (c = 0.64), not at the step's start: the stages
    // lie on both sides of it, which halves how far the bodies turn between the Jacobian's
    // configuration and the stages' (sync-3d, largest step 50 ms, at local error 1e-4 / 1e-5:
    // 1006 -> 917 / 1441 -> 1248 steps, 8,193 -> 7,548 / 12,285 -> 11,471 residuals, 802 -> 590 /
    // 848 -> 657 Jacobians).
    if (need_jacobian_) {
      form_stages(h);
      evaluate_jacobian(stage_[1]);
    }
  } catch (const ConvergenceError& e) {
    return failed(out, std::string("the Jacobian at the predicted second stage: ") + e.what(), 0.5);
  }
  if (h != h_factored_) {
    if (!factorize(h))
      return failed(out, "an iteration matrix is singular (" + detail::describe_singular(model_, S_) + ")", 0.5);
    ++out.factorizations;
  }
  newton_ran_ = true;
  faccon_ = std::pow(std::max(faccon_, kRoundoff), 0.8);
  theta_ = st_.radau.jacobian_theta;
  theta_measured_ = false;
  double dyno_old = 0.0, thq_old = 0.0;
  const Eigen::Matrix3d& T = rk_.T;
  const Eigen::Matrix3d& Ti = rk_.Tinv;
  newt_ = 0;
  int k = 0;               // iterations with the present factorisation
  bool refreshed = false;  // the Jacobian was re-evaluated at an iterate of this attempt
  // A slow or diverging iteration gets one new Jacobian at the present iterate's second stage (which
  // is closer to the solution than the prediction) before the step is given up: sync-3d, largest step
  // 50 ms, local error 1e-4 / 1e-5: 917 -> 701 / 1248 -> 976 steps, 212 -> 16 / 248 -> 20 rejected,
  // residuals + Jacobians + factorisations about as many (Newton takes more iterations per step).
  auto refresh = [&]() {
    if (refreshed) return false;
    refreshed = true;
    try {
      evaluate_jacobian(stage_[1]);
    } catch (const ConvergenceError&) {
      return false;
    }
    if (!factorize(h)) return false;
    ++out.factorizations;
    k = 0;
    dyno_old = thq_old = 0.0;
    theta_measured_ = false;
    return true;
  };
  bool evaluated = false;  // R_ holds the residuals at U_ (after a refresh without an increment)
  for (;;) {
    if (k >= nit_)
      return failed(out, "no convergence in " + std::to_string(nit_) + " simplified Newton iterations", 0.5);
    if (!evaluated) {
      form_stages(h);
      out.residual = 0.0;
      try {
        for (int i = 0; i < 3; ++i) {
          assemble(model_, stage_[i], data_, opt_residual_);
          ++evaluations_;
          R_.col(i) = data_.residual;
          out.residual = std::max(out.residual, data_.residual.norm());
          for (std::size_t b = 0; b < model_.flexible_bodies.size(); ++b) stage_[i].frames[b] = data_.flex[b].kin.frame;
        }
      } catch (const ConvergenceError& e) {
        return failed(out, e.what(), 0.5);
      }
    }
    evaluated = false;
    if (!std::isfinite(out.residual)) return failed(out, "the residual is not finite", 0.5);
    // Transformed residuals: W = T^-1 U, one real and one complex system.
    Rt_ = R_;
    if (transported) transport(Rt_, true);
    r1_ = Ti(0, 0) * Rt_.col(0) + Ti(0, 1) * Rt_.col(1) + Ti(0, 2) * Rt_.col(2);
    rc_.real() = Ti(1, 0) * Rt_.col(0) + Ti(1, 1) * Rt_.col(1) + Ti(1, 2) * Rt_.col(2);
    rc_.imag() = Ti(2, 0) * Rt_.col(0) + Ti(2, 1) * Rt_.col(1) + Ti(2, 2) * Rt_.col(2);
    real_.solve_negated(r1_, dw1_);
    complex_.solve_negated(rc_, dwc_);
    ++newt_;
    ++k;
    double sum = 0.0, largest = 0.0;
    for (Eigen::Index i = 0; i < n_; ++i) {
      const double a = dw1_[i] * w_[i], b = dwc_[i].real() * w_[i], c = dwc_[i].imag() * w_[i];
      sum += a * a + b * b + c * c;
      largest = std::max({largest, std::abs(a), std::abs(b), std::abs(c)});
    }
    const double dyno = std::sqrt(sum / (3.0 * n_));
    if (!std::isfinite(dyno)) return failed(out, "the Newton increment is not finite", 0.5);
    // Round-off floor: an increment of 1e-14 of the dofs' scales changes nothing that matters.
    const bool floor = largest * std::min(st_.tol_position, st_.tol_angle) <= 1e-14;
    if (!floor && k > 1 && k < nit_) {
      const double thq = dyno / dyno_old;
      theta_ = k == 2 ? thq : std::sqrt(thq * thq_old);
      theta_measured_ = true;
      if (k >= 3) later_rate_ = thq;
      thq_old = thq;
      if (!(theta_ < 0.99)) {
        if (refresh()) {  // from the present iterate, without its increment: its residuals again
          evaluated = true;
          continue;
        }
        std::ostringstream os;
        os.precision(3);
        os << "simplified Newton diverges (contraction rate " << theta_ << " at iteration " << newt_ << ")";
        return failed(out, os.str(), 0.5);
      }
      faccon_ = theta_ / (1.0 - theta_);
      // Distance to the solution after the remaining iterations, predicted from the rate: too far,
      // and a new Jacobian or a smaller step (theta ~ h) is the remedy. At the second iteration the
      // rate is the first ratio of increments alone, which can carry a transient the later ratios do
      // not: while the last later ratio measured (an earlier attempt's) was fast, below kSecondRatio,
      // the test waits for the third iteration. On sync-3d (local error 3e-4, largest step 50 ms,
      // 2026-12-07) the second increment is a median 0.36 of the first (10th-90th percentile
      // 0.06-0.87) and the third 0.04 of the second (0.02-0.19), also with a new Jacobian at every
      // step (0.37 and 0.033). Its cause, measured by central differences of the stacked stage
      // residuals at three steps: the stiffness K differs between the stages (one matrix for the
      // three leaves 1.2-16 % of the first increment wrong; each stage's own K, 0.2-1.3 %; its own C
      // or M, 1.2-16 %), so the first ratio measures how the stages differ more than how the
      // iteration contracts; judged on it, 307 of 682 attempts took a new Jacobian. On the spinning
      // beam (bench/study/spinup.yaml) the later ratios are often as slow as the first (0.24), and
      // waiting for them in every step cost 13 % more CPU there. Counts, CPU and errors of both:
      // docs/benchmarks.md, "Newton's first ratio is not its rate".
      const double dyth = faccon_ * dyno * std::pow(theta_, nit_ - 1 - k) / fnewt_;
      if (dyth >= 1.0 && st_.adaptive && !(k == 2 && later_rate_ < kSecondRatio)) {
        if (refresh()) {
          for (int i = 0; i < 3; ++i) F_.col(i) = T(i, 0) * dw1_ + T(i, 1) * dwc_.real() + T(i, 2) * dwc_.imag();
          if (transported) transport(F_, false);
          U_ += F_;
          continue;
        }
        const double q = std::clamp(dyth, 1e-4, 20.0);
        std::ostringstream os;
        os.precision(3);
        os << "simplified Newton too slow (contraction rate " << theta_ << " at iteration " << newt_ << ")";
        return failed(out, os.str(), 0.8 * std::pow(q, -1.0 / (4.0 + nit_ - 1 - k)));
      }
    }
    dyno_old = std::max(dyno, kRoundoff);
    for (int i = 0; i < 3; ++i) F_.col(i) = T(i, 0) * dw1_ + T(i, 1) * dwc_.real() + T(i, 2) * dwc_.imag();
    if (transported) transport(F_, false);
    U_ += F_;
    // With the transport, converged only once this step's own contraction rate is known (two
    // iterations): the rate of the last step, which RADAU5 lets stop the first iteration, let through
    // unconverged stages on sync-3d at local error 1e-4 (lock times 3.6e-3 s off instead of 3e-4 s).
    // The distance left is estimated with a rate no faster than the step control aims at
    // (kThetaTarget): a first increment that removed a poor prediction's bulk makes the next one look
    // like a contraction of 0.001-0.01 where the remainder contracts far slower (sync-3d at local error
    // 3e-5: steps stopped at two iterations left up to 0.24 of the tolerance; lock times 7.0e-5 s,
    // with the floor 1.5e-5 s, for 0.4 % more residuals).
    if ((std::max(faccon_, faccon_floor_) * dyno <= fnewt_ && (theta_measured_ || !transported)) || floor) break;
  }
  form_stages(h);  // the stages of the converged increments (not evaluated: the next step starts there)
  out.converged = true;
  out.iterations = newt_;
  out.evaluated = false;
  return out;
}

double RadauStepper::error_norm(double h) const {
  double sum = 0.0;
  for (Eigen::Index i = 0; i < n_; ++i) {
    const double a = eu_[i] * w_[i], b = h * ev_[i] * w_[i];
    sum += a * a + b * b;
  }
  const double err = std::sqrt(sum / (2.0 * std::max(1, n_)));
  return std::isfinite(err) ? err : std::numeric_limits<double>::infinity();
}

double RadauStepper::error_estimate(double h) const {
  if (n_ == 0) return 0.0;
  // (gamma/h - J)^-1 (y'_0 + (1/h) sum_j dd_j Z_j) for y = (u, v), y' = (dexp_u^-1 v, vdot), Z_j =
  // (U_j, V_j - v_0), J = [0 I; -M^-1 K  -M^-1 C]: with mu = gamma/h and c = (c_u, c_v),
  //   (K + mu C + mu^2 M) e_u = M c_v + (mu M + C) c_u,   e_v = mu e_u - c_u.
  const Eigen::Vector3d& dd = rk_.dd;
  const VectorXd& v0 = state_.v;
  const double mu = rk_.gamma / h;
  cu_ = v0 + (dd[0] * U_.col(0) + dd[1] * U_.col(1) + dd[2] * U_.col(2)) / h;
  cv_ = state_.vdot + (dd[0] * V_.col(0) + dd[1] * V_.col(1) + dd[2] * V_.col(2) - dd.sum() * v0) / h;
  tmp_ = cv_ + mu * cu_;
  rhs_.noalias() = M_ * tmp_;
  rhs_.noalias() += C_ * cu_;
  real_.solve_negated(rhs_, eu_);
  eu_ = -eu_;
  ev_ = mu * eu_ - cu_;
  double err = error_norm(h);
  if (err < 1.0 || !(first_ || reject_)) return err;
  // Second estimate (first step, after a rejection): c from y' at y_0 + e, which removes what the
  // first estimate leaves of stiff components. The v-part in residual form, M c_v = -r(x_0 (+) e_u,
  // v_0 + e_v, vdot = -(1/h) sum_j dd_j (V_j - v_0)), one residual evaluation (no mass solve).
  State& s = dense_;
  configure(s, state_, eu_, state_.t);
  s.frames = state_.frames;
  s.locks = state_.locks;
  s.v = v0 + ev_;
  s.vdot = -(dd[0] * V_.col(0) + dd[1] * V_.col(1) + dd[2] * V_.col(2) - dd.sum() * v0) / h;
  try {
    assemble(model_, s, data_, opt_residual_);
  } catch (const ConvergenceError&) {
    return err;  // the perturbed state cannot be evaluated: keep the first estimate
  }
  ++evaluations_;
  cu_ = s.v + (dd[0] * U_.col(0) + dd[1] * U_.col(1) + dd[2] * U_.col(2)) / h;
  for (const int r : model_.rotation_dof_starts) cu_.segment<3>(r) -= s.v.segment<3>(r) - so3::jl_inv(eu_.segment<3>(r)) * s.v.segment<3>(r);
  rhs_ = -data_.residual;
  tmp_ = mu * cu_;
  rhs_.noalias() += M_ * tmp_;
  rhs_.noalias() += C_ * cu_;
  real_.solve_negated(rhs_, eu_);
  eu_ = -eu_;
  ev_ = mu * eu_ - cu_;
  err = error_norm(h);
  return err;
}

void RadauStepper::accept() {
  const double h = stage_[2].t - state_.t;
  prev_ = state_;
  state_ = stage_[2];
  // Node poses of the accepted configuration (attached nodes, drives); the frames are those of the
  // last evaluation of stage 3 (a warm start).
  update_kinematics(model_, state_, data_, true);
  store_derived(model_, data_, state_);
  state_.frames = stage_[2].frames;
  U_acc_ = U_;
  V_acc_ = V_;
  A_acc_ = A_;
  h_acc_ = h;
  first_ = false;
  reject_ = false;
  caljac_ = false;
  if (theta_ > st_.radau.jacobian_theta) need_jacobian_ = true;  // Newton contracted slowly: a new Jacobian
}

double RadauStepper::step_after_accept(double h, double /*h_wanted*/, double err, bool after_rejection) {
  double q = ratio(err);
  if (naccpt_ > 0) {
    // Gustafsson's predictive controller: the error's trend over the last two accepted steps.
    const double g = std::clamp(kSafe / ((h_accepted_ctrl_ / h) * std::pow(err * err / err_accepted_, 0.25)), kMinRatio, kMaxRatio);
    q = std::min(q, g);
  }
  accepted_limit_ = q >= kMaxRatio ? StepLimit::Growth : StepLimit::Error;
  ++naccpt_;
  h_accepted_ctrl_ = h;
  err_accepted_ = std::max(1e-2, err);
  double h_new = h * q;
  if (after_rejection && h_new > h) {
    h_new = h;
    accepted_limit_ = StepLimit::Growth;
  }
  // Newton's limit: with one Jacobian for all stages, a stiff element that turns with its body makes
  // the contraction rate grow like h^3 (its stiffness, turned by ~ omega h, against the soft
  // directions' (gamma/h)^2 M). Growing the step beyond h (kThetaTarget / theta)^(1/3) made simplified
  // Newton fail at the next step (sync-3d at local error 1e-5, largest step 50 ms: 947 retries and
  // 1.74 s CPU without this limit; 150 and 1.21 s with it; targets 0.05 / 0.2 / 0.3: 1.27 / 1.51 / 1.49 s;
  // with the Jacobian at the second stage and one refresh of it in a slow iteration (attempt), residuals
  // + 4.6 Jacobians + 2 factorisations (their measured costs in residuals) at 1e-4 / 1e-5: target 0.05
  // 11,687 / 15,133, 0.1 11,968 / 15,883, 0.2 13,131 / 16,382, no limit 15,424 / 17,075). Without the
  // refresh, 94 % of the steps after the demo's last lock were set by this limit, not by the error (the
  // error would allow 7-9 ms where Newton allowed 3.6-6.5 ms at 1e-5). Lifting the limit with Newton on
  // the coupled stage system (a Jacobian per stage: rate 0.093 -> 0.019 after the demo's locks) let the
  // error estimate set the steps and cost more for larger errors (docs/benchmarks.md, "Newton on the
  // coupled stage system").
  if (theta_measured_ && theta_ > 0.0) {
    const double h_newton = std::max(h, h * std::cbrt(kThetaTarget / theta_));
    if (h_newton < h_new) {
      h_new = h_newton;
      accepted_limit_ = StepLimit::Newton;
    }
  }
  if (theta_ <= st_.radau.jacobian_theta && h_new >= kKeepLow * h && h_new <= kKeepHigh * h && h_new != h) {  // same matrices
    h_new = h;
    accepted_limit_ = StepLimit::Kept;
  }
  return h_new;
}

double RadauStepper::step_after_rejection(double h, double err) {
  reject_ = true;
  if (!caljac_) need_jacobian_ = true;
  return first_ ? 0.1 * h : h * ratio(err);
}

double RadauStepper::crossing_fraction(int hinge, double target, double side, double h) const {
  const int dof = model_.hinges[static_cast<std::size_t>(hinge)].dof;
  if (dof < 0)  // a driven hinge: its angle at the ends only
    return side * (hinge_angle(hinge, true) - target) >= 0.0 ? Stepper::crossing_fraction(hinge, target, side, h) : 2.0;
  const double phi0 = state_.phi[hinge];
  const auto g = [&](double s) { return side * (phi0 + rk_.basis(s).dot(U_.row(dof).transpose()) - target); };
  // The first sign change on a grid of the step (the angle may reach the lock and turn back inside it).
  constexpr int kGrid = 16;
  for (int k = 1; k <= kGrid; ++k)
    if (g(static_cast<double>(k) / kGrid) >= 0.0) return detail::first_crossing(g, static_cast<double>(k - 1) / kGrid, static_cast<double>(k) / kGrid);
  return 2.0;  // not reached in the step
}

void RadauStepper::sample_state(const State& s, Sample& out) {
  // A sample reads energies, frames and force elements, not the residual: the light evaluation
  // unless a driven hinge's sample needs its joint torque.
  AssemblyOptions opt{false, true, 1.0};
  opt.energies_only = !has_drives_;
  assemble(model_, s, data_, opt);
  make_sample(model_, s, data_, out);
}

void RadauStepper::sample_at(double t, Sample& out) {
  const double s = (t - prev_.t) / h_acc_;
  const Eigen::Vector3d l = rk_.basis(s);
  u_ = l[0] * U_acc_.col(0) + l[1] * U_acc_.col(1) + l[2] * U_acc_.col(2);
  configure(dense_, prev_, u_, t);
  dense_.frames = state_.frames;
  dense_.locks = prev_.locks;
  const VectorXd& v0 = prev_.v;
  const VectorXd& a0 = prev_.vdot;
  dense_.v = v0 + l[0] * (V_acc_.col(0) - v0) + l[1] * (V_acc_.col(1) - v0) + l[2] * (V_acc_.col(2) - v0);
  dense_.vdot = a0 + l[0] * (A_acc_.col(0) - a0) + l[1] * (A_acc_.col(1) - a0) + l[2] * (A_acc_.col(2) - a0);
  dense_.a = dense_.vdot;
  sample_state(dense_, out);
}

}  // namespace

RunStats simulate_radau5(const Model& model, State& state, Data& data, const IntegratorSettings& st, Observer* observer) {
  detail::validate_settings(st, state.t);
  initial_accelerations(model, state, data);
  RadauStepper stepper(model, state, data, st);
  RunStats stats = detail::drive_steps(model, st, stepper, observer);
  stats.jacobians = stepper.jacobians();
  stats.evaluations = stepper.evaluations();
  assemble(model, state, data, AssemblyOptions{false, true, 1.0});  // the caller's `data` belongs to the final state
  return stats;
}

}  // namespace seflex::mbd
