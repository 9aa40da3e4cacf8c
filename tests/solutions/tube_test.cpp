// CTUBE/PTUBE: a CROD whose section is a tube of outside diameter OD and wall T (QRG PTUBE; T = 0 or
// blank: a solid rod). Checked against the closed forms of a tube, A = pi (D^2 - d^2)/4 and
// J = pi (D^4 - d^4)/32 with d = D - 2T: a cantilever's axial and torsional end displacements, the
// element's mass with NSM, its rigid-body modes, the equal CROD/PROD; the writer and back; refusals
// by their whole message.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <sstream>
#include <string>

#include "nastran_test_util.hpp"
#include "statics_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_common.hpp"
#include "seflex/fem/mass_properties.hpp"
#include "seflex/io/nastran_writer.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

using test::num;
constexpr double kPi = 3.14159265358979323846;
constexpr double E = 7.0e10, nu = 0.3, G = E / (2 * (1 + nu)), rho = 2700.0;

// A tube from grid 1 (held) to grid 2 along (1, 2, 2)/3, length L = 3: axial force F and torque M at
// grid 2 along the axis.
std::string tube_deck(const std::string& ptube, const std::string& element = "CTUBE,5,7,1,2\n") {
  return "SOL 101\nCEND\nSPC = 1\nLOAD = 2\nBEGIN BULK\nMAT1,3," + num(E) + ",," + num(nu) + "," + num(rho) + "\n" + ptube +
         element + "GRID,1,,0.,0.,0.\nGRID,2,,1.,2.,2.\nSPC1,1,123456,1\n"
         "FORCE,2,2,,1000.,1.,2.,2.\nMOMENT,2,2,,30.,1.,2.,2.\nENDDATA\n";
}

/// Axial displacement and twist of grid 2 along the tube's axis.
std::pair<double, double> axial_and_twist(const fem::Model& m) {
  const auto s = solutions::solve_static(m);
  const Eigen::Vector3d n(1.0 / 3, 2.0 / 3, 2.0 / 3);
  Eigen::Vector3d u, r;
  for (int c = 1; c <= 3; ++c) {
    u[c - 1] = test::displacement(m, s, 2, c);
    r[c - 1] = test::displacement(m, s, 2, c + 3);
  }
  return {u.dot(n), r.dot(n)};
}

TEST(Ctube, CantileverAgainstTheTubeClosedForms) {
  const double L = 3.0, F = 3000.0, M = 90.0;  // FORCE 1000 (1, 2, 2) has magnitude 3000
  for (const auto& [D, T] : {std::pair{0.05, 0.002}, std::pair{0.04, 0.02}, std::pair{0.03, 0.0}}) {
    const double d = T == 0.0 ? 0.0 : D - 2 * T;
    const double A = kPi * (D * D - d * d) / 4, J = kPi * (std::pow(D, 4) - std::pow(d, 4)) / 32;
    const std::string ptube = "PTUBE,7,3," + num(D) + (T == 0.0 ? std::string(",\n") : "," + num(T) + "\n");
    const fem::Model m = test::read_deck(tube_deck(ptube));
    const auto [u, phi] = axial_and_twist(m);
    EXPECT_NEAR(u, F * L / (E * A), 1e-14 * F * L / (E * A)) << "D = " << D << " T = " << T;  // measured 1.3e-16
    EXPECT_NEAR(phi, M * L / (G * J), 1e-14 * M * L / (G * J)) << "D = " << D << " T = " << T;  // measured 4e-16
    // the same tube written as CROD/PROD with the closed-form A, J: the same stiffness
    const fem::Model rod = test::read_deck(tube_deck("PROD,7,3," + num(A) + "," + num(J) + "\n", "CROD,5,7,1,2\n"));
    const Eigen::MatrixXd Kt(fem::assemble(m, fem::assembly_options(m)).K), Kr(fem::assemble(rod, fem::assembly_options(rod)).K);
    EXPECT_LT((Kt - Kr).norm(), 1e-13 * Kr.norm());
    std::ostringstream out;
    io::write_nastran(m, out);
    const fem::Model back = test::read_deck(out.str(), "converted.bdf");
    EXPECT_NEAR(axial_and_twist(back).first, u, 1e-15 * std::abs(u));
  }
}

// Mass (rho A + NSM) L, lumped half at each end: the total and the centre of gravity at mid-length;
// the element's stiffness leaves the six rigid-body motions of its two grids without force.
TEST(Ctube, MassWithNsmAndRigidBodyModes) {
  const double D = 0.05, T = 0.002, nsm = 0.7, L = 3.0;
  const double A = kPi * (D * D - (D - 2 * T) * (D - 2 * T)) / 4;
  const fem::Model m = test::read_deck(tube_deck("PTUBE,7,3," + num(D) + "," + num(T) + "," + num(nsm) + "\n"));
  const fem::MassProperties mp = fem::mass_properties(m);
  EXPECT_NEAR(mp.mass, (rho * A + nsm) * L, 1e-12 * (rho * A + nsm) * L);
  EXPECT_LT((mp.cg - Eigen::Vector3d(0.5, 1.0, 1.0)).norm(), 1e-14);
  const Eigen::MatrixXd K(fem::assemble(m, fem::assembly_options(m)).K);
  const Eigen::Matrix<double, 12, 6> R = fem::rigid_body_modes<2>({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 2)});
  EXPECT_LT((K * R).norm(), 1e-15 * K.norm()) << K * R;
}

TEST(Ctube, RefusalsNameCardFieldAndWhatWasExpected) {
  EXPECT_EQ(test::read_error("PTUBE,7,3,0.05,0.03\n"),
            "deck.bdf:1: PTUBE 7, field 5 (T): got real '0.03'; expected a wall thickness 0 <= T <= OD/2 (0 or blank: a solid rod)");
  EXPECT_EQ(test::read_error("PTUBE,7,3,-0.05\n"), "deck.bdf:1: PTUBE 7, field 4 (OD): got real '-0.05'; expected an outside diameter > 0");
  const std::string mat = "MAT1,3,7.e10,,0.3\nGRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\n";
  EXPECT_EQ(test::read_error(mat + "PROD,7,3,1.e-4\nCTUBE,5,7,1,2\n"), "deck.bdf:5: CTUBE 5, field 3 (PID): references PROD 7; expected a PTUBE");
  EXPECT_EQ(test::read_error(mat + "PTUBE,7,3,0.05\nCROD,5,7,1,2\n"), "deck.bdf:5: CROD 5, field 3 (PID): references PTUBE 7; expected a PROD");
  EXPECT_EQ(test::read_error(mat + "CTUBE,5,7,1,2\n"),
            "deck.bdf:4: CTUBE 5, field 3 (PID): references property 7, which is not defined; expected the id of a PTUBE card");
  // OD2 tapers the tube in heat transfer only (QRG PTUBE remark 5): the structure keeps OD, listed
  const fem::Model m = test::read_deck(mat + "PTUBE,7,3,0.05,0.002,,0.06\nCTUBE,5,7,1,2\n");
  ASSERT_EQ(m.unsupported.size(), 1u);
  EXPECT_EQ(m.unsupported[0].name, "PTUBE OD2 (tapered; MSC Nastran tapers tubes in heat transfer only: the structure uses OD)");
}

}  // namespace
}  // namespace seflex
