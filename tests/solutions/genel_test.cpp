// GENEL in its stiffness (K) and flexibility (Z) forms, with S given or computed from six UD dofs
// (MSC QRG GENEL: K_e = [K, -K S; -S^T K, S^T K S]). References: a cantilever's tip flexibility
// [L^3/3EI, L^2/2EI; L^2/2EI, L/EI] (Euler-Bernoulli), whose GENEL must reproduce the CBAR's plane-1
// bending stiffness on both grids (S the rigid map v2 = v1 + L theta1); a spring between two dofs
// as K = k, S = 1 equal to a CELAS2; the element's rigid-body modes as null vectors. The writer
// and back; refusals by their whole message.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <sstream>
#include <string>

#include "assembly_test_util.hpp"
#include "nastran_test_util.hpp"
#include "statics_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_common.hpp"
#include "seflex/io/nastran_writer.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

using test::num;

Eigen::MatrixXd dense_K(const fem::Model& m) { return Eigen::MatrixXd(fem::assemble(m, fem::assembly_options(m)).K); }

fem::Model round_trip(const fem::Model& m) {
  std::ostringstream out;
  io::write_nastran(m, out);
  return test::read_deck(out.str(), "converted.bdf");
}

constexpr double E = 2.0e11, I = 3.0e-6, L = 1.5;

// Grid 1 at the origin, grid 2 at (L, 0, 0). UI: grid 2's T2 and R3; UD: grid 1's 123456 (S computed).
std::string cantilever_genel(bool flexibility) {
  const double a = L * L * L / (3 * E * I), b = L * L / (2 * E * I), c = L / (E * I);  // tip flexibility
  const double k11 = 12 * E * I / (L * L * L), k21 = -6 * E * I / (L * L), k22 = 4 * E * I / L;  // its inverse
  std::string s = "GENEL,7,,2,2,2,6\n,UD,,1,1,1,2,1,3\n,1,4,1,5,1,6\n";
  s += flexibility ? ",Z," + num(a) + "," + num(b) + "," + num(c) + "\n" : ",K," + num(k11) + "," + num(k21) + "," + num(k22) + "\n";
  return s;
}

const std::string kGrids = "GRID,1,,0.,0.,0.\nGRID,2,,1.5,0.,0.\n";

TEST(Genel, CantileverFlexibilityAndStiffnessFormsMatchTheCbarBending) {
  // CBAR with I1 = I (plane 1: bending in x-y, v and theta_z), no shear flexibility (K1 blank)
  const fem::Model bar = test::read_deck(kGrids + "MAT1,3," + num(E) + ",,0.3\nPBAR,4,3,1.e-3," + num(I) + ",1.e-6,1.e-6\n"
                                                  "CBAR,5,4,1,2,0.,1.,0.\n");
  const Eigen::MatrixXd Kb = dense_K(bar);
  const int dofs[4] = {1, 5, 7, 11};  // v1, theta_z1, v2, theta_z2 (0-based g-set)
  Eigen::Matrix4d Kbar;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) Kbar(i, j) = Kb(dofs[i], dofs[j]);
  for (const bool z : {true, false}) {
    const fem::Model m = test::read_deck(kGrids + cantilever_genel(z));
    for (const fem::Model& model : {m, round_trip(m)}) {
      const Eigen::MatrixXd K = dense_K(model);
      Eigen::Matrix4d Kg;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) Kg(i, j) = K(dofs[i], dofs[j]);
      EXPECT_LT((Kg - Kbar).norm(), 1e-10 * Kbar.norm()) << (z ? "Z" : "K") << "\n" << Kg << "\n" << Kbar;
      EXPECT_NEAR(K.norm(), Kg.norm(), 1e-12 * K.norm());  // nothing outside the bending block
      // the element's rigid-body motions are null vectors
      const Eigen::Matrix<double, 12, 6> R = fem::rigid_body_modes<2>({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(L, 0, 0)});
      EXPECT_LT((K * R).norm(), 1e-12 * K.norm());
    }
  }
  // clamped at grid 1, a tip force F gives the cantilever's v = F L^3 / (3 E I)
  const double F = 500.0;
  const fem::Model m = test::read_deck("SOL 101\nCEND\nSPC = 1\nLOAD = 2\nBEGIN BULK\n" + kGrids + cantilever_genel(true) +
                                       "SPC1,1,123456,1\nSPC1,1,1345,2\nFORCE,2,2,," + num(F) + ",0.,1.,0.\nENDDATA\n");
  const auto s = solutions::solve_static(m);
  // measured: 1e-15 of both
  EXPECT_NEAR(test::displacement(m, s, 2, 2), F * L * L * L / (3 * E * I), 1e-13 * F * L * L * L / (3 * E * I));
  EXPECT_NEAR(test::displacement(m, s, 2, 6), F * L * L / (2 * E * I), 1e-13 * F * L * L / (2 * E * I));
}

// K = k on UI = (grid 2, 1), UD = (grid 1, 1), S = 1: the spring k (u2 - u1)^2 / 2, a CELAS2.
TEST(Genel, GivenSEqualsASpring) {
  const fem::Model genel = test::read_deck(kGrids + "GENEL,7,,2,1\n,UD,,1,1\n,K,250.\n,S,1.\n");
  const fem::Model spring = test::read_deck(kGrids + "CELAS2,7,250.,2,1,1,1\n");
  EXPECT_LT((dense_K(genel) - dense_K(spring)).norm(), 1e-13);
  EXPECT_LT((dense_K(round_trip(genel)) - dense_K(spring)).norm(), 1e-13);
  // a scalar point among the dofs, no UD: K alone
  const fem::Model sp = test::read_deck(kGrids + "SPOINT,9\nGENEL,8,,9,0,2,3\n,K,2.,-1.,3.\n");
  const fem::DofMap dofs = fem::make_dof_map(sp);
  const Eigen::MatrixXd K = dense_K(sp);
  const Eigen::Index s9 = *fem::find_dof(sp, dofs, 9, 0), g23 = *fem::find_dof(sp, dofs, 2, 3);
  EXPECT_EQ(K(s9, s9), 2.0);
  EXPECT_EQ(K(g23, s9), -1.0);
  EXPECT_EQ(K(g23, g23), 3.0);
}

TEST(Genel, RefusalsNameCardFieldAndWhatWasExpected) {
  EXPECT_EQ(test::read_error(kGrids + "GENEL,7,,2,1,2,2\n,K,1.,2.\n"),
            "deck.bdf:3: GENEL 7: 2 K values for 2 UI dofs; expected the lower triangle, 3 values");
  EXPECT_EQ(test::read_error(kGrids + "GENEL,7,,2,1\n,UD,,1,1,1,2\n,K,1.\n"),
            "deck.bdf:3: GENEL 7: 2 UD dofs and no S; expected S, or six UD dofs that fix the rigid-body motion (S is then "
            "computed from the geometry)");
  EXPECT_EQ(test::read_error(kGrids + "GENEL,7,,2,7\n,K,1.\n"),
            "deck.bdf:3: GENEL 7, field 5 (CIi): got integer '7'; expected one component 1-6 (grid) or 0 (scalar point)");
  EXPECT_EQ(test::read_error(kGrids + "GENEL,7,,2,1\n,S,1.\n"),
            "deck.bdf:4: GENEL 7, field 2 (keyword): got text 'S'; expected UD, K or Z (each once, in this order)");
  EXPECT_EQ(test::read_error(kGrids + "GENEL,7,,3,1\n,K,1.\n"),
            "deck.bdf:3: GENEL 7, field UIi: references point 3, which is not defined; expected the id of a GRID or SPOINT");
  EXPECT_EQ(test::assembly_error(kGrids + "GENEL,7,,2,1,2,2\n,Z,1.,1.,1.\n"),
            "deck.bdf:3: GENEL 7, field Z: the flexibility matrix Z is singular; expected an invertible Z (K = Z^-1)");
  // six UD dofs that leave the rotation about x free
  EXPECT_EQ(test::assembly_error(kGrids + "GENEL,7,,2,2\n,UD,,1,1,1,2,1,3\n,1,5,1,6,2,1\n,K,1.\n"),
            "deck.bdf:3: GENEL 7, field UDi: the six UD dofs cannot describe every rigid-body motion of the element, so S "
            "cannot be computed; expected six UD dofs that fix all six rigid-body motions (e.g. 123456 of one grid), "
            "or S given on the card");
}

}  // namespace
}  // namespace seflex
