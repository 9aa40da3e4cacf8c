// The distributed backend (parallel/: SLEPc Krylov-Schur on a MUMPS factor, MUMPS multi-RHS solves)
// against the serial backends of reduction/, in one process per MPI rank (run with mpirun -n 2):
// eigenvalues of a 10k-dof plate and of the validation decks to 1e-9 relative, M-orthonormal modes,
// Craig-Bampton reduced K and M to 1e-9, and the factorisation error of a mechanism.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "fem_models.hpp"
#include "plates.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/io/model_reader.hpp"
#include "seflex/parallel/mumps_factorization.hpp"
#include "seflex/parallel/session.hpp"
#include "seflex/parallel/slepc_eigensolver.hpp"
#include "seflex/reduction/craig_bampton.hpp"
#include "seflex/solutions/normal_modes.hpp"

namespace seflex::parallel {
Session& test_session();  // main.cpp's
namespace {

using linalg::EigenBackend;
using solutions::ModesOptions;
using solutions::NormalModes;

/// Eigenvalues equal to `tol` relative to each one; rigid-body ones (|lambda| below 1e-6 of the
/// largest) to `tol` of the largest, since a zero has no relative accuracy.
void expect_same_eigenvalues(const Eigen::VectorXd& serial, const Eigen::VectorXd& slepc, double tol) {
  ASSERT_EQ(serial.size(), slepc.size());
  const double top = serial.cwiseAbs().maxCoeff();
  for (Eigen::Index k = 0; k < serial.size(); ++k) {
    const double scale = std::abs(serial(k)) < 1e-6 * top ? top : std::abs(serial(k));
    EXPECT_LE(std::abs(slepc(k) - serial(k)), tol * scale) << "mode " << k + 1 << ": serial " << serial(k) << ", slepc " << slepc(k);
  }
}

/// Phi^T M Phi = I on the f-set.
void expect_mass_orthonormal(const fem::Model& model, const NormalModes& r, double tol) {
  const fem::GlobalMatrices g = fem::assemble(model, fem::assembly_options(model));
  fem::ConstraintOptions co;
  co.autospc = fem::autospc_enabled(model);
  const fem::ConstrainedSystem c = fem::apply_constraints(model, g, co);
  Eigen::MatrixXd phi(c.n_free(), r.shapes_g.cols());
  for (Eigen::Index i = 0; i < c.n_free(); ++i) phi.row(i) = r.shapes_g.row(c.f_to_g[static_cast<std::size_t>(i)]);
  Eigen::MatrixXd G = phi.transpose() * (c.M_ff * phi);
  // mass-normalised modes: G = I; other normalisations (MAX, POINT): G diagonal
  const Eigen::VectorXd d = G.diagonal();
  G = d.cwiseSqrt().cwiseInverse().asDiagonal() * G * d.cwiseSqrt().cwiseInverse().asDiagonal();
  EXPECT_LE((G - Eigen::MatrixXd::Identity(G.rows(), G.cols())).cwiseAbs().maxCoeff(), tol);
  if (r.normalization == solutions::ModeNormalization::Mass) {
    EXPECT_LE((d.array() - 1.0).abs().maxCoeff(), tol);
  }
}

using test::clamped_plate;

TEST(SlepcBackend, TenThousandDofPlateMatchesSerial) {
  const fem::Model m = clamped_plate(41, 40);  // 42 x 41 grids, 41 clamped: 10,086 free dofs
  ModesOptions o;
  o.count = 20;
  const NormalModes serial = solutions::solve_normal_modes(m, o);
  o.external = slepc_eigenproblem;
  const NormalModes slepc = solutions::solve_normal_modes(m, o);
  EXPECT_EQ(slepc.n_free, 10086);
  EXPECT_EQ(slepc.stats.backend_used, EigenBackend::Slepc);
  expect_same_eigenvalues(serial.eigenvalues, slepc.eigenvalues, 1e-9);
  expect_mass_orthonormal(m, slepc, 1e-10);
  // the same shapes (sign fixed by the normalisation) where the eigenvalue is well separated (a
  // near-double pair may come as any orthonormal basis of its plane)
  for (Eigen::Index k = 0; k < 20; ++k) {
    const double gap_below = k > 0 ? serial.eigenvalues(k) - serial.eigenvalues(k - 1) : serial.eigenvalues(k);
    const double gap_above = k < 19 ? serial.eigenvalues(k + 1) - serial.eigenvalues(k) : serial.eigenvalues(k);
    if (std::min(gap_below, gap_above) < 1e-2 * serial.eigenvalues(k)) continue;
    // up to the sign: NORM = MASS signs by the largest component, a tie in a symmetric mode
    const double diff = std::min((slepc.shapes_g.col(k) - serial.shapes_g.col(k)).cwiseAbs().maxCoeff(),
                                 (slepc.shapes_g.col(k) + serial.shapes_g.col(k)).cwiseAbs().maxCoeff());
    EXPECT_LE(diff,
              1e-6 * serial.shapes_g.col(k).cwiseAbs().maxCoeff()) << "mode " << k + 1;
  }
}

TEST(SlepcBackend, FreePlateFindsSixRigidBodyModes) {
  fem::Model m = test::quad_plate(24, 16, 0.6, 0.4, 0.003, 7.0e10, 0.33, 2700);
  test::finalize_for_test(m);
  ModesOptions o;
  o.count = 14;
  const NormalModes serial = solutions::solve_normal_modes(m, o);
  o.external = slepc_eigenproblem;
  const NormalModes slepc = solutions::solve_normal_modes(m, o);
  expect_same_eigenvalues(serial.eigenvalues, slepc.eigenvalues, 1e-9);
  int rigid = 0;
  for (Eigen::Index k = 0; k < 14; ++k) rigid += slepc.cycles()(k) < 1e-4 * slepc.cycles()(6);
  EXPECT_EQ(rigid, 6);
  expect_mass_orthonormal(m, slepc, 1e-10);
}

class ValidationDeck : public ::testing::TestWithParam<const char*> {};

TEST_P(ValidationDeck, EigenvaluesMatchSerial) {
  const std::string deck = std::string(SEFLEX_TEST_DATA) + "/validation/" + GetParam();
  const fem::Model m = io::read_model(deck);
  ModesOptions o;
  const NormalModes serial = solutions::solve_normal_modes(m, o);
  o.external = slepc_eigenproblem;
  const NormalModes slepc = solutions::solve_normal_modes(m, o);
  ASSERT_GT(serial.eigenvalues.size(), 0);
  expect_same_eigenvalues(serial.eigenvalues, slepc.eigenvalues, 1e-9);
  expect_mass_orthonormal(m, slepc, 1e-10);
}

INSTANTIATE_TEST_SUITE_P(Decks, ValidationDeck,
                         ::testing::Values("mystran_cbar_cantilever_and_freefree_modes/BAR-CC-GIV.DAT",
                                           "mystran_cbar_cantilever_and_freefree_modes/BAR-FF-GIV.DAT",
                                           "mystran_mixed_cbar_crod_cquad4_ctria3_celas_modes/ALL-ELEM-TEST-GIV.DAT",
                                           "nastran_cbar_cbeam_conm2_modes/beam_modes.dat"));

/// Craig-Bampton of the clamped-free plate's f-set to the dofs of the grids of its free short edge:
/// serial (CHOLMOD) and distributed (MUMPS factor, block Lanczos or SLEPc) reduced K and M.
void expect_same_reduction(int nx, int ny, int modes) {
  const fem::Model m = clamped_plate(nx, ny);
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  fem::ConstraintOptions co;
  co.spc_set = 1;
  const fem::ConstrainedSystem c = fem::apply_constraints(m, g, co);
  std::vector<Eigen::Index> boundary;
  std::vector<Eigen::Index> g_to_f(static_cast<std::size_t>(g.K.rows()), -1);
  for (Eigen::Index f = 0; f < c.n_free(); ++f) g_to_f[static_cast<std::size_t>(c.f_to_g[static_cast<std::size_t>(f)])] = f;
  for (int j = 0; j <= ny; ++j)
    for (int comp = 1; comp <= 6; ++comp)
      boundary.push_back(g_to_f[static_cast<std::size_t>(g.dofs.grid_dof((nx + 1) * (j + 1) - 1, comp))]);
  reduction::CraigBamptonOptions opt;
  opt.modes = modes;
  const reduction::CraigBamptonBasis serial = reduction::craig_bampton(c.K_ff, c.M_ff, boundary, opt);
  opt.factorization_maker = make_mumps_factorization;
  opt.external = slepc_eigenproblem;
  reduction::CraigBamptonBasis dist = reduction::craig_bampton(c.K_ff, c.M_ff, boundary, opt);
  // A mode's sign is arbitrary: flip the distributed ones to the serial signs (phi_s^T M phi_d > 0)
  // before comparing the mode-to-boundary mass coupling.
  const auto nb = static_cast<Eigen::Index>(boundary.size());
  ASSERT_EQ(dist.Phi.cols(), serial.Phi.cols());
  for (Eigen::Index k = 0; k < dist.Phi.cols(); ++k)
    if (serial.Phi.col(k).dot(c.M_ff * dist.Phi.col(k)) < 0) {
      dist.Phi.col(k) *= -1;
      dist.M.row(nb + k) *= -1;
      dist.M.col(nb + k) *= -1;
    }
  EXPECT_EQ(dist.stats.interior_factorization.numeric_factorizations, 1);
  ASSERT_EQ(dist.K.rows(), serial.K.rows());
  const double nk = serial.K.cwiseAbs().maxCoeff(), nm = serial.M.cwiseAbs().maxCoeff();
  EXPECT_LE((dist.K - serial.K).cwiseAbs().maxCoeff(), 1e-9 * nk);
  EXPECT_LE((dist.M - serial.M).cwiseAbs().maxCoeff(), 1e-9 * nm);
  expect_same_eigenvalues(serial.eigenvalues, dist.eigenvalues, 1e-9);
  // Phi M-orthonormal on the interior
  const Eigen::MatrixXd G = dist.Phi.transpose() * (c.M_ff * dist.Phi);
  EXPECT_LE((G - Eigen::MatrixXd::Identity(modes, modes)).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(SlepcBackend, CraigBamptonLargeInteriorMatchesSerial) { expect_same_reduction(30, 20, 12); }  // block Lanczos on MUMPS
TEST(SlepcBackend, CraigBamptonSmallInteriorMatchesSerial) { expect_same_reduction(8, 5, 6); }     // SLEPc eigensolver

TEST(SlepcBackend, MechanismIsAFactorizationError) {
  // Two grids joined by nothing in rotation: K singular, lumped mass without rotary inertia.
  fem::Model m = test::quad_plate(2, 2, 0.6, 0.4, 0.003, 7.0e10, 0.33, 2700);
  test::finalize_for_test(m);
  linalg::EigenOptions eo;
  eo.count = 4;
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  linalg::SparseMatrixd K = g.K, M = g.M;
  K.coeffRef(0, 0) = -1.0;  // indefinite: no Cholesky
  for (Eigen::Index j = 0; j < M.outerSize(); ++j)
    for (linalg::SparseMatrixd::InnerIterator it(M, j); it; ++it) it.valueRef() = 0;
  M.coeffRef(0, 0) = 1;
  EXPECT_THROW((void)slepc_eigenproblem(K, M, eo), linalg::FactorizationError);
}

}  // namespace
}  // namespace seflex::parallel

namespace seflex::parallel {
namespace {

// An error on one rank only (the last): every rank learns its code and message, so all stop alike.
TEST(Session, OneRanksFailureReachesEveryRank) {
  Session& s = test_session();
  std::optional<Failure> mine;
  if (s.rank() == s.size() - 1) mine = Failure{3, "deck.bdf:7: GRID 3: bad coordinate", s.rank()};
  const std::optional<Failure> all = s.agree(mine);
  ASSERT_TRUE(all.has_value());
  EXPECT_EQ(all->exit_code, 3);
  EXPECT_EQ(all->message, "deck.bdf:7: GRID 3: bad coordinate");
  EXPECT_EQ(all->rank, s.size() - 1);
  EXPECT_FALSE(s.agree(std::nullopt).has_value());  // and nothing when no rank failed
}

}  // namespace
}  // namespace seflex::parallel
