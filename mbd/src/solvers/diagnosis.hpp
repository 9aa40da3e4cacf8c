#pragma once
// Human-readable diagnosis of a residual that does not converge (internal).
#include <algorithm>
#include <cmath>
#include <string>

#include "seflex/mbd/data.hpp"

namespace seflex::mbd::detail {

/// "node 'n3' rz = 1.2e+01 (bodies 'beam2', 'beam3'); hinge 'HL1' = ..." for the `top` largest
/// residual entries relative to their scale.
std::string describe_residual(const Model& model, const Data& data, int top = 3);

/// The dof with no mass/stiffness that makes a matrix singular, if one is found by its diagonal.
std::string describe_singular(const Model& model, const Eigen::SparseMatrix<double>& S);

/// The largest term of a step's local error estimate: its dof and the change of vdot over the step.
struct ErrorTerm {
  int dof = -1;
  double dvdot = 0.0;
};

/// Watches the accepted steps for an oscillation of period two steps: the largest term of the error
/// estimate on the same dof with its sign alternating from step to step (the spurious high-frequency
/// response an integrator without numerical damping keeps, e.g. generalized-alpha at rho_inf = 1 on a
/// direction without mass: docs/stability.md), then leading the estimate for as long as it keeps growing.
/// describe() explains a failure that follows it.
class SawtoothWatch {
 public:
  void accepted(const ErrorTerm& e) {
    const bool alternates = e.dof >= 0 && e.dof == last_.dof && e.dvdot * last_.dvdot < 0.0;
    run_ = alternates ? run_ + 1 : 0;
    if (run_ == 1) first_ = std::abs(last_.dvdot);
    last_ = e;
    if (seen_dof_ >= 0 && since_ == 0 && e.dof == seen_dof_) {  // the episode goes on: the same dof leads
      ++led_;
      if (run_ >= kMinRun) alternated_ = std::max(alternated_, static_cast<long>(run_) + 1);
      seen_last_ = std::abs(e.dvdot);
    } else if (run_ >= kMinRun) {  // a new episode: kMinRun + 1 alternating steps on one dof
      seen_dof_ = e.dof;
      led_ = alternated_ = run_ + 1;
      seen_first_ = first_;
      seen_last_ = std::abs(e.dvdot);
      since_ = 0;
    } else {
      ++since_;
    }
  }
  /// "" unless an episode lasted until at most kRecent accepted steps ago; else "; before this failure ...".
  std::string describe(const Model& model, double rho_inf) const;

  static constexpr int kMinRun = 8, kRecent = 50;

 private:
  ErrorTerm last_;
  int run_ = 0;           // accepted steps in a row whose largest error term alternated in sign on one dof
  double first_ = 0.0;    // |dvdot| at the start of that run
  // The last episode: its dof, the steps it led the estimate and alternated, its first and last |dvdot|.
  int seen_dof_ = -1;
  long led_ = 0, alternated_ = 0;
  double seen_first_ = 0.0, seen_last_ = 0.0;
  long since_ = 0;        // accepted steps since it ended
};

/// Weighted max-norm max_i |x_i| w_i.
double weighted_norm(const Eigen::VectorXd& x, const Eigen::VectorXd& w);

}  // namespace seflex::mbd::detail
