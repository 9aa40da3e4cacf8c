// The partitioned assembly (parallel/partitioned_system.hpp) under mpirun -n 2: METIS splits the
// elements (each rank fewer than all, together all of them, each once), the distributed K_ff and M_ff
// gathered back equal the serial fem::assemble + apply_constraints to 1e-12 (relative to the largest
// entry), and normal modes on them (partitioned_modes.hpp) equal the serial backends' to 1e-9.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>

#include "fem_models.hpp"
#include "plates.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/io/model_reader.hpp"
#include "seflex/parallel/element_partition.hpp"
#include "seflex/parallel/partitioned_modes.hpp"
#include "seflex/parallel/partitioned_system.hpp"
#include "seflex/parallel/session.hpp"
#include "seflex/solutions/normal_modes.hpp"

namespace seflex::parallel {
Session& test_session();  // main.cpp's
namespace {

using test::clamped_plate;

std::string deck(const char* name) { return std::string(SEFLEX_TEST_DATA) + "/validation/" + name; }

double max_abs(const Eigen::SparseMatrix<double>& A) {
  double v = 0;
  for (Eigen::Index j = 0; j < A.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) v = std::max(v, std::abs(it.value()));
  return v;
}

/// Every element has one owner in [0, P); each part has some but not all; the owners' counts add up.
void expect_real_split(const fem::Model& m, int parts) {
  const ElementPartition p = partition_elements(m, parts);
  std::size_t sum = 0;
  for (int r = 0; r < parts; ++r) {
    EXPECT_GT(p.count(r), 0u) << "part " << r;
    EXPECT_LT(p.count(r), p.total()) << "part " << r;
    sum += p.count(r);
  }
  EXPECT_EQ(sum, p.total());
  for (const std::vector<int>* v : {&p.bars, &p.rods, &p.shells, &p.solids, &p.bushes, &p.conm2, &p.conm1, &p.springs,
                                    &p.scalar_masses})
    for (int owner : *v) EXPECT_TRUE(owner >= 0 && owner < parts);
  EXPECT_EQ(p.node_owner.size(), m.grids.size() + m.spoints.size());
}

/// The partitioned K_ff, M_ff (gathered) against the serial ones, and the f-set and row split.
void expect_serial_matrices(fem::Model m, const fem::ConstraintOptions& co) {
  const Session& s = test_session();
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  const fem::ConstrainedSystem c = fem::apply_constraints(m, g, co);
  const std::size_t elements = partition_elements(m, 1).total();
  const fem::Model before = m;
  const PartitionedSystem p = assemble_partitioned(m, co);
  // the model's element lists are back as they were
  EXPECT_EQ(partition_elements(m, 1).total(), elements);
  ASSERT_EQ(m.shells.size(), before.shells.size());
  for (std::size_t e = 0; e < m.shells.size(); ++e) EXPECT_EQ(m.shells[e].id, before.shells[e].id);
  EXPECT_EQ(p.f_to_g, c.f_to_g);
  EXPECT_EQ(p.total_elements, partition_elements(m, s.size()).total());
  EXPECT_EQ(p.local_elements, partition_elements(m, s.size()).count(s.rank()));
  ASSERT_EQ(p.row_begin.size(), static_cast<std::size_t>(s.size()) + 1);
  EXPECT_EQ(p.row_begin.back(), c.n_free());
  for (int r = 0; r < s.size(); ++r) EXPECT_LT(p.row_begin[static_cast<std::size_t>(r)], p.row_begin[static_cast<std::size_t>(r) + 1]);
  const Eigen::SparseMatrix<double> K = p.gather_K_ff(), M = p.gather_M_ff();
  EXPECT_LE(max_abs(K - c.K_ff), 1e-12 * max_abs(c.K_ff));
  EXPECT_LE(max_abs(M - c.M_ff), 1e-12 * max_abs(c.M_ff));
}

TEST(PartitionedAssembly, PlateSplitsAndMatchesSerial) {
  const fem::Model m = clamped_plate(30, 20);
  expect_real_split(m, 2);
  expect_real_split(m, 3);
  fem::ConstraintOptions co;
  co.spc_set = 1;
  expect_serial_matrices(m, co);
}

TEST(PartitionedAssembly, MixedElementsDeckMatchesSerial) {
  // CBAR, CROD, CQUAD4, CTRIA3, CELAS, with AUTOSPC and GRID PS
  const fem::Model m = io::read_model(deck("mystran_mixed_cbar_crod_cquad4_ctria3_celas_modes/ALL-ELEM-TEST-GIV.DAT"));
  expect_real_split(m, 2);
  fem::ConstraintOptions co;
  co.spc_set = solutions::select_case(m).spc;
  co.autospc = fem::autospc_enabled(m);
  expect_serial_matrices(m, co);
}

TEST(PartitionedAssembly, RefusesDependentDofs) {
  fem::Model m = clamped_plate(4, 3);
  EXPECT_FALSE(partition_refusal(m, std::nullopt).has_value());
  m.rbe2.emplace_back();
  const auto why = partition_refusal(m, std::nullopt);
  ASSERT_TRUE(why.has_value());
  EXPECT_NE(why->find("RBE2"), std::string::npos) << *why;
  EXPECT_NE(why->find("whole model's K"), std::string::npos) << *why;
  m.rbe2.clear();
  m.omit.emplace_back();
  ASSERT_TRUE(partition_refusal(m, std::nullopt).has_value());
  EXPECT_NE(partition_refusal(m, std::nullopt)->find("ASET/OMIT"), std::string::npos);
}

TEST(PartitionedAssembly, OneRanksBadElementStopsEveryRank) {
  fem::Model m = clamped_plate(12, 8);
  m.shells.back().pid = 77;  // no such PSHELL: only the rank that owns this element finds out
  const int owner = partition_elements(m, test_session().size()).shells.back();
  fem::ConstraintOptions co;
  co.spc_set = 1;
  if (test_session().rank() == owner) {
    try {
      (void)assemble_partitioned(m, co);
      ADD_FAILURE() << "no InputError on the owning rank";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("77"), std::string::npos) << e.what();
    }
  } else {
    EXPECT_THROW((void)assemble_partitioned(m, co), PeerFailure);
  }
}

/// Absolute round-off floor of the eigenvalues of (K_ff, M_ff): eps max_j K_jj / M_jj. A backward-stable
/// eigensolver's eigenvalues carry an absolute error of order eps ||M^-1/2 K M^-1/2|| (Weyl's theorem on the
/// perturbed pencil; Golub and Van Loan, Matrix Computations, 4th ed., 8.1.2), and max_j K_jj / M_jj is a lower
/// bound of that norm (the Rayleigh quotients of the unit vectors). It only matters for the lowest modes of a fine
/// mesh: on the 100k-dof plate it is 9.8e-4 (rad/s)^2, 4.9e-7 of the first eigenvalue, where the serial backends
/// differ among themselves by 0.9e-8 to 1.5e-8 (CHOLMOD against LDLT) and the distributed one from them by 1.6e-8.
double eigenvalue_round_off(fem::Model m, const solutions::ModesOptions& o) {
  fem::ConstraintOptions co;
  co.spc_set = solutions::select_case(m, o.subcase).spc;
  co.autospc = fem::autospc_enabled(m);
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  const fem::ConstrainedSystem c = fem::apply_constraints(m, g, co);
  double largest = 0;
  for (Eigen::Index j = 0; j < c.K_ff.rows(); ++j)
    if (c.M_ff.coeff(j, j) > 0) largest = std::max(largest, c.K_ff.coeff(j, j) / c.M_ff.coeff(j, j));
  return std::numeric_limits<double>::epsilon() * largest;
}

/// The distributed modes against the serial ones: eigenvalues to `tol` relative (or to the round-off floor
/// above where that is larger), phi^T K phi = lambda phi^T M phi, the same generalised masses.
void expect_modes_match_serial(fem::Model m, solutions::ModesOptions o, double tol) {
  const double floor = eigenvalue_round_off(m, o);
  const solutions::NormalModes serial = solutions::solve_normal_modes(m, o);
  PartitionStats st;
  const solutions::NormalModes part = solve_normal_modes_partitioned(m, o, &st);
  EXPECT_EQ(part.stats.backend_used, linalg::EigenBackend::Slepc);
  EXPECT_LT(st.local_elements, st.total_elements);
  ASSERT_EQ(part.eigenvalues.size(), serial.eigenvalues.size());
  ASSERT_GT(serial.eigenvalues.size(), 0);
  const double top = serial.eigenvalues.cwiseAbs().maxCoeff();
  for (Eigen::Index k = 0; k < serial.eigenvalues.size(); ++k) {
    const double scale = std::abs(serial.eigenvalues(k)) < 1e-6 * top ? top : std::abs(serial.eigenvalues(k));
    EXPECT_LE(std::abs(part.eigenvalues(k) - serial.eigenvalues(k)), std::max(tol * scale, floor)) << "mode " << k + 1;
    // phi^T K phi = lambda phi^T M phi (the generalised stiffness and mass of the same normalised mode;
    // phi^T K phi carries the same round-off floor)
    EXPECT_NEAR(part.generalized_stiffness(k), part.eigenvalues(k) * part.generalized_mass(k),
                std::max(1e-9 * scale, floor) * part.generalized_mass(k)) << "mode " << k + 1;
    // the same generalised mass where the mode is well separated (a multiple eigenvalue's shapes are
    // any basis of its space, which NORM = MAX scales differently)
    const double gap = std::min(k > 0 ? serial.eigenvalues(k) - serial.eigenvalues(k - 1) : top,
                                k + 1 < serial.eigenvalues.size() ? serial.eigenvalues(k + 1) - serial.eigenvalues(k) : top);
    if (gap > 1e-6 * scale) {
      EXPECT_NEAR(part.generalized_mass(k), serial.generalized_mass(k), 1e-7 * std::abs(serial.generalized_mass(k)))
          << "mode " << k + 1;
    }
  }
  EXPECT_EQ(part.shapes_g.rows(), serial.shapes_g.rows());
  EXPECT_EQ(part.n_free, serial.n_free);
}

TEST(PartitionedModes, ClampedPlateMatchesSerial) {
  solutions::ModesOptions o;
  o.count = 20;
  expect_modes_match_serial(clamped_plate(41, 40), o, 1e-9);  // 10,086 free dofs
}

// The 100k-dof plate of issue 16 (100,620 free dofs): 1e-9 relative from the 7th mode up; the first six
// are held to the round-off floor of the pencil (eigenvalue_round_off), which 1e-9 of them is below.
TEST(PartitionedModes, HundredThousandDofPlateMatchesSerial) {
  solutions::ModesOptions o;
  o.count = 20;
  expect_modes_match_serial(clamped_plate(130, 128), o, 1e-9);
}

TEST(PartitionedModes, FreePlateMatchesSerial) {
  fem::Model m = test::quad_plate(24, 16, 0.6, 0.4, 0.003, 7.0e10, 0.33, 2700);
  test::finalize_for_test(m);
  solutions::ModesOptions o;
  o.count = 14;
  expect_modes_match_serial(m, o, 1e-9);  // six rigid-body modes
}

class PartitionedDeck : public ::testing::TestWithParam<const char*> {};

TEST_P(PartitionedDeck, EigenvaluesMatchSerial) {
  expect_modes_match_serial(io::read_model(deck(GetParam())), solutions::ModesOptions{}, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Decks, PartitionedDeck,
                         ::testing::Values("mystran_cbar_cantilever_and_freefree_modes/BAR-CC-GIV.DAT",
                                           "mystran_cbar_cantilever_and_freefree_modes/BAR-FF-GIV.DAT",
                                           "mystran_mixed_cbar_crod_cquad4_ctria3_celas_modes/ALL-ELEM-TEST-GIV.DAT",
                                           "nastran_cbar_cbeam_conm2_modes/beam_modes.dat"));

}  // namespace
}  // namespace seflex::parallel
