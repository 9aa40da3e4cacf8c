// Normal modes of the validation decks, read by the Nastran reader and solved by the production
// path (fem assembly and constraints, reduction's factorisation and eigensolvers).
// Decks and answers: tests/data/validation (MYSTRAN 12.0 benchmark archive; README there).
#include <gtest/gtest.h>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/mass_properties.hpp"
#include "seflex/io/nastran.hpp"
#include "seflex/solutions/normal_modes.hpp"
#include "test_support.hpp"

namespace seflex {
namespace {

fem::Model deck(const char* rel) { return io::read_nastran(test::validation_dir() / rel); }

// BAR-CC-GIV.reference.txt: REAL EIGENVALUES (EIGR GIV, ND = 4, NORM = MAX). Frequencies to 1e-6: the
// 7 printed digits are good to 4.7e-7 relative at most; measured (2026-11-28) 2.9e-7 (1.8e-7 free-free).
TEST(ValidationModes, BarCantileverMatchesMystran) {
  const auto r = solutions::solve_normal_modes(deck("mystran_cbar_cantilever_and_freefree_modes/BAR-CC-GIV.DAT"));
  ASSERT_EQ(r.eigenvalues.size(), 4);
  const double cycles[4] = {1.068719E+01, 6.281653E+01, 1.663460E+02, 2.899396E+02};
  const double gen_mass[4] = {6.800571E-04, 9.499997E-04, 1.461918E-03, 1.590132E-03};
  for (int j = 0; j < 4; ++j) {
    EXPECT_NEAR(r.cycles()(j) / cycles[j], 1.0, 1e-6) << "mode " << j + 1;
    EXPECT_NEAR(r.generalized_mass(j) / gen_mass[j], 1.0, 2e-6) << "mode " << j + 1;
  }
}

// BAR-FF-GIV.reference.txt (ND = 4, NORM = POINT 5/3): two rigid-body modes, then 59.11978 and
// 150.0817 Hz; the third elastic mode, 271.5359 Hz (README), with --count 5.
TEST(ValidationModes, BarFreeFreeMatchesMystran) {
  const fem::Model m = deck("mystran_cbar_cantilever_and_freefree_modes/BAR-FF-GIV.DAT");
  solutions::ModesOptions o;
  o.count = 5;
  const auto r = solutions::solve_normal_modes(m, o);
  ASSERT_EQ(r.eigenvalues.size(), 5);
  EXPECT_LT(r.cycles()(1), 1e-4 * r.cycles()(2));
  const double elastic[3] = {59.11978, 150.0817, 271.5359};
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(r.cycles()(j + 2) / elastic[j], 1.0, 1e-6) << "mode " << j + 3;
  EXPECT_NEAR(r.generalized_mass(2) / 9.738369E-04, 1.0, 2e-6);
}

// ALL-ELEM-TEST-GIV (CBAR, CROD, CQUAD4, CTRIA3, CELAS1; SPC 998, EIGR 2 with ND = 4, NORM = MAX):
// MYSTRAN's 34.46520 / 39.34327 / 63.02253 / 74.00890 Hz. The README expects 1 % (the shell
// formulations differ); measured (2026-11-28) 3.6e-5 at most, so the tolerance is 6e-5 (1.7 times).
TEST(ValidationModes, MixedElementShelfMatchesMystran) {
  const auto r = solutions::solve_normal_modes(deck("mystran_mixed_cbar_crod_cquad4_ctria3_celas_modes/ALL-ELEM-TEST-GIV.DAT"));
  ASSERT_EQ(r.eigenvalues.size(), 4);
  const double cycles[4] = {34.46520, 39.34327, 63.02253, 74.00890};
  for (int j = 0; j < 4; ++j) EXPECT_NEAR(r.cycles()(j) / cycles[j], 1.0, 6e-5) << "mode " << j + 1;
}

// CB-EXAMPLE-12: the Craig-Bampton frame's fixed-interface modes, i.e. the normal modes with the
// SUPORT dofs (the boundary set, README) held fixed: 9.933119 / 13.32647 / 14.70232 Hz, to 1e-6
// on the eigenvalues 3.895211E+03 / 7.011163E+03 / 8.533585E+03 (7 printed digits: 1e-6 is the
// precision of the reference itself).
TEST(ValidationModes, CraigBamptonFrameFixedInterfaceModes) {
  const fem::Model m = deck("mystran_craig_bampton_cbar_frame/CB-EXAMPLE-12.DAT");
  const fem::DofMap dofs = fem::make_dof_map(m);
  solutions::ModesOptions o;
  for (const fem::DofSetEntry& e : m.suport)
    for (int c = 1; c <= 6; ++c)
      if ((e.c >> (c - 1)) & 1u) o.fixed_dofs.push_back(*fem::find_dof(m, dofs, e.grid, c));
  ASSERT_EQ(o.fixed_dofs.size(), 8u);
  const auto r = solutions::solve_normal_modes(m, o);
  ASSERT_EQ(r.eigenvalues.size(), 3);
  const double lambda[3] = {3.895211E+03, 7.011163E+03, 8.533585E+03};
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(r.eigenvalues(j) / lambda[j], 1.0, 1e-6) << "mode " << j + 1;
  EXPECT_LT((r.generalized_mass.array() - 1.0).abs().maxCoeff(), 1e-10);  // EIGRL NORM = MASS
}

}  // namespace
}  // namespace seflex

namespace seflex {
namespace {

// nastran_cbar_cbeam_conm2_modes (pyNastran's models/beam_modes; Simcenter Nastran 2019.2 and MSC
// Nastran 2005 answers in beam_modes.reference.txt): a clamped 10 m ROD beam of nine CBARs and one
// CBEAM with a CONM2 at the tip. Nastran's lumped mass gives the CBEAM, not the CBARs, the polar
// inertia rho (I1 + I2) L, half at each end: the grid point weight generator's I(S) about the beam
// axis is 3.765757E-03 = 2.59E-03 (CONM2) + 1.175757E-03 (CBEAM), and the torsion mode (5) is
// 4.989076E+08 (without the CBEAM's polar inertia it would be 7.05E+08, 19 % off in frequency).
TEST(ValidationModes, CbarCbeamConm2MatchesNastranLumpedMass) {
  const fem::Model m = io::read_nastran(test::validation_dir() / "nastran_cbar_cbeam_conm2_modes" / "beam_modes.dat");
  const fem::MassProperties mp = fem::mass_properties(m);
  EXPECT_NEAR(mp.mass / 2.610514E-02, 1.0, 2e-7);
  EXPECT_NEAR(mp.M0(3, 3) / 3.765757E-03, 1.0, 2e-7);
  EXPECT_NEAR(mp.M0(4, 4) / 1.049347E+00, 1.0, 2e-6);
  const auto r = solutions::solve_normal_modes(m);
  ASSERT_EQ(r.eigenvalues.size(), 10);
  const double eig[10] = {8.232777E+06, 8.232777E+06, 2.824056E+08, 2.824056E+08, 4.989076E+08,
                          8.021004E+08, 1.733310E+09, 1.733310E+09, 4.874295E+09, 4.874295E+09};
  for (int j = 0; j < 10; ++j) EXPECT_NEAR(r.eigenvalues(j) / eig[j], 1.0, 1e-6) << "mode " << j + 1;
  // Generalized masses (NORM = MAX) of the modes that are not one of a repeated pair (a pair's
  // basis, and so its MAX-normalised mass, is arbitrary): torsion and axial.
  EXPECT_NEAR(r.generalized_mass(4) / 3.668128E-03, 1.0, 2e-6);
  EXPECT_NEAR(r.generalized_mass(5) / 1.334596E-02, 1.0, 2e-6);
}

}  // namespace
}  // namespace seflex
