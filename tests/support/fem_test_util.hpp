#pragma once
// Helpers of the fem tests: build models in code, finalize them for the tests, and solve small
// static and eigen problems with Eigen's own dense/sparse direct solvers (the production solvers
// live in reduction/).
#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "seflex/fem/finalize.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem::test {

/// Finalize a model written in code: GRDSET PS applied to grids without PS (the reader's job for
/// decks), then fem::finalize (lookups, coordinate systems, reference checks).
inline void finalize_for_test(Model& m) {
  if (m.files.empty()) m.files.push_back("test.bdf");
  for (Grid& g : m.grids)
    if (g.ps == 0 && m.grdset.present) g.ps = m.grdset.ps;
  finalize(m);
}

/// CORD2R `id` with the given origin and axes (columns, in basic).
inline CoordSys& add_rect_coord(Model& m, int id, const Eigen::Vector3d& origin, const Eigen::Matrix3d& axes) {
  CoordSys c;
  c.id = id;
  c.type = CoordType::Rectangular;
  const Eigen::Vector3d a = origin, b = origin + axes.col(2), cc = origin + axes.col(0);
  c.abc = {a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), cc.x(), cc.y(), cc.z()};
  m.coords.push_back(c);
  return m.coords.back();
}

inline Grid& add_grid(Model& m, int id, double x, double y, double z, int cd = 0, ComponentMask ps = 0) {
  Grid g;
  g.id = id;
  g.x = Eigen::Vector3d(x, y, z);
  g.cd = cd;
  g.ps = ps;
  m.grids.push_back(g);
  return m.grids.back();
}

inline Mat1& add_mat1(Model& m, int id, double E, double nu, double rho) {
  Mat1 mat;
  mat.id = id;
  mat.E = E;
  mat.nu = nu;
  mat.G = E / (2 * (1 + nu));
  mat.rho = rho;
  m.mat1.push_back(mat);
  return m.mat1.back();
}

inline BarProperty& add_pbar(Model& m, int id, int mid, double A, double I1, double I2, double J, double nsm = 0) {
  BarProperty p;
  p.id = id;
  p.mid = mid;
  p.A = A;
  p.I1 = I1;
  p.I2 = I2;
  p.J = J;
  p.nsm = nsm;
  m.bar_props.push_back(p);
  return m.bar_props.back();
}

inline Bar& add_cbar(Model& m, int id, int pid, int ga, int gb, const Eigen::Vector3d& v) {
  Bar b;
  b.id = id;
  b.pid = pid;
  b.ga = ga;
  b.gb = gb;
  b.v = v;
  m.bars.push_back(b);
  return m.bars.back();
}

inline ShellProperty& add_pshell(Model& m, int id, int mid, double t, bool shear = true, double nsm = 0) {
  ShellProperty p;
  p.id = id;
  p.mid1 = mid;
  p.t = t;
  p.mid2 = mid;
  p.mid3 = shear ? mid : 0;
  p.nsm = nsm;
  m.shell_props.push_back(p);
  return m.shell_props.back();
}

inline Shell& add_shell(Model& m, int id, int pid, std::initializer_list<int> g) {
  Shell s;
  s.id = id;
  s.pid = pid;
  s.nnode = static_cast<std::uint8_t>(g.size());
  int k = 0;
  for (int v : g) s.g[k++] = v;
  m.shells.push_back(s);
  return m.shells.back();
}

/// CONROD between grids ga and gb.
inline Rod& add_conrod(Model& m, int id, int ga, int gb, int mid, double A, double nsm = 0) {
  Rod r;
  r.id = id;
  r.ga = ga;
  r.gb = gb;
  r.inline_property = true;
  r.mid = mid;
  r.A = A;
  r.nsm = nsm;
  m.rods.push_back(r);
  return m.rods.back();
}

/// CONM2 at `grid` (CID 0, no offset or inertia unless set on the result).
inline Conm2& add_conm2(Model& m, int id, int grid, double mass) {
  Conm2 c;
  c.id = id;
  c.grid = grid;
  c.m = mass;
  m.conm2.push_back(c);
  return m.conm2.back();
}

/// CELAS2 of stiffness k between component c1 of g1 and c2 of g2 (g2 = 0: grounded).
inline Spring& add_celas2(Model& m, int id, int g1, int c1, double k, int g2 = 0, int c2 = 0) {
  Spring s;
  s.id = id;
  s.inline_property = true;
  s.k = k;
  s.g1 = g1;
  s.c1 = c1;
  s.g2 = g2;
  s.c2 = c2;
  m.springs.push_back(s);
  return m.springs.back();
}

inline void add_param(Model& m, const std::string& name, const std::string& value) {
  Param p;
  p.name = name;
  p.values = {value};
  m.params.push_back(p);
}

inline void add_spc1(Model& m, int sid, ComponentMask c, int grid) {
  SpcEntry e;
  e.sid = sid;
  e.grid = grid;
  e.c = c;
  m.spcs.push_back(e);
}

inline ComponentMask mask(const std::string& digits) {
  ComponentMask c = 0;
  for (char ch : digits) c |= static_cast<ComponentMask>(1u << (ch - '1'));
  return c;
}

/// RBE2 `id`: the dependent grids `gm` follow the independent grid `gn` in components `cm` ("123456").
inline Rbe2& add_rbe2(Model& m, int id, int gn, const std::string& cm, std::vector<int> gm) {
  Rbe2 r;
  r.id = id;
  r.gn = gn;
  r.cm = mask(cm);
  r.gm = std::move(gm);
  m.rbe2.push_back(r);
  return m.rbe2.back();
}

/// Null-space dimension of a symmetric matrix: eigenvalues below tol * largest.
inline int null_space_dimension(const Eigen::MatrixXd& K, double tol = 1e-9) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(K);
  const double top = es.eigenvalues().cwiseAbs().maxCoeff();
  int n = 0;
  for (int i = 0; i < es.eigenvalues().size(); ++i) n += std::abs(es.eigenvalues()[i]) <= tol * top;
  return n;
}

/// All eigenvalues (ascending) of K x = lambda M x for SPD K and PSD M (dense, small problems):
/// the eigenvalues mu of L^-1 M L^-T, lambda = 1/mu - shift with K + shift M = L L^T. Infinite
/// eigenvalues (massless dofs) are dropped.
inline std::vector<double> dense_eigenvalues(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, double shift = 0.0) {
  const Eigen::LLT<Eigen::MatrixXd> llt(K + shift * M);
  Eigen::MatrixXd C = llt.matrixL().solve(M);
  C = llt.matrixL().solve(C.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (C + C.transpose()));
  std::vector<double> lam;
  const double top = es.eigenvalues().maxCoeff();
  for (int i = 0; i < es.eigenvalues().size(); ++i)
    if (es.eigenvalues()[i] > 1e-12 * top) lam.push_back(1.0 / es.eigenvalues()[i] - shift);
  std::sort(lam.begin(), lam.end());
  return lam;
}

/// Lowest `nev` eigenvalues of K x = lambda M x for sparse SPD K (subspace iteration with
/// Rayleigh-Ritz, Bathe, Finite Element Procedures, sec. 11.6), converged to `tol` relative.
inline std::vector<double> lowest_eigenvalues(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                                              int nev, double tol = 1e-10) {
  const Eigen::Index n = K.rows();
  const int p = std::min<int>(static_cast<int>(n), 2 * nev + 8);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(K);
  Eigen::MatrixXd X = Eigen::MatrixXd::Random(n, p);
  std::vector<double> prev(nev, 0.0), lam(nev, 0.0);
  for (int it = 0; it < 300; ++it) {
    Eigen::MatrixXd Y = ldlt.solve(M * X);
    const Eigen::MatrixXd Kr = Y.transpose() * (K * Y), Mr = Y.transpose() * (M * Y);
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (Kr + Kr.transpose()),
                                                                      0.5 * (Mr + Mr.transpose()));
    X = Y * es.eigenvectors();
    for (int i = 0; i < nev; ++i) lam[i] = es.eigenvalues()[i];
    bool done = it > 2;
    for (int i = 0; i < nev; ++i) done = done && std::abs(lam[i] - prev[i]) <= tol * std::abs(lam[i]);
    if (done) break;
    prev = lam;
  }
  return lam;
}

inline Eigen::MatrixXd dense(const Eigen::SparseMatrix<double>& A) { return Eigen::MatrixXd(A); }

}  // namespace seflex::fem::test
