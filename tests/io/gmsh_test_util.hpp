#pragma once
// Helpers of the gmsh and convert tests: free-free frequencies of a model and exact comparison of
// assembled matrices.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/linalg/eigensolver.hpp"
#include "test_support.hpp"

namespace seflex::test {

inline std::filesystem::path meshes_dir() { return source_dir() / "meshes"; }

/// Lowest `count` natural frequencies (Hz) of a model without SPCs (free-free; AUTOSPC on).
inline Eigen::VectorXd free_frequencies(const fem::Model& m, int count) {
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  const fem::ConstrainedSystem c = fem::apply_constraints(m, g, std::nullopt);
  linalg::EigenOptions o;
  o.count = count;
  const linalg::EigenSolution s = linalg::solve_eigenproblem(c.K_ff, c.M_ff, o);
  return s.eigenvalues.cwiseMax(0.0).cwiseSqrt() / (2.0 * M_PI);
}

/// Frequencies (Hz) of the lowest `count` modes whose kinetic energy is at least 90 % in the basic
/// x translations (out-of-plane modes of a plate in the y-z plane), from the lowest `search` modes.
inline std::vector<double> out_of_plane_frequencies(const fem::Model& m, int count, int search) {
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  const fem::ConstrainedSystem c = fem::apply_constraints(m, g, std::nullopt);
  linalg::EigenOptions o;
  o.count = search;
  const linalg::EigenSolution s = linalg::solve_eigenproblem(c.K_ff, c.M_ff, o);
  std::vector<double> f;
  for (Eigen::Index k = 0; k < s.eigenvalues.size() && static_cast<int>(f.size()) < count; ++k) {
    const Eigen::VectorXd phi = s.vectors.col(k);
    const Eigen::VectorXd energy = phi.cwiseProduct(c.M_ff * phi);
    double x = 0;
    for (Eigen::Index i = 0; i < energy.size(); ++i)
      if (c.f_to_g[static_cast<std::size_t>(i)] % 6 == 0) x += energy(i);
    if (s.eigenvalues(k) > 1.0 && x > 0.9 * energy.sum()) f.push_back(std::sqrt(s.eigenvalues(k)) / (2.0 * M_PI));
  }
  return f;
}

/// The model with its grids (hence its dofs) in the order of their basic positions (x, then y, z).
inline fem::Model in_position_order(fem::Model m) {
  std::sort(m.grids.begin(), m.grids.end(), [](const fem::Grid& p, const fem::Grid& q) {
    return std::lexicographical_compare(p.x_basic.data(), p.x_basic.data() + 3, q.x_basic.data(), q.x_basic.data() + 3);
  });
  fem::finalize(m);
  return m;
}

/// Largest |a - b| over two sparse matrices of the same size (infinity if the sizes differ).
inline double max_abs_difference(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) return INFINITY;
  const Eigen::SparseMatrix<double> d = a - b;
  double m = 0;
  for (Eigen::Index k = 0; k < d.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(d, k); it; ++it) m = std::max(m, std::abs(it.value()));
  return m;
}

/// Same grids (basic positions, and ids unless `same_ids` is false) in the same order, and bitwise
/// the same assembled K and M.
inline void expect_same_matrices(const fem::Model& a, const fem::Model& b, bool same_ids = true) {
  ASSERT_EQ(a.grids.size(), b.grids.size());
  for (std::size_t i = 0; i < a.grids.size(); ++i) {
    if (same_ids) {
      ASSERT_EQ(a.grids[i].id, b.grids[i].id) << i;
    }
    ASSERT_EQ(a.grids[i].x_basic, b.grids[i].x_basic) << a.grids[i].id << " / " << b.grids[i].id;
  }
  const fem::GlobalMatrices ga = fem::assemble(a, fem::assembly_options(a));
  const fem::GlobalMatrices gb = fem::assemble(b, fem::assembly_options(b));
  EXPECT_GT(ga.K.nonZeros(), 0);
  EXPECT_EQ(ga.K.nonZeros(), gb.K.nonZeros());
  EXPECT_EQ(ga.M.nonZeros(), gb.M.nonZeros());
  EXPECT_EQ(max_abs_difference(ga.K, gb.K), 0.0);
  EXPECT_EQ(max_abs_difference(ga.M, gb.M), 0.0);
}

}  // namespace seflex::test
