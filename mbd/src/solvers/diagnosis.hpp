#pragma once
// Human-readable diagnosis of a residual that does not converge (internal).
#include <string>

#include "seflex/mbd/data.hpp"

namespace seflex::mbd::detail {

/// "node 'n3' rz = 1.2e+01 (bodies 'beam2', 'beam3'); hinge 'HL1' = ..." for the `top` largest
/// residual entries relative to their scale.
std::string describe_residual(const Model& model, const Data& data, int top = 3);

/// The dof with no mass/stiffness that makes a matrix singular, if one is found by its diagonal.
std::string describe_singular(const Model& model, const Eigen::SparseMatrix<double>& S);

/// Weighted max-norm max_i |x_i| w_i.
double weighted_norm(const Eigen::VectorXd& x, const Eigen::VectorXd& w);

}  // namespace seflex::mbd::detail
