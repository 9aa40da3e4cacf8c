// SUPORT1 (MSC QRG SUPORT1: SID ID1 C1 ID2 C2 ID3 C3, selected by case control SUPORT1 = SID):
// statics holds the supports of the subcase's set as it holds SUPORT's (statics.hpp). A free-free
// beam under a self-equilibrated load, supported statically determinately at one end: the support
// forces are zero (equilibrium: the load already balances) and the deformation is the closed form of
// a bar stretched by P (u = P L / (E A)) and bent by end moments M (curvature M / (E I): end rotation
// M L / (E I), deflection M L^2 / (2 E I)); each subcase holds the set it selects.
#include <gtest/gtest.h>

#include <string>

#include "nastran_test_util.hpp"
#include "statics_test_util.hpp"
#include "seflex/fem/dof_map.hpp"
#include "seflex/solutions/card_usage.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

using test::displacement;
using test::mentions;
constexpr double E = 7.0e10, G = 2.7e10, A = 1.0e-4, I1 = 2.0e-8, L = 2.0, P = 1000.0, M = 30.0;

/// A free beam of four CBARs from grid 1 (x = 0) to grid 5 (x = L), pulled by P and bent by M at
/// grid 5, and by -P and -M at grid 1; no SPC. `cases`: the case control's subcases.
std::string free_beam(const std::string& cases, const std::string& more = "") {
  return "SOL 101\nCEND\nLOAD = 1\n" + cases +
         "BEGIN BULK\nMAT1,1," + test::num(E) + "," + test::num(G) + ",,2700.\nPBAR,2,1," + test::num(A) + "," +
         test::num(I1) + ",3.e-8,4.e-8\n"
         "GRID,1,,0.,0.,0.\nGRID,2,,0.5,0.,0.\nGRID,3,,1.,0.,0.\nGRID,4,,1.5,0.,0.\nGRID,5,,2.,0.,0.\n"
         "CBAR,1,2,1,2,0.,1.,0.\nCBAR,2,2,2,3,0.,1.,0.\nCBAR,3,2,3,4,0.,1.,0.\nCBAR,4,2,4,5,0.,1.,0.\n"
         "FORCE,1,5,," + test::num(P) + ",1.,0.,0.\nFORCE,1,1,," + test::num(P) + ",-1.,0.,0.\n"
         "MOMENT,1,5,," + test::num(M) + ",0.,0.,1.\nMOMENT,1,1,," + test::num(M) + ",0.,0.,-1.\n"
         "SUPORT1,10,1,123456\nSUPORT1,20,5,123\nSUPORT1,20,5,456\n" +
         more + "ENDDATA\n";
}

/// The largest support force or moment of a solution.
double largest_support_force(const solutions::StaticSolution& s) { return s.q_g.cwiseAbs().maxCoeff(); }

TEST(Suport1, FreeBeamUnderABalancedLoadEachSubcaseHoldsItsSet) {
  const fem::Model m = test::read_deck(free_beam("SUBCASE 1\nSUPORT1 = 10\nSUBCASE 2\nSUPORT1 = 20\n"));
  ASSERT_EQ(m.suport1.size(), 3u);
  EXPECT_EQ(m.suport1[2].sid, 20);
  EXPECT_EQ(m.suport1[2].dofs.grid, 5);
  const auto sols = solutions::solve_statics(m);
  ASSERT_EQ(sols.size(), 2u);
  const double stretch = P * L / (E * A), rotation = M * L / (E * I1), deflection = M * L * L / (2 * E * I1);
  // SUBCASE 1 holds grid 1: grid 5 moves by the closed forms
  const auto& s1 = sols[0];
  EXPECT_NEAR(displacement(m, s1, 5, 1), stretch, 1e-12 * stretch);  // measured 2e-16 relative
  EXPECT_NEAR(displacement(m, s1, 5, 6), rotation, 1e-12 * rotation);
  EXPECT_NEAR(displacement(m, s1, 5, 2), deflection, 1e-12 * deflection);
  for (int c = 1; c <= 6; ++c) EXPECT_EQ(displacement(m, s1, 1, c), 0.0) << "component " << c;
  // SUBCASE 2 holds grid 5 (two SUPORT1 cards of set 20): grid 1 moves the other way
  const auto& s2 = sols[1];
  EXPECT_NEAR(displacement(m, s2, 1, 1), -stretch, 1e-12 * stretch);
  EXPECT_NEAR(displacement(m, s2, 1, 6), -rotation, 1e-12 * rotation);
  EXPECT_NEAR(displacement(m, s2, 1, 2), deflection, 1e-12 * deflection);
  for (int c = 1; c <= 6; ++c) EXPECT_EQ(displacement(m, s2, 5, c), 0.0) << "component " << c;
  // the load balances: the supports carry nothing (relative to P = 1000 N; measured 1e-13 N)
  EXPECT_LT(largest_support_force(s1), 1e-9 * P);
  EXPECT_LT(largest_support_force(s2), 1e-9 * P);
}

TEST(Suport1, AnUnbalancedLoadIsCarriedByTheSupport) {
  // the FORCE at grid 1 taken away: the support at grid 1 carries -P (equilibrium), the beam stretches as before
  std::string deck = free_beam("SUPORT1 = 10\n");
  deck.replace(deck.find("FORCE,1,1,"), std::string("FORCE,1,1,").size(), "FORCE,9,1,");
  const fem::Model m = test::read_deck(deck);
  const auto s = solutions::solve_static(m);
  EXPECT_NEAR(s.q_g[*fem::find_dof(m, s.dofs, 1, 1)], -P, 1e-9 * P);  // measured 1e-13 N
  EXPECT_NEAR(displacement(m, s, 5, 1), P * L / (E * A), 1e-12 * P * L / (E * A));
}

TEST(Suport1, RefusalsNameTheCardAndTheSelection) {
  auto statics_error = [](const fem::Model& m) -> std::string {
    try {
      solutions::solve_statics(m);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  // a set no SUPORT1 card has
  EXPECT_TRUE(mentions(statics_error(test::read_deck(free_beam("SUPORT1 = 30\n"))),
                       {"case control SUPORT1", "the global case control: SUPORT1 = 30 selects no SUPORT1 card"}));
  // not a set id
  EXPECT_TRUE(mentions(statics_error(test::read_deck(free_beam("SUPORT1 = ALL\n"))),
                       {"SUPORT1 = ALL: expected the set id of SUPORT1 cards (an integer > 0)"}));
  // a grid that does not exist, a blank pair
  EXPECT_TRUE(mentions(test::read_error(free_beam("SUPORT1 = 10\n", "SUPORT1,30,8,123\n")),
                       {"deck.bdf:24: SUPORT1 30", "references point 8, which is not defined"}));
  EXPECT_TRUE(mentions(test::read_error(free_beam("SUPORT1 = 10\n", "SUPORT1,30\n")),
                       {"deck.bdf:24: SUPORT1 30", "field 3 (ID1): blank; expected grid or scalar point ids with components"}));
  // no selection: the beam is free, and statics says which dofs move freely
  EXPECT_TRUE(mentions(statics_error(test::read_deck(free_beam(""))), {"singular"}));
}

}  // namespace
}  // namespace seflex
