// Nastran DMIG: the export of a superelement (io/dmig_export.hpp) read back by the reader and
// assembled through K2GG/M2GG (fem/dmig.hpp), and the assembly rules of direct matrix input.
#include "seflex/io/dmig_export.hpp"

#include <gtest/gtest.h>

#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/io/nastran.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"
#include "test_support.hpp"

namespace seflex {
namespace {

double max_abs(const Eigen::MatrixXd& A) { return A.cwiseAbs().maxCoeff(); }

se::Superelement reduced_yoke(int modes) {
  const fem::Model m = io::read_nastran(test::source_dir() / "meshes" / "yoke.bdf");
  reduction::SuperelementOptions o;
  o.interface_ids = {1, 3, 4};
  o.modes.modes = modes;
  o.name = "yoke";
  return reduction::reduce_to_superelement(m, o);
}

// The exported deck, read by seflex's reader, assembles (K2GG/M2GG) to the superelement's K and M
// to the 11 significant digits written, and its normal modes are the reduced model's free-free
// modes, every frequency to 1e-8 (the highest, of the stiff 0.02 m brackets, are the most sensitive
// to the rounding of the terms): the round trip the issue asks for.
TEST(DmigExport, RoundTripThroughTheReaderGivesTheReducedFrequencies) {
  const se::Superelement s = reduced_yoke(6);
  const std::string deck = io::dmig_deck(s);
  const fem::Model m = io::read_nastran_text(deck, "yoke_dmig.bdf");
  ASSERT_EQ(m.grids.size(), 3u);
  ASSERT_EQ(m.spoints.size(), 6u);
  ASSERT_EQ(m.dmigs.size(), 2u);
  EXPECT_EQ(m.case_control.sol.value_or(""), "103");
  EXPECT_TRUE(m.unsupported.empty());
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_EQ(m.grids[j].id, s.interfaces[j].id);
    EXPECT_LT((m.grids[j].x_basic - (s.p_OBo + s.interfaces[j].p_BoN_B)).norm(), 1e-9);
  }
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  ASSERT_EQ(g.dofs.size(), s.size());  // grids 1, 3, 4 then the SPOINTs: the order of q
  EXPECT_LT(max_abs(Eigen::MatrixXd(g.K) - s.K), 1e-9 * max_abs(s.K));
  EXPECT_LT(max_abs(Eigen::MatrixXd(g.M) - s.M), 1e-9 * max_abs(s.M));

  const fem::ConstrainedSystem c = fem::apply_constraints(m, g, std::nullopt);
  ASSERT_EQ(c.n_free(), s.size());
  // The same dense pencil solution on both sides isolates what the deck carries.
  const Eigen::VectorXd deck_lambda =
      reduction::small_pencil_eigenvalues(Eigen::MatrixXd(c.K_ff), Eigen::MatrixXd(c.M_ff), s.size());
  const Eigen::VectorXd red = reduction::reduced_eigenvalues(s, s.size());
  ASSERT_EQ(deck_lambda.size(), red.size());
  for (Eigen::Index k = 0; k < red.size(); ++k) {
    if (k < 6)
      EXPECT_LT(std::abs(deck_lambda(k)), 1e-8 * red(6)) << "rigid mode " << k + 1;
    else
      EXPECT_NEAR(std::sqrt(deck_lambda(k) / red(k)), 1.0, 1e-8) << "frequency of mode " << k + 1;
  }
}

TEST(DmigExport, DeckLayout) {
  const se::Superelement s = reduced_yoke(2);
  const std::string deck = io::dmig_deck(s);
  for (const char* part :
       {"SOL 103\n", "K2GG = KAAX\n", "M2GG = MAAX\n", "METHOD = 1\n", "BEGIN BULK\n",
        "SPOINT  9000001 THRU    9000002", "DMIG    KAAX    0       6       2       0",
        "DMIG    MAAX    0       6       2       0", "EIGRL   1                       20", "ENDDATA\n"})
    EXPECT_NE(deck.find(part), std::string::npos) << part;
  for (std::size_t pos = 0, next; pos < deck.size(); pos = next + 1) {  // Nastran's 80 columns
    next = deck.find('\n', pos);
    if (deck[pos] != '$') {
      EXPECT_LE(next - pos, 80u) << deck.substr(pos, next - pos);
    }
  }
  io::DmigExportOptions o;
  o.first_spoint = 4;  // clashes with interface grid 4
  try {
    io::dmig_deck(s, o);
    ADD_FAILURE() << "a first SPOINT id clashing with interface grid 4 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("DMIG export: modal SPOINT ids 4-5 clash with interface grid 4; expected a first "
                                         "SPOINT id outside the interface ids"),
              std::string::npos)
        << e.what();
  }
  o.first_spoint = 101;
  EXPECT_NE(io::dmig_deck(s, o).find("SPOINT  101     THRU    102"), std::string::npos);
}

// Direct matrix input rules: terms at grid components in the grid's CD system and at scalar
// points, either triangle of a symmetric DMIG, PARAM CK2/CM2 scale K2GG/M2GG, and PARAM WTMASS does
// not scale M2GG (Nastran QRG, M2GG remark 4).
TEST(DmigAssembly, K2ggAndM2ggAddToTheGsetMatrices) {
  const std::string deck = R"(SOL 103
CEND
K2GG = KU, KL
M2GG = MM
BEGIN BULK
GRID    1               0.      0.      0.
GRID    2               1.      0.      0.
SPOINT  7
CROD    10      20      1       2
PROD    20      30      0.01
MAT1    30      2.0+11          0.3     7800.
PARAM   WTMASS  0.5
PARAM   CK2     2.0
PARAM   CM2     3.0
DMIG    KU      0       6       2
DMIG    KU      7       0               2       1       5.0
DMIG    KU      7                       7               100.0
DMIG    KL      0       6       1
DMIG    KL      1       2               2       2       -4.0
DMIG    MM      0       6       2
DMIG    MM      7       0               7       0       1.5     
DMIG    MM      1       3               1       3       0.25
DMIG    UNUSED  0       6       2
DMIG    UNUSED  1       1               1       1       1.0+9
ENDDATA
)";
  const fem::Model m = io::read_nastran_text(deck, "dmig.bdf");
  fem::AssemblyOptions ao = fem::assembly_options(m);
  ao.prune_zeros = false;
  const fem::GlobalMatrices g = fem::assemble(m, ao);
  fem::Model no_dmig = m;
  no_dmig.case_control.global.k2gg.clear();
  no_dmig.case_control.global.m2gg.clear();
  const fem::GlobalMatrices e = fem::assemble(no_dmig, ao);
  const Eigen::MatrixXd dK = Eigen::MatrixXd(g.K) - Eigen::MatrixXd(e.K),
                        dM = Eigen::MatrixXd(g.M) - Eigen::MatrixXd(e.M);
  const Eigen::Index s7 = 12;  // the scalar point after the two grids
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(13, 13), M = K;
  K(s7, 6) = K(6, s7) = 2.0 * 5.0;  // (2-1, 7): upper triangle, in column 7
  K(s7, s7) = 2.0 * 100.0;
  K(7, 1) = K(1, 7) = 2.0 * -4.0;  // (2-2, 1-2): lower triangle, in column 1-2
  M(s7, s7) = 3.0 * 1.5;
  M(2, 2) = 3.0 * 0.25;  // not scaled by WTMASS
  EXPECT_LT(max_abs(dK - K), 1e-12);
  EXPECT_LT(max_abs(dM - M), 1e-12);
}

}  // namespace
}  // namespace seflex
