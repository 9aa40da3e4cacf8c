// CBEND/PBEND, the curved beam, against Castigliano's closed forms of a quarter-circle cantilever
// (Roark's Formulas for Stress and Strain, 7th ed., table 9.3; derived below from the section
// resultants): clamped at A = (R, 0, 0) on a circle about the origin, loaded at B = (0, R, 0):
//   in plane  (bending E I1, axial E A):  u_x = R^3/(E I1) (Fx (3 pi/4 - 2) + Fy/2) + R/(E A) (Fx pi/4 - Fy/2)
//                                         u_y = R^3/(E I1) (Fx/2 + Fy pi/4)       + R/(E A) (-Fx/2 + Fy pi/4)
//   out of plane (bending E I2, torsion G J):  u_z = Fz R^3 (pi/4 / (E I2) + (3 pi/4 - 2) / (G J)).
// The four GEOM options give the same arc; the rigid-body modes; the mass; the writer and back; the
// refusals by their whole message.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <sstream>
#include <string>

#include "assembly_test_util.hpp"
#include "nastran_test_util.hpp"
#include "statics_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_bend.hpp"
#include "seflex/fem/element_common.hpp"
#include "seflex/fem/mass_properties.hpp"
#include "seflex/io/nastran_writer.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

using test::num;
constexpr double kPi = 3.14159265358979323846;
constexpr double E = 2.0e11, nu = 0.3, G = E / (2 * (1 + nu)), rho = 7800.0;
constexpr double R = 0.8, A = 4.0e-4, I1 = 3.0e-8, I2 = 5.0e-8, J = 6.0e-8;

// GA = 1 at (R, 0, 0), GB = 2 at (0, R, 0), grid 9 at the centre; the quarter arc about the origin.
std::string bend_deck(const std::string& cbend, const std::string& pbend_tail, const std::string& load) {
  return "SOL 101\nCEND\nSPC = 1\nLOAD = 2\nBEGIN BULK\nMAT1,3," + num(E) + ",," + num(nu) + "," + num(rho) + "\n"
         "PBEND,7,3," + num(A) + "," + num(I1) + "," + num(I2) + "," + num(J) + pbend_tail + "\n" + cbend +
         "GRID,1,," + num(R) + ",0.,0.\nGRID,2,,0.," + num(R) + ",0.\nGRID,9,,0.,0.,0.\nGRID,8,," + num(2 * R) + "," + num(R) + ",0.\n"
         "SPC1,1,123456,1,9,8\n" + load + "ENDDATA\n";
}

fem::Model round_trip_model(const fem::Model& m) {
  std::ostringstream out;
  io::write_nastran(m, out);
  return test::read_deck(out.str(), "converted.bdf");
}

Eigen::Vector3d tip(const fem::Model& m) {
  const auto s = solutions::solve_static(m);
  return {test::displacement(m, s, 2, 1), test::displacement(m, s, 2, 2), test::displacement(m, s, 2, 3)};
}

TEST(Cbend, QuarterCircleCantileverAgainstCastigliano) {
  // measured: at most 3.4e-15 of each displacement (round-off); asserted 1e-13
  const double Fx = 30.0, Fy = -50.0, Fz = 20.0;
  const double ux = R * R * R / (E * I1) * (Fx * (3 * kPi / 4 - 2) + Fy / 2) + R / (E * A) * (Fx * kPi / 4 - Fy / 2);
  const double uy = R * R * R / (E * I1) * (Fx / 2 + Fy * kPi / 4) + R / (E * A) * (-Fx / 2 + Fy * kPi / 4);
  const double uz = Fz * R * R * R * (kPi / 4 / (E * I2) + (3 * kPi / 4 - 2) / (G * J));
  const std::string load = "FORCE,2,2,,1.," + num(Fx) + "," + num(Fy) + "," + num(Fz) + "\n";
  // GEOM 1: centre on the line from GA towards G0 = 9 (the centre); GEOM 2: tangent at GA along
  // +y; GEOM 3: RB = R, the orientation towards grid 8 (away from the centre); GEOM 4: THETAB = 90.
  const std::pair<std::string, std::string> cases[] = {
      {"CBEND,5,7,1,2,9,,,1\n", ",,"}, {"CBEND,5,7,1,2,0.,1.,0.,2\n", ",,"},
      {"CBEND,5,7,1,2,8,,,3\n", "," + num(R) + ","}, {"CBEND,5,7,1,2,1.,1.,0.,4\n", ",,90."}};
  for (const auto& [cbend, tail] : cases) {
    const fem::Model m = test::read_deck(bend_deck(cbend, tail, load));
    const Eigen::Vector3d u = tip(m);
    EXPECT_NEAR(u.x(), ux, 1e-13 * std::abs(ux)) << cbend;
    EXPECT_NEAR(u.y(), uy, 1e-13 * std::abs(uy)) << cbend;
    EXPECT_NEAR(u.z(), uz, 1e-13 * std::abs(uz)) << cbend;
    const Eigen::Vector3d back = tip(round_trip_model(m));
    EXPECT_NEAR(back.x(), ux, 1e-13 * std::abs(ux)) << cbend;
  }
}

// Shear flexibility (K1, K2): the tip displacement grows by the shear terms of Castigliano,
// int V^2 / (2 K G A) R dphi: in plane V_r = Fx cos(phi) + Fy sin(phi) (Fy alone: u_y += Fy R pi/4 / (K1 G A));
// out of plane V_z = Fz (u_z += Fz R pi/2 / (K2 G A)).
TEST(Cbend, ShearFactorsAddTheShearFlexibility) {
  const double Fy = -50.0, Fz = 20.0, K1 = 0.5, K2 = 0.8;
  const std::string tail = ",,\n,,,,,,,,\n," + num(K1) + "," + num(K2);
  const fem::Model m0 = test::read_deck(bend_deck("CBEND,5,7,1,2,9,,,1\n", ",,", "FORCE,2,2,,1.,0.," + num(Fy) + "," + num(Fz) + "\n"));
  const fem::Model m1 = test::read_deck(bend_deck("CBEND,5,7,1,2,9,,,1\n", tail, "FORCE,2,2,,1.,0.," + num(Fy) + "," + num(Fz) + "\n"));
  const Eigen::Vector3d d = tip(m1) - tip(m0);  // measured: 8.7e-12 and 1e-16 of the shear terms (a difference of two solutions 1600 times larger)
  EXPECT_NEAR(d.y(), Fy * R * kPi / 4 / (K1 * G * A), 1e-10 * std::abs(Fy * R * kPi / 4 / (K1 * G * A)));
  EXPECT_NEAR(d.z(), Fz * R * kPi / 2 / (K2 * G * A), 1e-10 * std::abs(Fz * R * kPi / 2 / (K2 * G * A)));
}

// A nearly straight bend (GEOM 1 with the orientation (0.5, 1e6, 0) of pyNastran's randvar2.bdf:
// radius 1e6 chords) is the straight cantilever, loaded along each axis in turn: F L / EA,
// F L^3 / 3 E I1 (in the plane of the bend), F L^3 / 3 E I2, to O(L / R) and the digits the far
// centre costs. (Loaded together, the in-plane force moves the tip along the chord by the sagitta's
// coupling, Fy L^2 h / E I1 with h = L^2 / 8R: 1e-3 of the axial displacement.)
TEST(Cbend, NearlyStraightBendIsTheStraightCantilever) {
  const double L = 1.0, F = 30.0;
  const double expected[3] = {F * L / (E * A), F * L * L * L / (3 * E * I1), F * L * L * L / (3 * E * I2)};
  for (int k = 0; k < 3; ++k) {
    const std::string load = k == 0 ? "1.,0.,0." : k == 1 ? "0.,1.,0." : "0.,0.,1.";
    const fem::Model m = test::read_deck(
        "SOL 101\nCEND\nSPC = 1\nLOAD = 2\nBEGIN BULK\nMAT1,3," + num(E) + ",," + num(nu) + "\nPBEND,7,3," + num(A) + "," + num(I1) +
        "," + num(I2) + "," + num(J) + "\nCBEND,5,7,1,2,.5,1.+6,,1\nGRID,1,,0.,0.,0.\nGRID,2,," + num(L) +
        ",0.,0.\nSPC1,1,123456,1\nFORCE,2,2,," + num(F) + "," + load + "\nENDDATA\n");
    EXPECT_NEAR(tip(m)[k], expected[k], 1e-8 * expected[k]) << k;  // measured 1.1e-10, 5e-14, 2.5e-13
  }
}

TEST(Cbend, RigidBodyModesAndMass) {
  const fem::Model m = test::read_deck(bend_deck("CBEND,5,7,1,2,9,,,1\n", ",,\n,,,,,,,,\n,,,0.3", ""));
  const fem::BendElement e = fem::make_bend_element(m, m.bends[0]);
  EXPECT_NEAR(e.radius, R, 1e-15);
  EXPECT_NEAR(e.angle, kPi / 2, 1e-15);
  const fem::NodeMatrix<2> K = fem::bend_stiffness(e);
  const Eigen::Matrix<double, 12, 6> Rm = fem::rigid_body_modes<2>({e.x_A, e.x_B}, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_LT((K * Rm).norm(), 1e-12 * K.norm());
  // (rho A + NSM) R pi/2, half at each end
  const double mass = (rho * A + 0.3) * R * kPi / 2;
  EXPECT_NEAR(fem::mass_properties(m).mass, mass, 1e-12 * mass);
}

TEST(Cbend, RefusalsNameCardFieldAndWhatWasExpected) {
  EXPECT_EQ(test::read_error("CBEND,5,7,1,2,9,,,5\n"), "deck.bdf:1: CBEND 5, field 9 (GEOM): got integer '5'; expected 1, 2, 3 or 4 (QRG CBEND)");
  EXPECT_EQ(test::read_error("CBEND,5,7,1,2,,,,1\n"),
            "deck.bdf:1: CBEND 5, field 6 (X1/G0): blank; expected an orientation grid G0 or vector X1 X2 X3 (the plane of the bend)");
  EXPECT_EQ(test::read_error("PBEND,7,3,-1.,1.,1.,1.\n"), "deck.bdf:1: PBEND 7, field 4 (A): got real '-1.'; expected a section property > 0");
  // GEOM 3 without RB
  EXPECT_EQ(test::assembly_error(bend_deck("CBEND,5,7,1,2,8,,,3\n", ",,", "")),
            "deck.bdf:8: CBEND 5, field 9 (GEOM): GEOM = 3 and PBEND 7 gives no RB; expected the bend radius RB > 0 on the PBEND");
  // an orientation along the chord
  EXPECT_EQ(test::assembly_error(bend_deck("CBEND,5,7,1,2,-1.,1.,0.,2\n", ",,", "")),
            "deck.bdf:8: CBEND 5, field 6-8 (X1-X3): the orientation is zero or along the chord GA-GB; expected a direction "
            "that, with the chord, spans the plane of the arc");
}

}  // namespace
}  // namespace seflex
