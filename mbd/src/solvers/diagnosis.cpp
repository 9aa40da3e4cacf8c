#include "solvers/diagnosis.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>

namespace seflex::mbd::detail {

namespace {

std::string bodies_on(const Model& model, const Data& data, int dof) {
  std::vector<std::string> names;
  for (std::size_t b = 0; b < model.flexible_bodies.size(); ++b) {
    const auto& d = data.pattern.dofs[static_cast<std::size_t>(data.clique_of_flex[b])];
    if (std::binary_search(d.begin(), d.end(), dof)) names.push_back("'" + model.flexible_bodies[b].name + "'");
  }
  for (std::size_t b = 0; b < model.rigid_bodies.size(); ++b) {
    const auto& d = data.pattern.dofs[static_cast<std::size_t>(data.clique_of_rigid[b])];
    if (std::binary_search(d.begin(), d.end(), dof)) names.push_back("'" + model.rigid_bodies[b].name + "'");
  }
  if (names.empty()) return "";
  std::string s = names.size() == 1 ? " (body " : " (bodies ";
  for (std::size_t i = 0; i < names.size() && i < 4; ++i) s += (i ? ", " : "") + names[i];
  if (names.size() > 4) s += ", ...";
  return s + ")";
}

}  // namespace

double weighted_norm(const Eigen::VectorXd& x, const Eigen::VectorXd& w) {
  double m = 0.0;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const double v = std::abs(x[i]) * w[i];
    if (!(v <= m)) m = v;  // NaN propagates
  }
  return m;
}

std::string describe_residual(const Model& model, const Data& data, int top) {
  const auto n = static_cast<int>(data.residual.size());
  std::vector<int> idx(static_cast<std::size_t>(n));
  std::iota(idx.begin(), idx.end(), 0);
  auto key = [&](int i) { return std::abs(data.residual[i]); };
  std::sort(idx.begin(), idx.end(), [&](int a, int b) { return key(a) > key(b); });
  std::ostringstream os;
  os.precision(3);
  for (int k = 0; k < std::min(top, n); ++k) {
    const int i = idx[static_cast<std::size_t>(k)];
    os << (k ? "; " : "") << model.dof_labels[static_cast<std::size_t>(i)] << " = " << data.residual[i]
       << bodies_on(model, data, i);
  }
  return os.str();
}

std::string describe_singular(const Model& model, const Eigen::SparseMatrix<double>& S) {
  Eigen::VectorXd colmax = Eigen::VectorXd::Zero(S.cols());
  for (int c = 0; c < S.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(S, c); it; ++it) colmax[c] = std::max(colmax[c], std::abs(it.value()));
  const double big = colmax.size() ? colmax.maxCoeff() : 0.0;
  std::string s;
  for (Eigen::Index c = 0; c < colmax.size(); ++c)
    if (!(colmax[c] > 1e-14 * big)) {
      s += (s.empty() ? "" : ", ") + model.dof_labels[static_cast<std::size_t>(c)];
      if (s.size() > 200) break;
    }
  return s.empty() ? "no dof without mass or stiffness: a combination of dofs, singular to round-off" : "no mass or stiffness on " + s;
}

std::string SawtoothWatch::describe(const Model& model, double rho_inf) const {
  if (seen_dof_ < 0 || since_ > kRecent) return "";
  std::ostringstream os;
  os.precision(3);
  os << "; before this failure the local error of " << led_ << " accepted steps was led by "
     << model.dof_labels[static_cast<std::size_t>(seen_dof_)] << ", whose acceleration changed sign at every step for "
     << alternated_ << " of them (its change per step grew from " << seen_first_ << " to " << seen_last_
     << "): an oscillation with a period of two steps that rho_inf = " << rho_inf
     << " does not damp enough and that cut the steps down, the mark of a direction without mass "
        "(docs/stability.md, \"Directions without mass\"); a smaller rho_inf damps it";
  return os.str();
}

}  // namespace seflex::mbd::detail
