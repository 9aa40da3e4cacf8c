// FFRF-LM time integration: Lie-group generalized-alpha for the index-3 DAE (Arnold and Bruls 2007)
//   M vdot + f(q, v, t) + G^T lambda = 0,   g(q, t) = 0
// with the equations of motion scaled by s = beta h^2 and the multipliers mu = s lambda, Newton on
// x = [h Dq; mu]:  [s (K T + gamma/(beta h) C + beta' M) + dG^T mu/dq T,  G^T;  G T,  0] dx = -[s r; g]
// (T: J_l(h Dq) on the frame rotations). Step control and lock events: step_control.hpp.
#include <Eigen/Dense>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "solvers/diagnosis.hpp"
#include "ffrf/ffrf_detail.hpp"
#include "ffrf/ffrf_iteration_matrix.hpp"
#include "ffrf/ffrf_redundancy.hpp"
#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/assembly/assembly.hpp"
#include "solvers/step_control.hpp"

namespace seflex::mbd {

using detail::AlphaCoefficients;
using detail::FfrfEval;
using Eigen::SparseMatrix;
using Eigen::VectorXd;
using Triplets = std::vector<Eigen::Triplet<double>>;

namespace {

double equation_scale(const FfrfSystem& sys, const AlphaCoefficients& c, double h) {
  return sys.options.scale_constraints ? c.beta * h * h : 1.0;
}

void set_driven(const FfrfSystem& sys, FfrfState& s) {
  const Model& model = *sys.model;
  for (std::size_t h = 0; h < model.hinges.size(); ++h)
    if (model.hinges[h].drive) s.phi[static_cast<Eigen::Index>(h)] = model.hinges[h].drive(s.t).phi;
}

/// Configuration, velocities, accelerations and multipliers at t0 + h for the unknowns x.
void configure(const FfrfSystem& sys, const FfrfState& s0, const AlphaCoefficients& c, double h, const VectorXd& x,
               FfrfState& s1) {
  const int nq = sys.num_coords;
  const auto hDq = x.head(nq);
  s1.t = s0.t + h;
  for (std::size_t b = 0; b < sys.bodies.size(); ++b) {
    const FfrfBody& bd = sys.bodies[b];
    s1.p_WB[b] = s0.p_WB[b] + hDq.segment<3>(bd.coord);
    s1.R_WB[b] = so3::exp(hDq.segment<3>(bd.coord + 3)) * s0.R_WB[b];
    if (bd.k > 0) s1.z.segment(bd.z_offset, bd.k) = s0.z.segment(bd.z_offset, bd.k) + hDq.segment(bd.coord + 6, bd.k);
  }
  for (std::size_t h2 = 0; h2 < sys.hinge_coord.size(); ++h2)
    if (sys.hinge_coord[h2] >= 0)
      s1.phi[static_cast<Eigen::Index>(h2)] = s0.phi[static_cast<Eigen::Index>(h2)] + hDq[sys.hinge_coord[h2]];
  set_driven(sys, s1);
  s1.a = (hDq / h - s0.v - h * (0.5 - c.beta) * s0.a) / (c.beta * h);
  s1.v = s0.v + h * (1.0 - c.gamma) * s0.a + h * c.gamma * s1.a;
  s1.vdot = ((1.0 - c.am) * s1.a + c.am * s0.a - c.af * s0.vdot) / (1.0 - c.af);
  s1.lambda = x.tail(sys.num_multipliers()) / equation_scale(sys, c, h);
}

/// Right-multiply the rotation columns of the triplets by J_l(h Dq) of their body (Lie tangent).
/// skip_removed: the triplets are constraint rows, those of removed equations left out.
void add_tangent(const FfrfSystem& sys, const VectorXd& hDq, const Triplets& in, double factor, int row_offset, Triplets& out,
                 const FfrfSystem* skip_removed = nullptr) {
  for (const auto& t : in) {
    if (skip_removed && skip_removed->is_removed(t.row())) continue;
    const int j = t.col();
    if (sys.kind[static_cast<std::size_t>(j)] != 'r') {
      out.emplace_back(t.row() + row_offset, j, factor * t.value());
      continue;
    }
    const FfrfBody& b = sys.bodies[static_cast<std::size_t>(sys.owner[static_cast<std::size_t>(j)])];
    const Eigen::Matrix3d T = so3::jl(hDq.segment<3>(b.coord + 3));
    const int cj = j - b.coord - 3;
    for (int k = 0; k < 3; ++k) out.emplace_back(t.row() + row_offset, b.coord + 3 + k, factor * t.value() * T(cj, k));
  }
}

/// Scratch of step_system.
struct StepScratch {
  VectorXd hDq;
  Triplets T;
};

/// Residual R and (if matrices) the iteration matrix as triplets w.T.
void step_system(const FfrfSystem& sys, const FfrfState& s0, double h, const AlphaCoefficients& c, const VectorXd& x,
                 FfrfState& s1, FfrfEval& ev, VectorXd& R, bool matrices, StepScratch& w) {
  configure(sys, s0, c, h, x, s1);
  detail::ffrf_assemble(sys, s1, matrices, ev);
  const int nq = sys.num_coords, nm = sys.num_multipliers();
  const double sc = equation_scale(sys, c, h);
  R.resize(nq + nm);
  R.head(nq) = sc * ev.r;
  R.tail(nm) = ev.g;
  // A removed (redundant) equation: its multiplier is held at zero, the row reads mu_i = 0.
  for (const RedundantEquation& e : sys.redundant) R[nq + e.equation] = x[nq + e.equation];
  if (!matrices) return;
  const double bp = (1.0 - c.am) / ((1.0 - c.af) * c.beta * h * h), gp = c.gamma / (c.beta * h);
  const VectorXd& hDq = w.hDq = x.head(nq);
  Triplets& T = w.T;
  T.clear();
  // Capacity for the largest lists (a rotation column of K and G becomes three): constant once the
  // lists' capacities are (detail::ffrf_assemble), so T never grows after the first step.
  T.reserve(3 * ev.K.capacity() + ev.C.capacity() + ev.M.capacity() + 4 * ev.G.capacity() + sys.redundant.size());
  add_tangent(sys, hDq, ev.K, sc, 0, T);
  for (const auto& t : ev.C) T.emplace_back(t.row(), t.col(), sc * gp * t.value());
  for (const auto& t : ev.M) T.emplace_back(t.row(), t.col(), sc * bp * t.value());
  add_tangent(sys, hDq, ev.G, 1.0, nq, T, &sys);
  for (const auto& t : ev.G)
    if (!sys.is_removed(t.row())) T.emplace_back(t.col(), nq + t.row(), t.value());
  for (const RedundantEquation& e : sys.redundant) T.emplace_back(nq + e.equation, nq + e.equation, 1.0);
}

SparseMatrix<double> to_sparse(const Triplets& T, int rows, int cols) {
  SparseMatrix<double> A(rows, cols);
  A.setFromTriplets(T.begin(), T.end());
  return A;
}

/// Solve [W G^T; G 0] [x; y] = [a; b]; throws ConvergenceError if singular.
/// Removed (redundant) equations: their rows read y_i = 0 (FfrfSystem::removed).
VectorXd saddle_solve(const FfrfSystem& sys, const SparseMatrix<double>& W, const SparseMatrix<double>& G, const VectorXd& a,
                      const VectorXd& b, const std::string& what) {
  const auto n = W.rows(), m = G.rows();
  Triplets T;
  for (int k = 0; k < W.outerSize(); ++k)
    for (SparseMatrix<double>::InnerIterator it(W, k); it; ++it) T.emplace_back(static_cast<int>(it.row()), static_cast<int>(it.col()), it.value());
  for (int k = 0; k < G.outerSize(); ++k)
    for (SparseMatrix<double>::InnerIterator it(G, k); it; ++it) {
      if (sys.is_removed(it.row())) continue;
      T.emplace_back(static_cast<int>(n + it.row()), static_cast<int>(it.col()), it.value());
      T.emplace_back(static_cast<int>(it.col()), static_cast<int>(n + it.row()), it.value());
    }
  for (const RedundantEquation& e : sys.redundant) T.emplace_back(static_cast<int>(n + e.equation), static_cast<int>(n + e.equation), 1.0);
  const SparseMatrix<double> A = to_sparse(T, static_cast<int>(n + m), static_cast<int>(n + m));
  Eigen::SparseLU<SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  lu.compute(A);
  if (lu.info() != Eigen::Success)
    throw ConvergenceError("floating-frame formulation: the " + what +
                           " system is singular (redundant joints, or a coordinate without mass)");
  VectorXd rhs(n + m);
  rhs << a, b;
  for (const RedundantEquation& e : sys.redundant) rhs[n + e.equation] = 0.0;
  return lu.solve(rhs);
}

/// s advanced along its velocities by dt (accelerations ignored), drives at t + dt.
FfrfState advanced(const FfrfSystem& sys, const FfrfState& s, double dt) {
  FfrfState o = s;
  o.t = s.t + dt;
  for (std::size_t b = 0; b < sys.bodies.size(); ++b) {
    const FfrfBody& bd = sys.bodies[b];
    o.p_WB[b] += dt * s.v.segment<3>(bd.coord);
    o.R_WB[b] = so3::exp(dt * s.v.segment<3>(bd.coord + 3)) * s.R_WB[b];
    if (bd.k > 0) o.z.segment(bd.z_offset, bd.k) += dt * s.v.segment(bd.coord + 6, bd.k);
  }
  for (std::size_t h = 0; h < sys.hinge_coord.size(); ++h)
    if (sys.hinge_coord[h] >= 0) o.phi[static_cast<Eigen::Index>(h)] += dt * s.v[sys.hinge_coord[h]];
  set_driven(sys, o);
  return o;
}

VectorXd body_velocity_guess(const FfrfSystem& sys, const Model& model, const Data& d, int bi) {
  const FfrfBody& b = sys.bodies[static_cast<std::size_t>(bi)];
  VectorXd v = VectorXd::Zero(6 + b.k);
  const NodeKinematics& n0 = d.nodes[static_cast<std::size_t>(b.nodes[0].value)];
  if (!b.flexible) {
    v.head<3>() = n0.v + n0.w.cross(b.X_WB0.p - n0.p);
    v.segment<3>(3) = n0.w;
    return v;
  }
  // The AIC kernel splits the interface velocities into frame motion (Zx) and elastic rates (Tx).
  const FlexibleBody& fb = model.flexible_bodies[static_cast<std::size_t>(b.model_index)];
  const AicElement& e = model.superelement(fb.se);
  std::vector<Eigen::Matrix3d> R_WI;
  std::vector<Eigen::Vector3d> p_WI;
  VectorXd w = VectorXd::Zero(e.n);
  const Eigen::Matrix3d& R = b.X_WB0.R;
  for (int j = 0; j < e.N; ++j) {
    const NodeKinematics& nk = d.nodes[static_cast<std::size_t>(fb.nodes[static_cast<std::size_t>(j)].value)];
    R_WI.push_back(nk.R * fb.R_NI[static_cast<std::size_t>(j)]);
    p_WI.push_back(nk.p);
    w.segment<3>(6 * j) = R.transpose() * nk.v;
    w.segment<3>(6 * j + 3) = R.transpose() * nk.w;
  }
  AicKinematics kin;
  recover_frame(e, R_WI, p_WI, VectorXd::Zero(e.m), FrameRecovery::Newton6, FloatingFrame{b.X_WB0.R, b.X_WB0.p}, kin);
  const VectorXd tw = kin.Zx * w;
  v.head<3>() = kin.frame.R_WB * tw.head<3>();
  v.segment<3>(3) = kin.frame.R_WB * tw.tail<3>();
  if (b.k > 0) v.tail(b.k) = b.V.transpose() * (e.M * (transfer_matrix(e, kin) * w));
  return v;
}

}  // namespace

void ffrf_step_system(const FfrfSystem& sys, const FfrfState& s0, double h, double rho_inf, const VectorXd& x, FfrfState& s1,
                      VectorXd& R, SparseMatrix<double>* S) {
  FfrfEval ev;
  StepScratch w;
  s1 = s0;
  step_system(sys, s0, h, AlphaCoefficients(rho_inf), x, s1, ev, R, S != nullptr, w);
  if (!S) return;
  const int n = sys.num_coords + sys.num_multipliers();
  S->resize(n, n);
  S->setFromTriplets(w.T.begin(), w.T.end());
}

void ffrf_constraints(const FfrfSystem& sys, const FfrfState& s, VectorXd& g, VectorXd& gdot) {
  VectorXd phi, phidot;
  detail::ConstraintEval ce;
  detail::constraint_rates(sys, s, phi, phidot, ce, g, gdot);
}

FfrfState ffrf_initial_state(const FfrfSystem& sys) {
  const Model& model = *sys.model;
  const State st = initial_state(model);
  Data d(model);
  update_kinematics(model, st, d, true);
  const int nq = sys.num_coords, nm = sys.num_multipliers();
  FfrfState s;
  s.t = 0.0;
  for (const FfrfBody& b : sys.bodies) {
    s.R_WB.push_back(b.X_WB0.R);
    s.p_WB.push_back(b.X_WB0.p);
  }
  s.z = VectorXd::Zero(sys.num_z);
  s.phi = st.phi;
  s.locks = st.locks;
  s.v = VectorXd::Zero(nq);
  s.vdot = VectorXd::Zero(nq);
  s.lambda = VectorXd::Zero(nm);
  for (std::size_t b = 0; b < sys.bodies.size(); ++b)
    s.v.segment(sys.bodies[b].coord, 6 + sys.bodies[b].k) = body_velocity_guess(sys, model, d, static_cast<int>(b));
  for (std::size_t h = 0; h < model.hinges.size(); ++h)
    if (sys.hinge_coord[h] >= 0) s.v[sys.hinge_coord[h]] = model.hinges[h].phidot0;
  FfrfEval ev;
  detail::ffrf_assemble(sys, s, true, ev);
  const SparseMatrix<double> M = to_sparse(ev.M, nq, nq), G = to_sparse(ev.G, nm, nq);
  // Velocities: the mass-weighted nearest ones that satisfy the velocity constraints (hinge rates
  // weighted heavily: they are what the user gave).
  VectorXd g, gdot;
  ffrf_constraints(sys, s, g, gdot);
  if (nm > 0) {
    SparseMatrix<double> W = M;
    const double wh = 1e3 * std::max(1e-12, M.diagonal().cwiseAbs().maxCoeff());
    for (int i = 0; i < nq; ++i)
      if (sys.kind[static_cast<std::size_t>(i)] == 'h') W.coeffRef(i, i) += wh;
    s.v += saddle_solve(sys, W, G, VectorXd::Zero(nq), -gdot, "initial velocity").head(nq);
  }
  // Accelerations and multipliers: M vdot + G^T lambda = -f, G vdot = -(d/dt G) v.
  ffrf_assemble(sys, s, false, ev);
  VectorXd conv = VectorXd::Zero(nm);
  if (nm > 0) {
    const double eps = 1e-5;
    VectorXd gp, gdp, gm, gdm;
    ffrf_constraints(sys, advanced(sys, s, eps), gp, gdp);
    ffrf_constraints(sys, advanced(sys, s, -eps), gm, gdm);
    conv = (gdp - gdm) / (2.0 * eps);
  }
  const VectorXd sol = saddle_solve(sys, M, G, -ev.r, -conv, "initial acceleration");
  s.vdot = sol.head(nq);
  s.a = s.vdot;
  s.lambda = sol.tail(nm);
  return s;
}

namespace {

/// FFRF-LM as seen by the step driver.
class FfrfStepper final : public detail::Stepper {
 public:
  FfrfStepper(const FfrfSystem& sys, FfrfState& state, const IntegratorSettings& st, FfrfStats& stats)
      : sys_(sys), state_(state), st_(st), c_(st.rho_inf), stats_(stats) {
    w_tol_.resize(sys.num_coords);
    for (int i = 0; i < sys.num_coords; ++i) {
      const char k = sys.kind[static_cast<std::size_t>(i)];
      w_tol_[i] = sys.weight[i] / ((k == 't' || k == 'e') ? st.tol_position : st.tol_angle);
    }
    record_drift();
  }
  double time() const override { return state_.t; }
  detail::StepResult attempt(double h) override;
  double error_estimate(double h) const override {
    dvdot_ = trial_.vdot - state_.vdot;
    return detail::wrms_error(dvdot_, w_tol_, h, c_);
  }
  double hinge_angle(int hinge, bool trial) const override { return (trial ? trial_ : state_).phi[hinge]; }
  double hinge_rate(int hinge, bool trial) const override {
    const FfrfState& s = trial ? trial_ : state_;
    const int c = sys_.hinge_coord[static_cast<std::size_t>(hinge)];
    return c >= 0 ? s.v[c] : sys_.model->hinges[static_cast<std::size_t>(hinge)].drive(s.t).phidot;
  }
  std::vector<LockState>& locks() override { return state_.locks; }
  void accept() override {
    locks_ = state_.locks;
    state_ = trial_;
    state_.locks = locks_;
    record_drift();
  }
  void sample(Sample& out) override { detail::ffrf_sample(sys_, state_, sample_, out); }
  std::string describe_residual() const override;

 private:
  void record_drift() {
    VectorXd &g = g_, &gd = gd_;
    detail::constraint_rates(sys_, state_, phi_, phidot_, ce_, g, gd);
    for (Eigen::Index c = 0; c < g.size() / 6; ++c) {
      stats_.drift_position = std::max(stats_.drift_position, g.segment<3>(6 * c).norm());
      stats_.drift_rotation = std::max(stats_.drift_rotation, g.segment<3>(6 * c + 3).norm());
      stats_.drift_velocity = std::max(stats_.drift_velocity, gd.segment<3>(6 * c).norm());
      stats_.drift_angular = std::max(stats_.drift_angular, gd.segment<3>(6 * c + 3).norm());
    }
  }
  const FfrfSystem& sys_;
  FfrfState& state_;
  const IntegratorSettings& st_;
  AlphaCoefficients c_;
  FfrfStats& stats_;
  VectorXd w_tol_;
  FfrfState trial_;
  FfrfEval ev_;
  // Scratch, sized at the first step (no allocation after it).
  StepScratch step_;
  VectorXd x_, a1_, R_, d_, dq_, g_, gd_, phi_, phidot_;
  mutable VectorXd dvdot_;
  std::vector<LockState> locks_;
  detail::ConstraintEval ce_;
  detail::SampleScratch sample_;
  detail::FfrfIterationMatrix iteration_;
  detail::RankScratch rank_;
};

detail::StepResult FfrfStepper::attempt(double h) {
  detail::StepResult out;
  const FfrfState& s0 = state_;
  trial_ = s0;
  const int nq = sys_.num_coords, nm = sys_.num_multipliers();
  const double L = sys_.model->length_scale;
  VectorXd& x = x_;
  x.resize(nq + nm);
  VectorXd& a1 = a1_;
  a1 = (s0.vdot - c_.am * s0.a) / (1.0 - c_.am);
  x.head(nq) = h * s0.v + h * h * (0.5 - c_.beta) * s0.a + h * h * c_.beta * a1;
  x.tail(nm) = equation_scale(sys_, c_, h) * s0.lambda;
  VectorXd& R = R_;
  double inc = std::numeric_limits<double>::infinity(), r_prev = inc;
  bool fresh = false;
  for (int it = 0; it <= st_.newton_max_iterations; ++it) {
    bool matrices = !fresh || !st_.reuse_iteration_matrix;
    step_system(sys_, s0, h, c_, x, trial_, ev_, R, matrices, step_);
    out.iterations = it;
    out.residual = ev_.r.norm();
    out.scale = ev_.scale.norm();
    if (!std::isfinite(out.residual) || !ev_.g.allFinite()) {
      out.why = "the residual is not finite";
      return out;
    }
    double gw = 0.0;
    for (Eigen::Index i = 0; i < nm; ++i)
      if (!sys_.is_removed(i)) gw = std::max(gw, std::abs(ev_.g[i]) / (i % 6 < 3 ? L : 1.0));
    const double tol = st_.newton_residual_tol * out.scale + 1e-14 * out.scale;
    if ((out.residual <= tol && inc <= st_.newton_increment_tol && gw <= st_.newton_increment_tol) ||
        (inc <= 1e-15 && out.residual <= 1e4 * tol)) {  // the latter: round-off floor (see the AIC integrator)
      out.why = detail::rank_change(sys_, trial_, rank_);
      out.converged = out.why.empty();
      return out;
    }
    if (it == st_.newton_max_iterations) break;
    if (!matrices && out.residual > 0.1 * r_prev) {
      matrices = true;
      step_system(sys_, s0, h, c_, x, trial_, ev_, R, true, step_);
    }
    r_prev = out.residual;
    if (matrices) {
      if (!iteration_.factorize(step_.T, nq + nm)) {
        out.why = "the iteration matrix is singular (redundant joints or a coordinate without mass)";
        return out;
      }
      if (sys_.options.condition_estimate) {
        const Eigen::JacobiSVD<Eigen::MatrixXd> svd{iteration_.matrix()};
        const auto& sv = svd.singularValues();
        const double cond = sv[0] / sv[sv.size() - 1];
        stats_.condition_max = std::max(stats_.condition_max, cond);
        stats_.condition_min = stats_.condition_min > 0.0 ? std::min(stats_.condition_min, cond) : cond;
      }
      fresh = true;
      ++out.factorizations;
    }
    VectorXd& d = d_;
    iteration_.solve_negated(R, d);
    dq_ = d.head(nq);
    inc = detail::weighted_norm(dq_, sys_.weight);
    if (!std::isfinite(inc)) {
      out.why = "the Newton increment is not finite";
      return out;
    }
    x += d;
  }
  out.why = "no convergence in " + std::to_string(st_.newton_max_iterations) + " Newton iterations";
  return out;
}

std::string FfrfStepper::describe_residual() const {
  std::vector<int> idx(static_cast<std::size_t>(sys_.num_coords));
  for (int i = 0; i < sys_.num_coords; ++i) idx[static_cast<std::size_t>(i)] = i;
  auto rel = [&](int i) { return std::abs(ev_.r[i]) / std::max(ev_.scale[i], 1e-300); };
  std::sort(idx.begin(), idx.end(), [&](int a, int b) { return rel(a) > rel(b); });
  std::ostringstream os;
  os.precision(3);
  static const char* comp[] = {"x", "y", "z", "rx", "ry", "rz"};
  for (std::size_t k = 0; k < idx.size() && k < 3; ++k) {
    const int i = idx[k];
    const char kind = sys_.kind[static_cast<std::size_t>(i)];
    const int o = sys_.owner[static_cast<std::size_t>(i)];
    if (k) os << "; ";
    if (kind == 'h') {
      os << "hinge '" << sys_.model->hinges[static_cast<std::size_t>(o)].name << "'";
    } else {
      const FfrfBody& b = sys_.bodies[static_cast<std::size_t>(o)];
      const int c = i - b.coord;
      os << "body '" << b.name << "' " << (c < 6 ? std::string(comp[c]) : "mode " + std::to_string(c - 5));
    }
    os << " = " << ev_.r[i];
  }
  return os.str();
}

}  // namespace

FfrfStats simulate_ffrf(const Model& model, const IntegratorSettings& st, const FfrfOptions& options, Observer* observer) {
  detail::validate_settings(st, 0.0);
  const FfrfSystem sys = make_ffrf_system(model, options);
  FfrfState state = ffrf_initial_state(sys);
  FfrfStats stats;
  stats.coordinates = sys.num_coords;
  stats.constraints = sys.num_multipliers() - static_cast<int>(sys.redundant.size());
  stats.redundant = sys.redundant;
  FfrfStepper stepper(sys, state, st, stats);
  stats.run = detail::drive_steps(model, st, stepper, observer);
  return stats;
}

}  // namespace seflex::mbd
