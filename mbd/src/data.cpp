// Data: per-node and per-body scratch and the fixed sparse pattern built from dof cliques.
#include "seflex/mbd/data.hpp"

#include <algorithm>
#include <cmath>

#include "seflex/common/error.hpp"

namespace seflex::mbd {

namespace {

std::vector<int> hinge_dofs(const Model& model, const ForceElement& fe) {
  std::vector<int> d;
  auto add = [&](HingeIndex h) {
    const int dof = model.hinge(h).dof;
    if (dof >= 0) d.push_back(dof);
  };
  std::visit(
      [&](const auto& el) {
        using T = std::decay_t<decltype(el)>;
        if constexpr (std::is_same_v<T, CableLoop>) {
          for (auto h : el.hinges_a) add(h);
          for (auto h : el.hinges_b) add(h);
        } else {
          add(el.hinge);
        }
      },
      fe);
  std::sort(d.begin(), d.end());
  d.erase(std::unique(d.begin(), d.end()), d.end());
  return d;
}

int position(const std::vector<int>& sorted, int dof) {
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), dof);
  SEFLEX_DEMAND(it != sorted.end() && *it == dof, "dof missing from its clique");
  return static_cast<int>(it - sorted.begin());
}

}  // namespace

Data::Data(const Model& model) {
  nodes.resize(model.nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    nodes[k].J.assign(model.node_dofs[k].size(), Vector6d::Zero());
    nodes[k].G.assign(model.node_dofs[k].size(), Vector6d::Zero());
  }
  hinges.resize(model.hinges.size());
  flex.resize(model.flexible_bodies.size());
  rigid.resize(model.rigid_bodies.size());
  forces.resize(model.force_elements.size());
  residual = Eigen::VectorXd::Zero(model.num_dofs);
  scale = Eigen::VectorXd::Zero(model.num_dofs);
  floor = Eigen::VectorXd::Zero(model.num_dofs);

  auto& cl = pattern.dofs;
  for (std::size_t b = 0; b < model.flexible_bodies.size(); ++b) {
    const FlexibleBody& body = model.flexible_bodies[b];
    std::vector<int> d;
    for (auto n : body.nodes) {
      const auto& nd = model.node_dofs[static_cast<std::size_t>(n.value)];
      d.insert(d.end(), nd.begin(), nd.end());
    }
    const int m = model.superelement(body.se).m;
    for (int k = 0; k < m; ++k) d.push_back(body.eta_dof + k);
    std::sort(d.begin(), d.end());
    d.erase(std::unique(d.begin(), d.end()), d.end());
    std::vector<std::vector<int>> pos;
    for (auto n : body.nodes) {
      std::vector<int> p;
      for (int dof : model.node_dofs[static_cast<std::size_t>(n.value)]) p.push_back(position(d, dof));
      pos.push_back(p);
    }
    std::vector<int> epos;
    for (int k = 0; k < m; ++k) epos.push_back(position(d, body.eta_dof + k));
    flex_node_pos.push_back(pos);
    flex_eta_pos.push_back(epos);
    clique_of_flex.push_back(static_cast<int>(cl.size()));
    cl.push_back(d);
  }
  for (const auto& body : model.rigid_bodies) {
    clique_of_rigid.push_back(static_cast<int>(cl.size()));
    cl.push_back(model.node_dofs[static_cast<std::size_t>(body.anchor.value)]);
  }
  for (std::size_t k = 0; k < model.nodes.size(); ++k) {
    clique_of_node.push_back(static_cast<int>(cl.size()));
    cl.push_back(model.node_dofs[k]);
  }
  for (const auto& fe : model.force_elements) {
    clique_of_force.push_back(static_cast<int>(cl.size()));
    cl.push_back(hinge_dofs(model, fe.element));
  }
  std::vector<Eigen::Triplet<double>> trip;
  for (int i = 0; i < model.num_dofs; ++i) trip.emplace_back(i, i, 0.0);
  for (const auto& d : cl)
    for (int a : d)
      for (int b : d) trip.emplace_back(a, b, 0.0);
  auto& S = pattern.matrix;
  S.resize(model.num_dofs, model.num_dofs);
  S.setFromTriplets(trip.begin(), trip.end());
  S.makeCompressed();
  pattern.offsets.resize(cl.size());
  const int* outer = S.outerIndexPtr();
  const int* inner = S.innerIndexPtr();
  for (std::size_t c = 0; c < cl.size(); ++c) {
    const auto& d = cl[c];
    const auto nc = d.size();
    auto& off = pattern.offsets[c];
    off.resize(nc * nc);
    for (std::size_t b = 0; b < nc; ++b) {
      const int* beg = inner + outer[d[b]];
      const int* end = inner + outer[d[b] + 1];
      for (std::size_t a = 0; a < nc; ++a) {
        const int* it = std::lower_bound(beg, end, d[a]);
        SEFLEX_DEMAND(it != end && *it == d[a], "pattern entry missing");
        off[a + nc * b] = static_cast<int>(it - inner);
      }
    }
  }
  const auto nnz = static_cast<std::size_t>(S.nonZeros());
  K.assign(nnz, 0.0);
  C.assign(nnz, 0.0);
  M.assign(nnz, 0.0);
  S_flex.assign(nnz, 0.0);
  // The rotation triples among every node's Jacobian columns: a Free node's three rotation dofs are
  // consecutive dofs, and an Attached node copies its parent's columns in order (ModelBuilder::build).
  node_rotation_triples.resize(model.nodes.size());
  for (std::size_t k = 0; k < model.nodes.size(); ++k) {
    const auto& dofs = model.node_dofs[k];
    for (std::size_t r = 0; r < model.rotation_dof_starts.size(); ++r) {
      const auto it = std::find(dofs.begin(), dofs.end(), model.rotation_dof_starts[r]);
      if (it == dofs.end()) continue;
      const auto c0 = it - dofs.begin();
      SEFLEX_DEMAND(c0 + 2 < static_cast<std::ptrdiff_t>(dofs.size()) && dofs[static_cast<std::size_t>(c0 + 1)] == *it + 1 &&
                        dofs[static_cast<std::size_t>(c0 + 2)] == *it + 2,
                    "a node's Jacobian holds a Free node's rotation dofs as three consecutive columns");
      node_rotation_triples[k].push_back({static_cast<int>(c0), static_cast<int>(r)});
    }
  }
}

bool Data::factorize(const Eigen::SparseMatrix<double>& S) {
  if (S.rows() <= kDenseDofs) {
    dense_.setZero(S.rows(), S.cols());
    for (int c = 0; c < S.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(S, c); it; ++it) dense_(it.row(), it.col()) = it.value();
    dense_lu_.compute(dense_);
    // PartialPivLU does not report singularity: a zero or non-finite pivot (relative to the largest
    // entry) marks it.
    const double largest = dense_.cwiseAbs().maxCoeff();
    const auto pivots = dense_lu_.matrixLU().diagonal().cwiseAbs();
    return std::isfinite(pivots.sum()) && pivots.minCoeff() > 1e-14 * largest;
  }
  if (!analyzed_) {
    lu_.analyzePattern(S);
    analyzed_ = true;
  }
  lu_.factorize(S);
  return lu_.info() == Eigen::Success;
}

void Data::solve_negated(const Eigen::VectorXd& r, Eigen::VectorXd& x) const {
  if (r.size() <= kDenseDofs)
    x = dense_lu_.solve(r);
  else
    x = lu_.solve(r);
  x = -x;
}

}  // namespace seflex::mbd
