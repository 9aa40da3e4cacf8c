// RBE1, CRIGD1, CRIGD2, CRIGD3 (rigid bodies) and RROD, CRIGDR (rigid rods) read from decks and
// checked against hand-derived rigid-body kinematics and statics: a rigid motion enforced on the
// independent components reappears exactly on the dependent ones (u = u0 + theta x x, rotations
// theta, in each grid's CD system); a rigid arm on a sprung grid moves as the hand solution of its
// equilibrium; a rod rigid in extension leaves its far end the one motion normal to it, whose
// amplitude minimises the springs' energy. Each also goes through the writer and back, and the
// refusals are checked by their whole message.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <sstream>
#include <string>

#include "nastran_test_util.hpp"
#include "statics_test_util.hpp"
#include "seflex/io/nastran_writer.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

using test::displacement;
using test::num;

fem::Model round_trip(const fem::Model& m) {
  std::ostringstream out;
  io::write_nastran(m, out);
  return test::read_deck(out.str(), "converted.bdf");
}

// A rigid motion: translation u0 of the basic origin and small rotation theta.
const Eigen::Vector3d kU0(0.1, -0.2, 0.3), kTheta(0.01, 0.02, -0.03);
Eigen::Vector3d rigid_u(const Eigen::Vector3d& x) { return kU0 + kTheta.cross(x); }

/// SPC entries (set 1) enforcing the rigid motion on components `c` of a basic-CD grid at x.
std::string enforce(int grid, const Eigen::Vector3d& x, const std::string& c) {
  std::string s;
  const Eigen::Vector3d u = rigid_u(x);
  for (const char ch : c) {
    const int k = ch - '1';
    s += "SPC,1," + std::to_string(grid) + "," + ch + "," + num(k < 3 ? u[k] : kTheta[k - 3]) + "\n";
  }
  return s;
}

/// Every component of `grid` not in `c` held at zero (SPC set 1).
std::string hold_others(int grid, const std::string& c) {
  std::string rest;
  for (const char ch : std::string("123456"))
    if (c.find(ch) == std::string::npos) rest += ch;
  return rest.empty() ? "" : "SPC1,1," + rest + "," + std::to_string(grid) + "\n";
}

// Independent set spread over three grids (123 at grid 1, 23 at grid 2 on the x axis, 3 at grid 3 on
// the y axis: the six fix the rigid motion), enforced to the rigid motion; the rest of those grids
// held. Dependent: grid 4 (all six; its CD system cylindrical) and component 1 of grid 2. A spring
// gives the solver one free dof (grid 9).
std::string spread_deck(const std::string& element) {
  const Eigen::Vector3d x1(0, 0, 0), x2(1, 0, 0), x3(0, 1, 0);
  return "SOL 101\nCEND\nSPC = 1\nBEGIN BULK\n"
         "CORD2C,7,,0.,0.,0.,0.,0.,1.,\n,1.,0.,0.\n"
         "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,0.,1.,0.\nGRID,4,,2.,3.,4.,7\nGRID,9,,5.,5.,5.\n"
         "CELAS2,90,1.,9,1\nSPC1,1,23456,9\n" +
         enforce(1, x1, "123") + hold_others(1, "123") + enforce(2, x2, "23") + hold_others(2, "123") +
         enforce(3, x3, "3") + hold_others(3, "3") + element + "ENDDATA\n";
}

void expect_rigid_motion_at_grid4(const fem::Model& m, const std::string& what) {
  const auto s = solutions::solve_static(m);
  // grid 4 at (2, 3, 4); its CD system is cylindrical: radial e_r = (2, 3, 0)/sqrt(13), e_theta = (-3, 2, 0)/sqrt(13), z
  const Eigen::Vector3d x4(2, 3, 4), er = Eigen::Vector3d(2, 3, 0) / std::sqrt(13.0), et = Eigen::Vector3d(-3, 2, 0) / std::sqrt(13.0);
  const Eigen::Matrix3d A = (Eigen::Matrix3d() << er, et, Eigen::Vector3d::UnitZ()).finished();
  const Eigen::Vector3d u = A.transpose() * rigid_u(x4), r = A.transpose() * kTheta;
  for (int c = 1; c <= 3; ++c) {
    EXPECT_NEAR(displacement(m, s, 4, c), u[c - 1], 1e-14) << what << " T" << c;
    EXPECT_NEAR(displacement(m, s, 4, c + 3), r[c - 1], 1e-15) << what << " R" << c;
  }
  EXPECT_NEAR(displacement(m, s, 2, 1), rigid_u(Eigen::Vector3d(1, 0, 0)).x(), 1e-15) << what;  // = u0_x
}

TEST(RigidBody, Rbe1AndCrigd3CarryTheRigidMotionOfTheirIndependentSet) {
  const fem::Model rbe1 = test::read_deck(spread_deck("RBE1,50,1,123,2,23,3,3\n,UM,4,123456,2,1\n"));
  expect_rigid_motion_at_grid4(rbe1, "RBE1");
  expect_rigid_motion_at_grid4(round_trip(rbe1), "RBE1 written and read back");
  // CRIGD3 in its COSMIC layout, with the independent grids in another order and a continuation
  const fem::Model crigd3 = test::read_deck(spread_deck("CRIGD3,50,3,3,2,23\n,,1,123\n,MSET,4,123456,2,1\n"));
  expect_rigid_motion_at_grid4(crigd3, "CRIGD3");
  expect_rigid_motion_at_grid4(round_trip(crigd3), "CRIGD3 written and read back");
}

// A rigid arm from grid 1 (six grounded springs k1..k6) to grid 2 at (L, 0, 0), force F along z at
// grid 2. Equilibrium of the arm: grid 1 carries F along z and the moment (L, 0, 0) x (0, 0, F) =
// (0, -L F, 0): w1 = F/k3, theta_y1 = -L F/k5; grid 2: w2 = w1 - theta_y1 L = F/k3 + L^2 F/k5,
// theta_y2 = theta_y1.
std::string arm_deck(const std::string& element) {
  std::string d = "SOL 101\nCEND\nLOAD = 2\nBEGIN BULK\nGRID,1,,0.,0.,0.\nGRID,2,,2.,0.,0.\nFORCE,2,2,,100.,0.,0.,1.\n";
  for (int c = 1; c <= 6; ++c) d += "CELAS2," + std::to_string(10 + c) + "," + std::to_string(c) + ".e3,1," + std::to_string(c) + "\n";
  return d + element + "ENDDATA\n";
}

TEST(RigidBody, Crigd1AndCrigd2ArmOnASprungGrid) {
  const double L = 2.0, F = 100.0, k3 = 3e3, k5 = 5e3;
  for (const std::string& card : {std::string("CRIGD1,5,1,2\n"), std::string("CRIGD1,5,1,2,THRU,3\nGRID,3,,1.,1.,0.\n"),
                                  std::string("CRIGD2,5,1,2,123456\n")}) {
    const fem::Model m = test::read_deck(arm_deck(card));
    for (const fem::Model* model : {&m}) {
      const auto s = solutions::solve_static(*model);
      EXPECT_NEAR(displacement(*model, s, 2, 3), F / k3 + L * L * F / k5, 1e-13) << card;
      EXPECT_NEAR(displacement(*model, s, 2, 5), -L * F / k5, 1e-15) << card;
      EXPECT_NEAR(displacement(*model, s, 1, 3), F / k3, 1e-13) << card;
    }
    const fem::Model back = round_trip(m);
    EXPECT_NEAR(displacement(back, solutions::solve_static(back), 2, 3), F / k3 + L * L * F / k5, 1e-13) << card;
  }
  // CRIGD2 with component 3 only: w2 = w1 - theta_y1 L still holds, so F loads grid 1 as before;
  // grid 2's other components are not tied (springs of their own hold them, unloaded: zero).
  std::string d = arm_deck("CRIGD2,5,1,2,3\n");
  d.insert(d.find("ENDDATA"), "CELAS2,30,7.,2,1\nCELAS2,31,7.,2,2\nCELAS2,32,7.,2,4\nCELAS2,33,7.,2,5\nCELAS2,34,7.,2,6\n");
  const fem::Model m = test::read_deck(d);
  const auto s = solutions::solve_static(m);
  EXPECT_NEAR(displacement(m, s, 2, 3), F / k3 + L * L * F / k5, 1e-13);
  EXPECT_NEAR(displacement(m, s, 2, 5), 0.0, 1e-15);
}

// A rod rigid in extension from grid 1 (held) to grid 2 at L (cos a, sin a, 0); grid 2 on grounded
// springs kx, ky along basic x, y (kz along z); force F along x at grid 2. Grid 2 can only move
// normal to the rod: u = s t, t = (-sin a, cos a, 0); minimising (kx (s tx)^2 + ky (s ty)^2)/2 - F s tx:
//   s = F tx / (kx tx^2 + ky ty^2).
TEST(RigidRod, RrodAndCrigdrLeaveTheMotionNormalToTheRod) {
  const double a = 0.5, L = 3.0, F = 10.0, kx = 2e3, ky = 5e3;
  const double tx = -std::sin(a), ty = std::cos(a), sv = F * tx / (kx * tx * tx + ky * ty * ty);
  const std::string base = "SOL 101\nCEND\nSPC = 1\nLOAD = 2\nBEGIN BULK\nGRID,1,,0.,0.,0.\nGRID,2,,"
                           + num(L * std::cos(a)) + "," + num(L * std::sin(a)) + ",0.\nSPC1,1,123456,1\nSPC1,1,456,2\n"
                           "CELAS2,21," + num(kx) + ",2,1\nCELAS2,22," + num(ky) + ",2,2\nCELAS2,23,1.e3,2,3\nFORCE,2,2,," + num(F) + ",1.,0.,0.\n";
  for (const std::string& card : {std::string("RROD,7,1,2,,1\n"), std::string("RROD,7,1,2,,2\n"), std::string("RROD,7,1,2\n"),
                                  std::string("CRIGDR,7,1,2,1\n"), std::string("CRIGDR,7,1,2,2\n")}) {
    const fem::Model m = test::read_deck(base + card + "ENDDATA\n");
    for (const fem::Model& model : {m, round_trip(m)}) {
      const auto s = solutions::solve_static(model);
      EXPECT_NEAR(displacement(model, s, 2, 1), sv * tx, 1e-15) << card;
      EXPECT_NEAR(displacement(model, s, 2, 2), sv * ty, 1e-15) << card;
      EXPECT_NEAR(displacement(model, s, 2, 3), 0.0, 1e-15) << card;
    }
  }
}

std::string solve_error(const std::string& deck) {
  try {
    const fem::Model m = test::read_deck(deck);
    solutions::solve_static(m);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "solved without error";
  return "";
}

TEST(RigidElements, RefusalsNameCardFieldAndWhatWasExpected) {
  EXPECT_EQ(test::read_error("RBE1,50,1,123,2,23\n,UM,4,123456\n"),
            "deck.bdf:1: RBE1 50, field 4 (CNi): 5 independent components; expected six in all, able to describe any "
            "rigid-body motion of the element");
  EXPECT_EQ(test::read_error("RBE1,50,1,123,2,23,3,3\n,,4,123456\n"),
            "deck.bdf:1: RBE1 50: no UM continuation; expected UM in field 2 of a continuation line, followed by the "
            "dependent grids and components");
  EXPECT_EQ(test::read_error("RBE1,50,1,123,2,23,3,3\n,4,123456\n"),
            "deck.bdf:2: RBE1 50, field 2 (keyword): got integer '4'; expected blank or UM (once) before the dependent grids");
  EXPECT_EQ(test::read_error("CRIGD3,50,1,123,2,23,3,3\n,MSET,2,2\n"),
            "deck.bdf:2: CRIGD3 50, field 3 (DGi): grid 2 has a component both independent and dependent; expected none in both");
  EXPECT_EQ(test::read_error("CRIGD2,5,1,2,123,2,456\n"),
            "deck.bdf:1: CRIGD2 5, field 4 (Gi): grid 2 is dependent twice; expected each dependent grid once");
  EXPECT_EQ(test::read_error("CRIGDR,7,1,2,4\n"), "deck.bdf:1: CRIGDR 7, field 5 (C1): got integer '4'; expected a translation component 1, 2 or 3");
  EXPECT_EQ(test::read_error("RROD,7,1,2,1,2\n"),
            "deck.bdf:1: RROD 7, field 6 (CMB): got integer '2' with CMA 1; expected one dependent translation, CMA or CMB");
  // three independent grids on one line leave the rotation about it free
  EXPECT_EQ(solve_error(spread_deck("").replace(spread_deck("").find("ENDDATA"), 0,
                                                "GRID,5,,2.,0.,0.\nRBE1,50,1,123,2,12,5,3\n,UM,4,123456\n")),
            "deck.bdf:24: RBE1 50: the independent components (grid components: 1 123, 2 12, 5 3) cannot describe every "
            "rigid-body motion of the element; expected six components that fix all six rigid-body motions (e.g. 123 "
            "at three grids not on one line)");
  // a dependent translation normal to the rod
  EXPECT_EQ(solve_error("SOL 101\nCEND\nSPC = 1\nBEGIN BULK\nGRID,1,,0.,0.,0.\nGRID,2,,3.,0.,0.\nSPC1,1,123456,1\n"
                        "CELAS2,21,1.,2,1\nCRIGDR,7,1,2,2\nENDDATA\n"),
            "deck.bdf:9: CRIGDR 7, field C1: translation 2 of grid 2 is perpendicular to the rod (direction cosine "
            "0); expected a dependent translation along the rod (direction cosine of magnitude >= 1e-3)");
  EXPECT_EQ(solve_error("SOL 101\nCEND\nBEGIN BULK\nGRID,1,,0.,0.,0.\nCELAS2,21,1.,1,1\nRROD,7,1,3\nENDDATA\n"),
            "deck.bdf:6: RROD 7, field 4 (GB): references grid 3, which is not defined; expected the id of a GRID");
}

}  // namespace
}  // namespace seflex
