// Spectra backend: implicitly restarted Lanczos on OP = (K - sigma M)^-1 M with the M inner product
// (SymGEigsShiftSolver, GEigsMode::ShiftInvert). Spectra forces its start vector and any restart
// vector into the range of OP, which is what a singular (lumped) M needs.
#include <Spectra/SymGEigsShiftSolver.h>

#include <random>
#include <stdexcept>

#include "shift_invert.hpp"

namespace seflex::linalg {
namespace {

/// Spectra's "(A - sigma B)^-1 x" operation: the factorisation was made for sigma already.
class SolveOp {
 public:
  using Scalar = double;
  explicit SolveOp(ShiftInvertOperator& op) : op_(&op) {}
  Eigen::Index rows() const { return op_->rows(); }
  Eigen::Index cols() const { return op_->rows(); }
  void set_shift(double /*sigma*/) {}
  void perform_op(const double* x_in, double* y_out) const { op_->apply_inverse(x_in, y_out); }

 private:
  ShiftInvertOperator* op_;
};

/// Spectra's "B x" operation: the mass matrix.
class MassOp {
 public:
  using Scalar = double;
  explicit MassOp(const ShiftInvertOperator& op) : op_(&op) {}
  Eigen::Index rows() const { return op_->rows(); }
  Eigen::Index cols() const { return op_->rows(); }
  void perform_op(const double* x_in, double* y_out) const { op_->apply_M(x_in, y_out); }

 private:
  const ShiftInvertOperator* op_;
};

}  // namespace

KrylovResult run_spectra(ShiftInvertOperator& op, int nev, int ncv, double tol, int max_restarts, unsigned seed) {
  SolveOp solve(op);
  MassOp mass(op);
  KrylovResult result;
  try {
    // sigma = 0 here: Spectra then reports 1/theta, and theta is what the caller wants.
    Spectra::SymGEigsShiftSolver<SolveOp, MassOp, Spectra::GEigsMode::ShiftInvert> solver(solve, mass, nev, ncv, 0.0);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::VectorXd start(op.rows());
    for (Eigen::Index i = 0; i < start.size(); ++i) start(i) = uniform(rng);
    solver.init(start.data());
    const auto nconv = solver.compute(Spectra::SortRule::LargestAlge, max_restarts, tol, Spectra::SortRule::SmallestAlge);
    result.restarts = static_cast<int>(solver.num_iterations());
    result.converged = solver.info() == Spectra::CompInfo::Successful;
    if (nconv > 0) {
      result.theta = solver.eigenvalues().cwiseInverse();
      result.vectors = solver.eigenvectors();
    }
  } catch (const std::invalid_argument& e) {
    SEFLEX_DEMAND(false, std::string("Spectra: ") + e.what());
  }
  return result;
}

}  // namespace seflex::linalg
