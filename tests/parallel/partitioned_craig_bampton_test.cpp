// Craig-Bampton on the partitioned matrices (parallel/partitioned_craig_bampton.hpp) under mpirun -n 2
// against the serial reduction::craig_bampton on the replicated K_ff, M_ff (CHOLMOD, Spectra/dense):
// reduced K and M to 1e-9 relative to their largest entry, fixed-interface eigenvalues to 1e-9,
// Psi = identity on the boundary and Phi M-orthonormal.
#include <gtest/gtest.h>

#include "../reduction/fem_models.hpp"
#include "plates.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/parallel/partitioned_craig_bampton.hpp"
#include "seflex/parallel/partitioned_system.hpp"
#include "seflex/reduction/craig_bampton.hpp"

namespace seflex::parallel {
namespace {

using test::clamped_plate;

/// The clamped plate reduced to the six dofs of every grid of its free short edge.
void expect_same_reduction(int nx, int ny, reduction::CraigBamptonOptions opt) {
  fem::Model m = clamped_plate(nx, ny);
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  fem::ConstraintOptions co;
  co.spc_set = 1;
  const fem::ConstrainedSystem c = fem::apply_constraints(m, g, co);
  std::vector<Eigen::Index> boundary;
  for (int j = 0; j <= ny; ++j)
    for (int comp = 1; comp <= 6; ++comp)
      boundary.push_back(c.g_to_f[static_cast<std::size_t>(g.dofs.grid_dof((nx + 1) * (j + 1) - 1, comp))]);
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
  if (modes == 0) return;
  const Eigen::MatrixXd G = dist.Phi.transpose() * (c.M_ff * dist.Phi);
  EXPECT_LE((G - Eigen::MatrixXd::Identity(modes, modes)).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(PartitionedCraigBampton, ModeCountMatchesSerial) {
  reduction::CraigBamptonOptions opt;
  opt.modes = 12;
  expect_same_reduction(30, 20, opt);
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
