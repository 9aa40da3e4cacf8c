#pragma once
// FE models built in code for the Craig-Bampton tests, and independent dense references.
#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "fem_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"

namespace seflex::cbtest {

using namespace fem::test;

/// A free-free box frame 1.0 x 0.6 x 0.4 (m): 8 corner grids 1-8 and a mid-edge grid on each of the
/// 12 edges (ids 11-22), 24 CBARs of a tube-like section with density (lumped: translational mass
/// only), CONM2s with rotary inertia on corners 2, 4, 5 (one with an offset), and grid 30 carried by
/// RBE2 401 on corner 6 with a CONM2 of its own. Grid 3 has its displacements in a rotated
/// rectangular system (CD = 7) so the reduction has to turn its dofs to basic. PARAM WTMASS 0.5
/// makes the analysis mass half the deck's numbers. With `coupled`, PARAM COUPMASS 1.
inline fem::Model box_frame(bool coupled = false) {
  fem::Model m;
  const double X[8][3] = {{0, 0, 0},   {1, 0, 0},   {1, 0.6, 0},   {0, 0.6, 0},
                          {0, 0, 0.4}, {1, 0, 0.4}, {1, 0.6, 0.4}, {0, 0.6, 0.4}};
  for (int i = 0; i < 8; ++i) add_grid(m, i + 1, X[i][0], X[i][1], X[i][2]);
  m.grids[2].cd = 7;
  add_rect_coord(m, 7, Eigen::Vector3d(0.3, -0.2, 0.1),
                 Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix());
  add_mat1(m, 1, 7.0e10, 0.3, 2700.0);
  add_pbar(m, 1, 1, 3.0e-4, 2.0e-8, 3.0e-8, 4.0e-8);
  const int edges[12][2] = {{1, 2}, {2, 3}, {3, 4}, {4, 1}, {5, 6}, {6, 7},
                            {7, 8}, {8, 5}, {1, 5}, {2, 6}, {3, 7}, {4, 8}};
  int bar = 100;
  for (int e = 0; e < 12; ++e) {
    const int a = edges[e][0], b = edges[e][1], mid = 11 + e;
    const Eigen::Vector3d xa(X[a - 1][0], X[a - 1][1], X[a - 1][2]), xb(X[b - 1][0], X[b - 1][1], X[b - 1][2]);
    const Eigen::Vector3d xm = 0.5 * (xa + xb);
    add_grid(m, mid, xm.x(), xm.y(), xm.z());
    const Eigen::Vector3d axis = (xb - xa).normalized();
    const Eigen::Vector3d v = std::abs(axis.z()) > 0.9 ? Eigen::Vector3d(1, 0, 0) : Eigen::Vector3d(0, 0, 1);
    add_cbar(m, bar++, 1, a, mid, v);
    add_cbar(m, bar++, 1, mid, b, v);
  }
  add_grid(m, 30, 1.1, 0.05, 0.45);
  add_rbe2(m, 401, 6, "123456", {30});
  auto conm2 = [&](int id, int grid, double mass, Eigen::Vector3d offset, double I) {
    fem::Conm2 c;
    c.id = id;
    c.grid = grid;
    c.m = mass;
    c.x = offset;
    c.I11 = I;
    c.I22 = 1.5 * I;
    c.I33 = 0.7 * I;
    c.I21 = 0.1 * I;
    m.conm2.push_back(c);
  };
  conm2(901, 2, 1.2, Eigen::Vector3d::Zero(), 2e-3);
  conm2(902, 4, 0.8, Eigen::Vector3d(0.02, -0.01, 0.03), 1e-3);
  conm2(903, 5, 0.5, Eigen::Vector3d::Zero(), 5e-4);
  conm2(904, 30, 0.9, Eigen::Vector3d::Zero(), 8e-4);
  m.params.push_back(fem::Param{"WTMASS", {"0.5"}, {}});
  if (coupled) m.params.push_back(fem::Param{"COUPMASS", {"1"}, {}});
  finalize_for_test(m);
  return m;
}

/// K_ff and M_ff of a model with its case-control SPC set, as dense matrices.
struct DenseSystem {
  fem::GlobalMatrices g;
  fem::ConstrainedSystem c;
  Eigen::MatrixXd K, M;
};
inline DenseSystem dense_system(const fem::Model& m) {
  DenseSystem d;
  d.g = fem::assemble(m, fem::assembly_options(m));
  d.c = fem::apply_constraints(m, d.g, m.case_control.global.spc);
  d.K = Eigen::MatrixXd(d.c.K_ff);
  d.M = Eigen::MatrixXd(d.c.M_ff);
  return d;
}

/// All finite eigenpairs of (K, M), K positive definite, M positive semi-definite, dense:
/// C = L^-1 M L^-T (K = L L^T), C z = mu z, lambda = 1/mu, x = L^-T z / sqrt(mu) (x^T M x = 1).
struct DenseModes {
  Eigen::VectorXd lambda;
  Eigen::MatrixXd X;
};
inline DenseModes dense_modes(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M) {
  const Eigen::LLT<Eigen::MatrixXd> llt(K);
  Eigen::MatrixXd C = llt.matrixL().solve(M);
  C = llt.matrixL().solve(C.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (C + C.transpose()));
  const double top = es.eigenvalues().maxCoeff();
  std::vector<int> keep;
  for (int i = static_cast<int>(es.eigenvalues().size()) - 1; i >= 0; --i)
    if (es.eigenvalues()(i) > 1e-12 * top) keep.push_back(i);
  DenseModes r;
  r.lambda.resize(static_cast<Eigen::Index>(keep.size()));
  r.X.resize(K.rows(), static_cast<Eigen::Index>(keep.size()));
  for (std::size_t k = 0; k < keep.size(); ++k) {
    const double mu = es.eigenvalues()(keep[k]);
    r.lambda(static_cast<Eigen::Index>(k)) = 1.0 / mu;
    r.X.col(static_cast<Eigen::Index>(k)) = llt.matrixU().solve(es.eigenvectors().col(keep[k])) / std::sqrt(mu);
  }
  return r;
}

}  // namespace seflex::cbtest
