// Craig-Bampton on the partitioned matrices (parallel/partitioned_craig_bampton.hpp) under mpirun -n 2
// against the serial reduction::craig_bampton on the replicated K_ff, M_ff (CHOLMOD, Spectra/dense):
// reduced K and M to 1e-9 relative to their largest entry, fixed-interface eigenvalues to 1e-9,
// Psi = identity on the boundary and Phi M-orthonormal. With interior loads (the inertia load cases of
// the geometric-stiffness invariants ride on the same solve): the static responses equal the serial
// ones to 1e-9 of their largest entry, are exactly zero on the boundary and satisfy K_ii y_i = F_i
// (residual checked on the f-set K, independently of either factor).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fem_models.hpp"
#include "plates.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/parallel/partitioned_craig_bampton.hpp"
#include "seflex/parallel/partitioned_system.hpp"
#include "seflex/reduction/craig_bampton.hpp"

namespace seflex::parallel {
namespace {

using test::clamped_plate;

/// `cases` load cases on every f-dof, boundary rows included (they must be ignored): smooth fields
/// of different shape per case and component, so that no two columns are alike.
Eigen::MatrixXd test_loads(Eigen::Index n, int cases) {
  Eigen::MatrixXd F(n, cases);
  for (Eigen::Index f = 0; f < n; ++f)
    for (int c = 0; c < cases; ++c)
      F(f, c) = std::cos(0.37 * static_cast<double>(f) * (c + 1) + c) * (1.0 + static_cast<double>(f % 6));
  return F;
}

/// The clamped plate reduced to the six dofs of every grid of its free short edge (reversed: the
/// columns of Psi are not in f order), with `load_cases` interior loads.
void expect_same_reduction(int nx, int ny, reduction::CraigBamptonOptions opt, int load_cases = 0) {
  fem::Model m = clamped_plate(nx, ny);
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  fem::ConstraintOptions co;
  co.spc_set = 1;
  const fem::ConstrainedSystem c = fem::apply_constraints(m, g, co);
  std::vector<Eigen::Index> boundary;
  for (int j = 0; j <= ny; ++j)
    for (int comp = 1; comp <= 6; ++comp)
      boundary.push_back(c.g_to_f[static_cast<std::size_t>(g.dofs.grid_dof((nx + 1) * (j + 1) - 1, comp))]);
  std::reverse(boundary.begin(), boundary.end());
  if (load_cases > 0) opt.interior_loads = test_loads(c.n_free(), load_cases);
  const reduction::CraigBamptonBasis serial = reduction::craig_bampton(c.K_ff, c.M_ff, boundary, opt);
  const PartitionedSystem s = assemble_partitioned(m, co);
  ASSERT_EQ(s.f_to_g, c.f_to_g);
  reduction::CraigBamptonBasis dist = craig_bampton_partitioned(s, boundary, opt);
  const auto nb = static_cast<Eigen::Index>(boundary.size());
  const Eigen::Index modes = serial.Phi.cols();
  ASSERT_EQ(dist.Phi.cols(), modes);
  ASSERT_EQ(dist.K.rows(), serial.K.rows());
  // a mode's sign is arbitrary: the serial one's
  for (Eigen::Index k = 0; k < modes; ++k)
    if (serial.Phi.col(k).dot(c.M_ff * dist.Phi.col(k)) < 0) {
      dist.Phi.col(k) *= -1;
      dist.M.row(nb + k) *= -1;
      dist.M.col(nb + k) *= -1;
    }
  EXPECT_EQ(dist.stats.interior_factorization.numeric_factorizations, 1);
  EXPECT_EQ(dist.stats.n_interior, serial.stats.n_interior);
  EXPECT_LE((dist.K - serial.K).cwiseAbs().maxCoeff(), 1e-9 * serial.K.cwiseAbs().maxCoeff());
  EXPECT_LE((dist.M - serial.M).cwiseAbs().maxCoeff(), 1e-9 * serial.M.cwiseAbs().maxCoeff());
  ASSERT_EQ(dist.eigenvalues.size(), serial.eigenvalues.size());
  for (Eigen::Index k = 0; k < modes; ++k)
    EXPECT_LE(std::abs(dist.eigenvalues(k) - serial.eigenvalues(k)), 1e-9 * serial.eigenvalues(k)) << "mode " << k + 1;
  EXPECT_LE((dist.Psi - serial.Psi).cwiseAbs().maxCoeff(), 1e-9 * serial.Psi.cwiseAbs().maxCoeff());
  for (Eigen::Index k = 0; k < nb; ++k) EXPECT_EQ(dist.Psi(boundary[static_cast<std::size_t>(k)], k), 1.0);
  // The static responses, on the factor of the constraint modes: one solve with n_b + k columns.
  EXPECT_EQ(dist.stats.interior_factorization.solve_columns, nb + load_cases);
  ASSERT_EQ(dist.static_responses.rows(), load_cases > 0 ? c.n_free() : 0);
  ASSERT_EQ(dist.static_responses.cols(), load_cases);
  ASSERT_EQ(serial.static_responses.rows(), dist.static_responses.rows());
  if (load_cases > 0) {
    const double scale = serial.static_responses.cwiseAbs().maxCoeff();
    ASSERT_GT(scale, 0.0);
    EXPECT_LE((dist.static_responses - serial.static_responses).cwiseAbs().maxCoeff(), 1e-9 * scale);
    std::vector<char> on_b(static_cast<std::size_t>(c.n_free()), 0);
    for (Eigen::Index f : boundary) on_b[static_cast<std::size_t>(f)] = 1;
    // K_ff y = F on the interior rows (y is zero on b, so K_ff y restricted to i is K_ii y_i), to a
    // componentwise backward error of 1e-10: |r| <= 1e-10 (|K| |y| + |F|), row by row.
    const Eigen::MatrixXd R = c.K_ff * dist.static_responses - opt.interior_loads;
    const Eigen::MatrixXd bound =
        linalg::SparseMatrixd(c.K_ff.cwiseAbs()) * dist.static_responses.cwiseAbs() + opt.interior_loads.cwiseAbs();
    for (Eigen::Index f = 0; f < c.n_free(); ++f)
      for (int k = 0; k < load_cases; ++k)
        if (on_b[static_cast<std::size_t>(f)]) {
          EXPECT_EQ(dist.static_responses(f, k), 0.0) << "boundary f-dof " << f;
        } else {
          EXPECT_LE(std::abs(R(f, k)), 1e-10 * bound(f, k)) << "interior f-dof " << f << ", case " << k;
        }
  }
  if (modes == 0) return;
  const Eigen::MatrixXd G = dist.Phi.transpose() * (c.M_ff * dist.Phi);
  EXPECT_LE((G - Eigen::MatrixXd::Identity(modes, modes)).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(PartitionedCraigBampton, ModeCountMatchesSerial) {
  reduction::CraigBamptonOptions opt;
  opt.modes = 12;
  expect_same_reduction(30, 20, opt);
}

TEST(PartitionedCraigBampton, StaticResponsesOfInteriorLoadsMatchSerial) {
  reduction::CraigBamptonOptions opt;
  opt.modes = 6;
  expect_same_reduction(30, 20, opt, 12);  // as many as the inertia load cases of the stiffening
}

TEST(PartitionedCraigBampton, StaticResponsesWithConstraintModesOnly) {
  reduction::CraigBamptonOptions opt;
  opt.modes = 0;
  expect_same_reduction(8, 5, opt, 3);
}

TEST(PartitionedCraigBampton, FrequencyLimitMatchesSerial) {
  reduction::CraigBamptonOptions opt;
  opt.fmax_hz = 400;
  expect_same_reduction(16, 10, opt);
}

TEST(PartitionedCraigBampton, ConstraintModesOnly) {
  reduction::CraigBamptonOptions opt;
  opt.modes = 0;
  expect_same_reduction(8, 5, opt);
}

}  // namespace
}  // namespace seflex::parallel
