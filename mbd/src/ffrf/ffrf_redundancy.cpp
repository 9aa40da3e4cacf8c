// Redundant constraint equations of FFRF-LM and rigid-LM (docs/ffrf.md, "Redundant constraints"):
// the rows of the constraint Jacobian (position rows divided by the model's length scale, columns
// equilibrated to a largest entry of 1) are orthogonalised in the order of the joints (classical Gram-Schmidt, applied twice: "twice is
// enough", Giraud, Langou and Rozloznik 2005); a row whose component orthogonal to the rows kept
// before it is at most tol times the largest row norm depends on them and is removed. Along the run
// the same test on every accepted configuration checks that the rank has not changed.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ffrf/ffrf_detail.hpp"
#include "ffrf/ffrf_redundancy.hpp"
#include "seflex/mbd/state.hpp"

namespace seflex::mbd::detail {

namespace {

/// Hysteresis of the check along the run: a kept row must stay above tol / kHysteresis, a removed one
/// below tol * kHysteresis (relative to the largest row norm), so that round-off near the threshold
/// of t = 0 is not taken for a change of rank.
constexpr double kHysteresis = 100.0;

/// The scaled constraint Jacobian at s into w.G (num_multipliers x num_coords) and the rotation of
/// each constraint's second pose (the axes of its rotation rows) into R_B (if given).
void scaled_jacobian(const FfrfSystem& sys, const FfrfState& s, RankScratch& w, std::vector<Eigen::Matrix3d>* R_B) {
  const int nm = sys.num_multipliers(), nq = sys.num_coords;
  if (w.G.rows() != nm || w.G.cols() != nq) w.G.resize(nm, nq);
  w.G.setZero();
  const double L = sys.model->length_scale;
  hinge_values(sys, s, w.phi, w.phidot);
  for (int c = 0; c < static_cast<int>(sys.constraints.size()); ++c) {
    eval_constraint(sys, s, c, w.ce);
    if (R_B) R_B->push_back(w.ce.B.R);
    for (std::size_t i = 0; i < w.ce.cols.size(); ++i) {
      const int col = w.ce.cols[i];
      if (col < 0) continue;  // a driven hinge: not a coordinate
      for (int k = 0; k < 6; ++k) w.G(6 * c + k, col) += w.ce.G(k, static_cast<Eigen::Index>(i)) / (k < 3 ? L : 1.0);
    }
  }
  // Columns equilibrated (largest entry 1): the rank does not depend on the units of a coordinate.
  for (Eigen::Index j = 0; j < nq; ++j) {
    const double m = w.G.col(j).cwiseAbs().maxCoeff();
    if (m > 0.0) w.G.col(j) /= m;
  }
}

/// Component of row i of w.G orthogonal to the first r columns of w.Q (two passes), into w.v; its norm.
double orthogonal_part(RankScratch& w, Eigen::Index i, Eigen::Index r) {
  w.v = w.G.row(i).transpose();
  for (int pass = 0; pass < 2 && r > 0; ++pass) {
    w.c.head(r).noalias() = w.Q.leftCols(r).transpose() * w.v;
    w.v.noalias() -= w.Q.leftCols(r) * w.c.head(r);
  }
  return w.v.norm();
}

void ensure_sizes(const FfrfSystem& sys, RankScratch& w) {
  const int nm = sys.num_multipliers(), nq = sys.num_coords;
  if (w.Q.rows() != nq || w.Q.cols() != nm) w.Q.resize(nq, nm);
  if (w.v.size() != nq) w.v.resize(nq);
  if (w.c.size() != nm) w.c.resize(nm);
}

double largest_row_norm(const Eigen::MatrixXd& G) { return G.rows() > 0 ? G.rowwise().norm().maxCoeff() : 0.0; }

std::string vector_text(const Eigen::Vector3d& d) {
  char buf[96];
  auto z = [](double x) { return std::abs(x) < 5e-4 ? 0.0 : x; };  // no "-0"
  std::snprintf(buf, sizeof buf, "(%.3g, %.3g, %.3g)", z(d.x()), z(d.y()), z(d.z()));
  return buf;
}

}  // namespace

std::string constraint_joint_name(const FfrfSystem& sys, int c) {
  const Model& model = *sys.model;
  const FfrfConstraint& con = sys.constraints[static_cast<std::size_t>(c)];
  const Node& node = model.node(con.node);
  if (con.chain && node.hinge.valid()) return "hinge '" + model.hinges[static_cast<std::size_t>(node.hinge.value)].name + "'";
  return "body '" + sys.bodies[static_cast<std::size_t>(con.body)].name + "' on node '" + node.name + "'";
}

void find_redundant(FfrfSystem& sys) {
  const int nm = sys.num_multipliers();
  sys.removed.assign(static_cast<std::size_t>(nm), 0);
  sys.redundant.clear();
  if (!sys.options.remove_redundant || nm == 0) return;
  // The initial configuration (as ffrf_initial_state places it).
  FfrfState s;
  for (const FfrfBody& b : sys.bodies) {
    s.R_WB.push_back(b.X_WB0.R);
    s.p_WB.push_back(b.X_WB0.p);
  }
  s.z = Eigen::VectorXd::Zero(sys.num_z);
  s.phi = initial_state(*sys.model).phi;
  s.v = Eigen::VectorXd::Zero(sys.num_coords);
  RankScratch w;
  std::vector<Eigen::Matrix3d> R_B;
  scaled_jacobian(sys, s, w, &R_B);
  ensure_sizes(sys, w);
  const double tol = sys.options.redundancy_tolerance * largest_row_norm(w.G);
  Eigen::Index r = 0;
  static const char* axis[] = {"x", "y", "z"};
  for (Eigen::Index i = 0; i < nm; ++i) {
    const double res = orthogonal_part(w, i, r);
    if (res > tol) {
      w.Q.col(r++) = w.v / res;
      continue;
    }
    sys.removed[static_cast<std::size_t>(i)] = 1;
    const int c = static_cast<int>(i / 6), k = static_cast<int>(i % 6);
    RedundantEquation e;
    e.equation = static_cast<int>(i);
    e.joint = constraint_joint_name(sys, c);
    e.direction = k < 3 ? std::string("translation along ") + axis[k]
                        : "rotation about " + vector_text(R_B[static_cast<std::size_t>(c)].col(k - 3));
    sys.redundant.push_back(std::move(e));
  }
}

std::string rank_change(const FfrfSystem& sys, const FfrfState& s, RankScratch& w) {
  if (sys.redundant.empty()) return {};
  scaled_jacobian(sys, s, w, nullptr);
  ensure_sizes(sys, w);
  const double scale = sys.options.redundancy_tolerance * largest_row_norm(w.G);
  const int nm = sys.num_multipliers();
  Eigen::Index r = 0;
  std::string dependent, independent;
  auto add = [&](std::string& list, Eigen::Index i) {
    const std::string name = constraint_joint_name(sys, static_cast<int>(i / 6));
    if (list.find(name) == std::string::npos) list += (list.empty() ? "" : ", ") + name;
  };
  for (Eigen::Index i = 0; i < nm; ++i) {
    const double res = orthogonal_part(w, i, r);
    if (sys.is_removed(i)) {
      if (res > kHysteresis * scale) add(independent, i);
      continue;
    }
    if (res <= scale / kHysteresis) {
      add(dependent, i);
      continue;
    }
    w.Q.col(r++) = w.v / res;
  }
  if (dependent.empty() && independent.empty()) return {};
  std::string why = "the rank of the constraint equations changed since t = 0:";
  if (!independent.empty()) why += " equations removed as redundant at t = 0 are no longer dependent (" + independent + ")";
  if (!dependent.empty()) why += std::string(independent.empty() ? "" : ";") + " equations kept at t = 0 became dependent (" + dependent + ")";
  return why + " (docs/ffrf.md, \"Redundant constraints\")";
}

}  // namespace seflex::mbd::detail

namespace seflex::mbd {

std::string describe_redundant(const std::vector<RedundantEquation>& removed) {
  std::string out;
  for (std::size_t i = 0; i < removed.size(); ++i) {
    const RedundantEquation& e = removed[i];
    const bool new_joint = i == 0 || removed[i - 1].joint != e.joint;
    const std::size_t kind = e.direction.find(' ', e.direction.find(' ') + 1) + 1;  // "translation along " / "rotation about "
    const bool new_kind = new_joint || e.direction.compare(0, kind, removed[i - 1].direction, 0, kind) != 0;
    if (new_joint) out += (i ? " | " : "") + e.joint + ": ";
    else out += new_kind ? "; " : ", ";
    out += new_kind ? e.direction : e.direction.substr(kind);  // the kind once per joint and kind
  }
  return out;
}

}  // namespace seflex::mbd
