// PLOAD1 on CBAR/CBEAM against beam theory, and SPCD (enforced displacement selected by LOAD)
// against a hand result. References:
// - fixed-end forces of a clamped-clamped beam with a uniform load q on the left half of the span:
//   R_A = 13 qL/32, M_A = 11 qL^2/192, R_B = 3 qL/32, M_B = 5 qL^2/192 (Roark's Formulas for Stress
//   and Strain, 7th ed., table 8.1 case 2e with a = 0, b = L/2; AISC Manual beam diagrams);
// - cantilever tip deflections (Timoshenko & Gere, Mechanics of Materials, table G-1): a load
//   decreasing linearly from q0 at the root to 0 at the tip, q0 L^4 / (30 E I); a point load P at
//   distance a from the root, P a^2 (3L - a) / (6 E I). The Euler-Bernoulli bar element with
//   work-equivalent loads is exact at its nodes for these loads, so one element is compared at 1e-12.
// - a tip displacement d enforced on a cantilever (free rotation): reaction 3 E I d / L^3 and tip
//   slope 3 d / (2 L) (the same table, point load P = 3 E I d / L^3).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "nastran_test_util.hpp"
#include "seflex/fem/loads.hpp"
#include "seflex/io/nastran_writer.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

constexpr double E = 7e10, I1 = 2e-8, I2 = 3e-8, L = 2.0;

std::string bar_deck(const std::string& cc, const std::string& more, const std::string& gb = "2.,0.,0.") {
  return "SOL 101\nCEND\nSPC = 1\n" + cc + "BEGIN BULK\nMAT1,1,7.e10,,0.3,2700.\nPBAR,1,1,1.e-4,2.e-8,3.e-8,4.e-8\n"
         "GRID,1,,0.,0.,0.\nGRID,2,," + gb + "\nCBAR,1,1,1,2,0.,1.,0.\n" + more + "ENDDATA\n";
}

double load_at(const fem::Model& m, int sid, int g, int c) {
  const fem::DofMap dofs = fem::make_dof_map(m);
  return fem::load_vector(m, dofs, sid)[*fem::find_dof(m, dofs, g, c)];
}

double u(const fem::Model& m, const solutions::StaticSolution& s, int g, int c) {
  return s.u_g[*fem::find_dof(m, s.dofs, g, c)];
}

fem::Model round_trip(const fem::Model& m) {
  std::ostringstream out;
  io::write_nastran(m, out);
  return test::read_deck(out.str(), "converted.bdf");
}

TEST(Pload1, FixedEndForcesOfAHalfSpanUniformLoad) {
  const double q = -1500.0;
  for (const std::string& card : {std::string("PLOAD1,2,1,FZ,FR,0.,-1500.,0.5,-1500.\n"),
                                 std::string("PLOAD1,2,1,FZE,LE,0.,-1500.,1.,-1500.\n")}) {
    const fem::Model m = test::read_deck(bar_deck("LOAD = 2\n", "SPC1,1,123456,1,2\n" + card));
    EXPECT_NEAR(load_at(m, 2, 1, 3), 13 * q * L / 32, 1e-12 * std::abs(q * L)) << card;
    EXPECT_NEAR(load_at(m, 2, 1, 5), -11 * q * L * L / 192, 1e-12 * std::abs(q * L * L)) << card;
    EXPECT_NEAR(load_at(m, 2, 2, 3), 3 * q * L / 32, 1e-12 * std::abs(q * L)) << card;
    EXPECT_NEAR(load_at(m, 2, 2, 5), 5 * q * L * L / 192, 1e-12 * std::abs(q * L * L)) << card;
    EXPECT_EQ(load_at(m, 2, 1, 2), 0.0);
    // the clamped bar does not move: the SPC forces are minus the loads
    const auto s = solutions::solve_static(m);
    EXPECT_NEAR(s.q_g[*fem::find_dof(m, s.dofs, 1, 3)], -13 * q * L / 32, 1e-9 * std::abs(q * L));
    EXPECT_NEAR(load_at(round_trip(m), 2, 2, 5), 5 * q * L * L / 192, 1e-12 * std::abs(q * L * L));
  }
}

TEST(Pload1, CantileverTipDeflections) {
  {  // triangular load along element y (= basic y): q0 at the root, 0 at the tip
    const double q0 = 800.0;
    const fem::Model m = test::read_deck(bar_deck("LOAD = 2\n", "SPC1,1,123456,1\nPLOAD1,2,1,FYE,LE,0.,800.,2.,0.\n"));
    const double w = q0 * std::pow(L, 4) / (30 * E * I1);
    EXPECT_NEAR(u(m, solutions::solve_static(m), 2, 2), w, 1e-12 * w);
  }
  {  // point load P along basic z at mid-span (X1 = X2)
    const double P = 250.0, a = 1.0;
    const fem::Model m = test::read_deck(bar_deck("LOAD = 2\n", "SPC1,1,123456,1\nPLOAD1,2,1,FZ,LE,1.,250.\n"));
    const double w = P * a * a * (3 * L - a) / (6 * E * I2);
    const auto s = solutions::solve_static(m);
    EXPECT_NEAR(u(m, s, 2, 3), w, 1e-12 * w);
    EXPECT_NEAR(s.q_g[*fem::find_dof(m, s.dofs, 1, 5)], P * a, 1e-9 * P * a);  // root moment about y: -(-a P)
  }
}

// LEPR: P per unit of the length projected on the plane normal to the load: a bar at 45 degrees in
// the x-z plane loaded along z carries P times its x extent; LE carries P times its length.
TEST(Pload1, ProjectedLoadTotals) {
  const double P = 10.0;
  const std::vector<std::pair<std::string, double>> cases = {{"LEPR", P * 1.0}, {"LE", P * std::sqrt(2.0)}, {"FRPR", P * 1.0}};
  for (const auto& [scale, total] : cases) {
    const std::string x2 = scale == "FRPR" ? "1." : "1.4142135";  // just inside the length sqrt(2)
    const fem::Model m = test::read_deck(
        bar_deck("LOAD = 2\n", "SPC1,1,123456,1\nPLOAD1,2,1,FZ," + scale + ",0.,10.," + x2 + ",10.\n", "1.,0.,1."));
    EXPECT_NEAR(load_at(m, 2, 1, 3) + load_at(m, 2, 2, 3), total, 1e-6 * total) << scale;
  }
  // with an element-axis TYPE the projection is not defined: LEPR is LE (as MSC Nastran runs it)
  const fem::Model lepr = test::read_deck(bar_deck("LOAD = 2\n", "SPC1,1,123456,1\nPLOAD1,2,1,FZE,LEPR,0.,10.,1.4142135,10.\n", "1.,0.,1."));
  const fem::Model le = test::read_deck(bar_deck("LOAD = 2\n", "SPC1,1,123456,1\nPLOAD1,2,1,FZE,LE,0.,10.,1.4142135,10.\n", "1.,0.,1."));
  for (int c = 1; c <= 6; ++c) EXPECT_EQ(load_at(lepr, 2, 2, c), load_at(le, 2, 2, c)) << c;
}

TEST(Pload1, BadInputIsRefused) {
  EXPECT_TRUE(test::mentions(test::read_error("PLOAD1,2,1,FQ,LE,0.,1.\n"), {"deck.bdf:1: PLOAD1 2, field 4 (TYPE): got text 'FQ'; expected FX, FY, FZ, FXE, FYE, FZE, MX, MY, MZ, MXE, MYE or MZE"}));
  EXPECT_TRUE(test::mentions(test::read_error("PLOAD1,2,1,FX,LX,0.,1.\n"), {"deck.bdf:1: PLOAD1 2, field 5 (SCALE): got text 'LX'; expected LE, FR, LEPR or FRPR"}));
  EXPECT_TRUE(test::mentions(test::read_error("PLOAD1,2,1,FX,FR,0.,1.,1.5,1.\n"), {"deck.bdf:1: PLOAD1 2, field 8 (X2): got real '1.5'; expected a fraction of the length <= 1 with SCALE FR"}));
  const fem::Model m = test::read_deck(bar_deck("LOAD = 2\n", "SPC1,1,123456,1\nPLOAD1,2,1,FZ,LE,0.,1.,3.,1.\n"));
  std::string msg;
  try {
    solutions::solve_static(m);
  } catch (const InputError& e) {
    msg = e.what();
  }
  EXPECT_TRUE(test::mentions(msg, {"deck.bdf:12: PLOAD1 2, field 8 (X2): X2 = 3.000000 is beyond the end of CBAR 1 (length 2.000000); "
                                   "expected 0 <= X1 <= X2 <= L"}));
}

// ---------------------------------------------------------------------------------------------
TEST(Spcd, EnforcedTipDisplacementOfACantilever) {
  const double d = 0.01;
  const std::string bulk = "SPC1,1,123456,1\nSPC1,1,3,2\nSPCD,2,2,3,0.01\nLOAD,5,2.,1.,2\n";
  const fem::Model m = test::read_deck(bar_deck("LOAD = 2\n", bulk));
  const auto s = solutions::solve_static(m);
  EXPECT_NEAR(u(m, s, 2, 3), d, 1e-15);
  EXPECT_NEAR(u(m, s, 2, 5), -3 * d / (2 * L), 1e-12 * d / L);  // theta_y = -dw/dx
  EXPECT_NEAR(s.q_g[*fem::find_dof(m, s.dofs, 2, 3)], 3 * E * I2 * d / std::pow(L, 3), 1e-9 * 3 * E * I2 * d / std::pow(L, 3));
  // through a LOAD combination: scaled by S * S1 = 2
  const fem::Model c = test::read_deck(bar_deck("LOAD = 5\n", bulk));
  EXPECT_NEAR(u(c, solutions::solve_static(c), 2, 3), 2 * d, 1e-15);
  // written back by seflex convert
  const fem::Model back = round_trip(m);
  EXPECT_NEAR(u(back, solutions::solve_static(back), 2, 3), d, 1e-15);
}

TEST(Spcd, ComponentOutsideTheSpcSetIsAnError) {
  const fem::Model m = test::read_deck(bar_deck("LOAD = 2\n", "SPC1,1,123456,1\nSPCD,2,2,3,0.01\n"));
  std::string msg;
  try {
    solutions::solve_static(m);
  } catch (const InputError& e) {
    msg = e.what();
  }
  EXPECT_TRUE(test::mentions(msg, {"deck.bdf:12: SPCD: grid 2 component 3 is not in the subcase's SPC set 1; expected every SPCD component "
                                   "to be constrained by an SPC/SPC1 of the selected set"}));
}

}  // namespace
}  // namespace seflex
