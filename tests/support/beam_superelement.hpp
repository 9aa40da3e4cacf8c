#pragma once
// Test-only dense Craig-Bampton builder for small 3D frames of Euler-Bernoulli beams, mirroring
// ../shared/reference/aic_verify.py (beam_k, beam_m, element axes, constraint modes). It stands in
// for reduction/ until that library is on main; every number it produces is checked in
// aic_kernel_test.cpp against identities that hold for any correct Craig-Bampton reduction.
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "seflex/common/so3.hpp"
#include "seflex/superelement/superelement.hpp"

namespace seflex::test {

struct BeamSection {
  double E = 7e10, G = 7e10 / 2.6, A = 1e-4, Iy = 1e-9, Iz = 2e-9, J = 3e-9, rho = 2700;
};

struct FrameFE {
  std::vector<Eigen::Vector3d> pts;
  std::vector<std::pair<int, int>> elements;
  BeamSection section;
  bool consistent_mass = false;          ///< consistent beam mass; else lumped as aic_verify.py
  std::vector<double> point_masses;      ///< optional extra translational mass per node
  Eigen::MatrixXd K, M;                  ///< assembled (6 dofs per node), filled by assemble()

  int nodes() const { return static_cast<int>(pts.size()); }
};

inline Eigen::Matrix<double, 12, 12> beam_k(const BeamSection& s, double L) {
  Eigen::Matrix<double, 12, 12> k = Eigen::Matrix<double, 12, 12>::Zero();
  const double a = s.E * s.A / L, t = s.G * s.J / L;
  k(0, 0) = k(6, 6) = a;
  k(0, 6) = k(6, 0) = -a;
  k(3, 3) = k(9, 9) = t;
  k(3, 9) = k(9, 3) = -t;
  const int idx[2][4] = {{1, 5, 7, 11}, {2, 4, 8, 10}};
  const double I[2] = {s.Iz, s.Iy}, sg[2] = {1.0, -1.0};
  for (int p = 0; p < 2; ++p) {
    const double c = s.E * I[p] / (L * L * L), q = sg[p];
    const double kb[4][4] = {{12, q * 6 * L, -12, q * 6 * L},
                             {q * 6 * L, 4 * L * L, -q * 6 * L, 2 * L * L},
                             {-12, -q * 6 * L, 12, -q * 6 * L},
                             {q * 6 * L, 2 * L * L, -q * 6 * L, 4 * L * L}};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) k(idx[p][i], idx[p][j]) += c * kb[i][j];
  }
  return k;
}

inline Eigen::Matrix<double, 12, 12> beam_m(const BeamSection& s, double L, bool consistent) {
  Eigen::Matrix<double, 12, 12> m = Eigen::Matrix<double, 12, 12>::Zero();
  const double mA = s.rho * s.A * L;
  if (!consistent) {
    const double mm = mA / 2;
    for (int i : {0, 1, 2, 6, 7, 8}) m(i, i) = mm;
    for (int i : {3, 9}) m(i, i) = s.rho * s.J * L / 2;
    for (int i : {4, 5, 10, 11}) m(i, i) = mm * L * L / 50;
    return m;
  }
  m(0, 0) = m(6, 6) = mA / 3;
  m(0, 6) = m(6, 0) = mA / 6;
  const double mt = s.rho * s.J * L;
  m(3, 3) = m(9, 9) = mt / 3;
  m(3, 9) = m(9, 3) = mt / 6;
  const int idx[2][4] = {{1, 5, 7, 11}, {2, 4, 8, 10}};
  const double sg[2] = {1.0, -1.0};
  for (int p = 0; p < 2; ++p) {
    const double q = sg[p], c = mA / 420;
    const double mb[4][4] = {{156, q * 22 * L, 54, -q * 13 * L},
                             {q * 22 * L, 4 * L * L, q * 13 * L, -3 * L * L},
                             {54, q * 13 * L, 156, -q * 22 * L},
                             {-q * 13 * L, -3 * L * L, -q * 22 * L, 4 * L * L}};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) m(idx[p][i], idx[p][j]) += c * mb[i][j];
  }
  return m;
}

inline Eigen::Matrix3d elem_axes(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) {
  const Eigen::Vector3d ex = (p2 - p1).normalized();
  const Eigen::Vector3d tmp = std::abs(ex.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d ey = tmp.cross(ex).normalized();
  const Eigen::Vector3d ez = ex.cross(ey);
  Eigen::Matrix3d T;
  T.row(0) = ex;
  T.row(1) = ey;
  T.row(2) = ez;
  return T;
}

inline void assemble(FrameFE& fe) {
  const int nd = 6 * fe.nodes();
  fe.K = Eigen::MatrixXd::Zero(nd, nd);
  fe.M = Eigen::MatrixXd::Zero(nd, nd);
  for (const auto& [a, b] : fe.elements) {
    const double L = (fe.pts[b] - fe.pts[a]).norm();
    Eigen::Matrix<double, 12, 12> T = Eigen::Matrix<double, 12, 12>::Zero();
    const Eigen::Matrix3d R = elem_axes(fe.pts[a], fe.pts[b]);
    for (int i = 0; i < 4; ++i) T.block<3, 3>(3 * i, 3 * i) = R;
    const Eigen::Matrix<double, 12, 12> ke = T.transpose() * beam_k(fe.section, L) * T;
    const Eigen::Matrix<double, 12, 12> me = T.transpose() * beam_m(fe.section, L, fe.consistent_mass) * T;
    const int d[2] = {6 * a, 6 * b};
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        fe.K.block<6, 6>(d[i], d[j]) += ke.block<6, 6>(6 * i, 6 * j);
        fe.M.block<6, 6>(d[i], d[j]) += me.block<6, 6>(6 * i, 6 * j);
      }
  }
  for (std::size_t i = 0; i < fe.point_masses.size(); ++i) fe.M.block<3, 3>(6 * i, 6 * i) += fe.point_masses[i] * Eigen::Matrix3d::Identity();
}

/// Rigid-body modes of all FE nodes about `origin` (6 n x 6).
inline Eigen::MatrixXd fe_rigid_modes(const FrameFE& fe, const Eigen::Vector3d& origin) {
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(6 * fe.nodes(), 6);
  for (int i = 0; i < fe.nodes(); ++i) {
    P.block<3, 3>(6 * i, 0).setIdentity();
    P.block<3, 3>(6 * i, 3) = -so3::skew(fe.pts[i] - origin);
    P.block<3, 3>(6 * i + 3, 3).setIdentity();
  }
  return P;
}

/// Craig-Bampton superelement of `fe` (assembled on demand) with interface nodes `ifn` (in order),
/// floating frame at node `f`, and the first `modes` fixed-interface modes.
inline se::Superelement craig_bampton(FrameFE& fe, const std::vector<int>& ifn, int f, int modes = 0,
                                      const std::string& name = "beam") {
  if (fe.K.size() == 0) assemble(fe);
  const int nn = fe.nodes(), nd = 6 * nn, N = static_cast<int>(ifn.size());
  std::vector<int> b, ii;
  for (int n : ifn)
    for (int k = 0; k < 6; ++k) b.push_back(6 * n + k);
  for (int d = 0; d < nd; ++d)
    if (std::find(b.begin(), b.end(), d) == b.end()) ii.push_back(d);
  const int ni = static_cast<int>(ii.size());
  auto sub = [](const Eigen::MatrixXd& A, const std::vector<int>& r, const std::vector<int>& c) {
    Eigen::MatrixXd S(r.size(), c.size());
    for (std::size_t i = 0; i < r.size(); ++i)
      for (std::size_t j = 0; j < c.size(); ++j) S(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = A(r[i], c[j]);
    return S;
  };
  const Eigen::MatrixXd Kii = sub(fe.K, ii, ii), Kib = sub(fe.K, ii, b), Mii = sub(fe.M, ii, ii);
  const Eigen::MatrixXd X = -Kii.ldlt().solve(Kib);
  const int n = 6 * N + modes;
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(nd, n);
  for (int k = 0; k < 6 * N; ++k) T(b[static_cast<std::size_t>(k)], k) = 1.0;
  for (int r = 0; r < ni; ++r) T.row(ii[static_cast<std::size_t>(r)]).head(6 * N) = X.row(r);
  Eigen::VectorXd freq;
  if (modes > 0) {
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(Kii, Mii);
    freq = es.eigenvalues().head(modes).cwiseMax(0.0).cwiseSqrt() / (2 * M_PI);
    for (int k = 0; k < modes; ++k) {
      Eigen::VectorXd phi = es.eigenvectors().col(k);
      phi /= std::sqrt(phi.dot(Mii * phi));
      for (int r = 0; r < ni; ++r) T(ii[static_cast<std::size_t>(r)], 6 * N + k) = phi[r];
    }
  }
  se::Superelement s;
  s.name = name;
  s.frame_node_id = f + 1;
  s.p_OBo = fe.pts[f];
  for (int j = 0; j < N; ++j) {
    se::InterfaceNode itf;
    itf.id = ifn[static_cast<std::size_t>(j)] + 1;
    itf.p_BoN_B = fe.pts[ifn[static_cast<std::size_t>(j)]] - fe.pts[f];
    s.interfaces.push_back(itf);
  }
  s.num_modes = modes;
  s.mode_frequencies_hz = modes > 0 ? freq : Eigen::VectorXd();
  s.K = T.transpose() * fe.K * T;
  s.M = T.transpose() * fe.M * T;
  s.K = 0.5 * (s.K + s.K.transpose()).eval();
  s.M = 0.5 * (s.M + s.M.transpose()).eval();
  s.Phi_f = T.middleRows(6 * f, 6);
  const Eigen::MatrixXd Pr = fe_rigid_modes(fe, fe.pts[f]);
  const Eigen::MatrixXd M0 = Pr.transpose() * fe.M * Pr;
  s.mass = M0(0, 0);
  s.p_BoCm_B = so3::vee(M0.block<3, 3>(3, 0)) / s.mass;
  const Eigen::Matrix3d cx = so3::skew(s.p_BoCm_B);
  s.I_Cm_B = M0.block<3, 3>(3, 3) + s.mass * cx * cx;
  for (int i = 0; i < nn; ++i) s.fe_node_ids.push_back(i + 1);
  s.p_BoI_B.resize(3, nn);
  for (int i = 0; i < nn; ++i) s.p_BoI_B.col(i) = fe.pts[i] - fe.pts[f];
  s.recovery = T;
  s.M_fe = fe.M.sparseView();
  for (int e = 0; e < static_cast<int>(fe.elements.size()); ++e) {
    se::MeshCell c;
    c.type = se::MeshCell::Type::Line;
    c.nodes = {fe.elements[e].first, fe.elements[e].second, -1, -1};
    c.element_id = e + 1;
    s.cells.push_back(c);
  }
  return s;
}

/// A straight beam from the origin along `dir` of length L with `ne` elements; interfaces at both
/// ends, frame at node `frame` (default: the middle node).
inline FrameFE straight_beam(double L, int ne, const BeamSection& sec, const Eigen::Vector3d& dir = Eigen::Vector3d::UnitX(),
                             bool consistent = true) {
  FrameFE fe;
  fe.section = sec;
  fe.consistent_mass = consistent;
  for (int i = 0; i <= ne; ++i) fe.pts.push_back(dir.normalized() * (L * i / ne));
  for (int i = 0; i < ne; ++i) fe.elements.emplace_back(i, i + 1);
  return fe;
}

/// The 9-node L-shaped spatial frame of aic_verify.py (interfaces 0, 8, 6; frame node 3).
inline FrameFE l_frame() {
  FrameFE fe;
  for (int i = 0; i < 5; ++i) fe.pts.emplace_back(0.25 * i, 0, 0);
  for (int i = 1; i < 5; ++i) fe.pts.emplace_back(1.0, 0.2 * i, 0.1 * i);
  for (int i = 0; i + 1 < fe.nodes(); ++i) fe.elements.emplace_back(i, i + 1);
  return fe;
}

}  // namespace seflex::test
