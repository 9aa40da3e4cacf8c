#pragma once
// Eigenproblems built in code with known answers, for the solver tests of tests/reduction/.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <cmath>
#include <numbers>
#include <vector>

namespace seflex::test {

using Sparse = Eigen::SparseMatrix<double>;
using Triplets = std::vector<Eigen::Triplet<double>>;

struct Pencil {
  Sparse K, M;
};

inline Sparse from_triplets(Eigen::Index n, const Triplets& t) {
  Sparse A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

inline void add_spring(Triplets& t, int i, int j, double k) {  // j < 0: grounded
  t.emplace_back(i, i, k);
  if (j < 0) return;
  t.emplace_back(j, j, k);
  t.emplace_back(i, j, -k);
  t.emplace_back(j, i, -k);
}

/// n equal masses m joined by n+1 equal springs k, both ends fixed (fixed_fixed) or both free.
/// Eigenvalues (e.g. Strang, Computational Science and Engineering, 1.5 / 2.2):
///   fixed-fixed  lambda_j = (4k/m) sin^2(j pi / (2(n+1))), j = 1..n
///   free-free    lambda_j = (4k/m) sin^2(j pi / (2n)),     j = 0..n-1 (j = 0: rigid translation)
inline Pencil spring_chain(int n, double k, double m, bool fixed_fixed) {
  Triplets kt, mt;
  for (int i = 0; i < n; ++i) mt.emplace_back(i, i, m);
  for (int i = 0; i + 1 < n; ++i) add_spring(kt, i, i + 1, k);
  if (fixed_fixed) {
    add_spring(kt, 0, -1, k);
    add_spring(kt, n - 1, -1, k);
  }
  return {from_triplets(n, kt), from_triplets(n, mt)};
}
inline double chain_eigenvalue(int n, double k, double m, bool fixed_fixed, int j) {
  const double s = std::sin(j * std::numbers::pi / (2.0 * (fixed_fixed ? n + 1 : n)));
  return 4.0 * k / m * s * s;
}

/// The fixed-fixed chain again, with a massless node in the middle of every spring (springs 2k on
/// each side): condensing the massless nodes gives back springs k in series, so the eigenvalues are
/// those of spring_chain(n, k, m, true), while M is singular (n of 2n+1 dofs carry mass).
inline Pencil chain_with_massless_nodes(int n, double k, double m) {
  const int dofs = 2 * n + 1;  // massless, mass, massless, ..., mass, massless
  Triplets kt, mt;
  for (int i = 0; i < n; ++i) mt.emplace_back(2 * i + 1, 2 * i + 1, m);
  for (int i = 0; i + 1 < dofs; ++i) add_spring(kt, i, i + 1, 2 * k);
  add_spring(kt, 0, -1, 2 * k);
  add_spring(kt, dofs - 1, -1, 2 * k);
  return {from_triplets(dofs, kt), from_triplets(dofs, mt)};
}

/// Five-point Laplacian on an N x N grid with Dirichlet boundary, M = I. Eigenvalues
/// lambda_pq = 4 sin^2(p pi / (2(N+1))) + 4 sin^2(q pi / (2(N+1))): pairs (p, q), (q, p) are double.
inline Pencil laplacian_plate(int N) {
  Triplets kt, mt;
  auto id = [N](int i, int j) { return i * N + j; };
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      kt.emplace_back(id(i, j), id(i, j), 4.0);
      mt.emplace_back(id(i, j), id(i, j), 1.0);
      if (i + 1 < N) kt.emplace_back(id(i, j), id(i + 1, j), -1.0), kt.emplace_back(id(i + 1, j), id(i, j), -1.0);
      if (j + 1 < N) kt.emplace_back(id(i, j), id(i, j + 1), -1.0), kt.emplace_back(id(i, j + 1), id(i, j), -1.0);
    }
  return {from_triplets(N * N, kt), from_triplets(N * N, mt)};
}
inline std::vector<double> laplacian_plate_eigenvalues(int N) {
  std::vector<double> ev;
  for (int p = 1; p <= N; ++p)
    for (int q = 1; q <= N; ++q) {
      const double a = std::sin(p * std::numbers::pi / (2.0 * (N + 1))), b = std::sin(q * std::numbers::pi / (2.0 * (N + 1)));
      ev.push_back(4 * a * a + 4 * b * b);
    }
  std::sort(ev.begin(), ev.end());
  return ev;
}

/// A free-floating 3-D truss: an nx x ny x nz lattice of nodes (3 dofs each) with springs along
/// every edge, face diagonal and body diagonal of each cell (a rigid lattice), lumped masses on the
/// nodes of even i + j + k and none on the others (so M is singular). Exactly six zero modes.
struct Truss {
  Pencil pencil;
  Eigen::MatrixXd rigid_modes;  ///< 3N x 6: translations x, y, z and small rotations about x, y, z
};
inline Truss free_truss(int nx, int ny, int nz, double k, double m) {
  auto id = [&](int i, int j, int l) { return (i * ny + j) * nz + l; };
  const int N = nx * ny * nz;
  std::vector<Eigen::Vector3d> x(static_cast<std::size_t>(N));
  Triplets kt, mt;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int l = 0; l < nz; ++l) {
        x[static_cast<std::size_t>(id(i, j, l))] = Eigen::Vector3d(i, j, 1.3 * l);
        if ((i + j + l) % 2 == 0)
          for (int c = 0; c < 3; ++c) mt.emplace_back(3 * id(i, j, l) + c, 3 * id(i, j, l) + c, m);
      }
  auto bar = [&](int a, int b) {
    const Eigen::Vector3d e = (x[static_cast<std::size_t>(b)] - x[static_cast<std::size_t>(a)]).normalized();
    const Eigen::Matrix3d kb = k * e * e.transpose();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        kt.emplace_back(3 * a + r, 3 * a + c, kb(r, c));
        kt.emplace_back(3 * b + r, 3 * b + c, kb(r, c));
        kt.emplace_back(3 * a + r, 3 * b + c, -kb(r, c));
        kt.emplace_back(3 * b + r, 3 * a + c, -kb(r, c));
      }
  };
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int l = 0; l < nz; ++l)
        for (int di = 0; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj)
            for (int dl = -1; dl <= 1; ++dl) {
              if (di == 0 && (dj < 0 || (dj == 0 && dl <= 0))) continue;  // each pair once
              const int i2 = i + di, j2 = j + dj, l2 = l + dl;
              if (i2 >= nx || j2 < 0 || j2 >= ny || l2 < 0 || l2 >= nz) continue;
              bar(id(i, j, l), id(i2, j2, l2));
            }
  Truss t{{from_triplets(3 * N, kt), from_triplets(3 * N, mt)}, Eigen::MatrixXd::Zero(3 * N, 6)};
  for (int a = 0; a < N; ++a) {
    const Eigen::Vector3d& p = x[static_cast<std::size_t>(a)];
    t.rigid_modes.block(3 * a, 0, 3, 3).setIdentity();
    // rotation about axis c: u = e_c x p
    for (int c = 0; c < 3; ++c) t.rigid_modes.block(3 * a, 3 + c, 3, 1) = Eigen::Vector3d::Unit(c).cross(p);
  }
  return t;
}

/// Euler-Bernoulli beam bending in one plane: nodes 0..ne, dofs (w, theta) per node, elements of
/// length L = length/ne with the standard cubic stiffness (EI/L^3)[12 6L -12 6L; ...]; lumped
/// translational mass rho A L / 2 per element end and no rotary inertia (Nastran's default lumped
/// CBAR mass, so M is singular). clamped: node 0 fixed (its two dofs removed).
inline Pencil lumped_beam(int ne, double length, double EI, double mass_per_length, bool clamped) {
  const double L = length / ne;
  Eigen::Matrix4d ke;
  ke << 12, 6 * L, -12, 6 * L, 6 * L, 4 * L * L, -6 * L, 2 * L * L, -12, -6 * L, 12, -6 * L, 6 * L, 2 * L * L, -6 * L,
      4 * L * L;
  ke *= EI / (L * L * L);
  const int first = clamped ? 2 : 0;  // dofs of node 0 removed when clamped
  const int n = 2 * (ne + 1) - first;
  Triplets kt, mt;
  for (int e = 0; e < ne; ++e)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const int ga = 2 * e + a - first, gb = 2 * e + b - first;
        if (ga >= 0 && gb >= 0) kt.emplace_back(ga, gb, ke(a, b));
      }
  for (int node = 0; node <= ne; ++node) {
    const int g = 2 * node - first;
    if (g < 0) continue;
    const double share = (node == 0 || node == ne) ? 0.5 : 1.0;
    mt.emplace_back(g, g, share * mass_per_length * L);
  }
  return {from_triplets(n, kt), from_triplets(n, mt)};
}

/// Reference solution independent of the library: massless dofs condensed exactly (Guyan), then
/// Eigen's dense generalised solver on the mass-carrying dofs. Ascending eigenvalues.
inline Eigen::VectorXd condensed_reference_eigenvalues(const Pencil& p) {
  const Eigen::MatrixXd K(p.K), M(p.M);
  std::vector<int> a, o;
  for (int i = 0; i < K.rows(); ++i) (M.row(i).cwiseAbs().sum() > 0 ? a : o).push_back(i);
  auto block = [](const Eigen::MatrixXd& A, const std::vector<int>& r, const std::vector<int>& c) {
    Eigen::MatrixXd B(r.size(), c.size());
    for (std::size_t i = 0; i < r.size(); ++i)
      for (std::size_t j = 0; j < c.size(); ++j) B(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = A(r[i], c[j]);
    return B;
  };
  Eigen::MatrixXd Kc = block(K, a, a);
  if (!o.empty()) Kc -= block(K, a, o) * block(K, o, o).ldlt().solve(block(K, o, a));
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (Kc + Kc.transpose()), block(M, a, a));
  return eig.eigenvalues();
}

}  // namespace seflex::test
