// CQUADR and CTRIAR: CQUAD4/CTRIA3 with Allman-type membranes whose drilling rotations enter the
// in-plane field (element_membrane_drilling.hpp). Checked: the membrane patch test on distorted
// meshes (with theta_z = the membrane rotation) and the six rigid-body modes of warped elements;
// the straight cantilever in in-plane shear (MacNeal & Harder, Finite Elements in Analysis and
// Design 1 (1985) 3-20, reference 0.1081 = Timoshenko's P L^3/3EI + P L/(k G A)) refined from their
// 6 x 1 mesh to 48 x 8, converging to it, and its tip rotation to the beam's slope P L^2 / 2EI;
// K6ROT has no effect; the plate part is CQUAD4's; the writer and back.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <sstream>
#include <string>

#include "nastran_test_util.hpp"
#include "statics_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_common.hpp"
#include "seflex/fem/element_shell_quad4.hpp"
#include "seflex/fem/element_shell_tria3.hpp"
#include "seflex/io/nastran_writer.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

using test::num;

/// The MacNeal-Harder straight cantilever (length 6, depth 0.2, thickness 0.1, E = 1e7, nu = 0.3)
/// in nx x ny quadrilaterals or twice as many triangles, clamped at x = 0, a unit in-plane shear at
/// the tip shared equally by its grids.
std::string cantilever(const std::string& card, bool tri, int nx = 6, int ny = 1) {
  std::ostringstream d;
  d << "SOL 101\nCEND\nSPC = 1\nLOAD = 2\nBEGIN BULK\nMAT1,3,1.e7,,0.3\nPSHELL,7,3,0.1,3,,3\n";
  auto id = [&](int i, int j) { return 1000 * i + j + 1; };
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j) {
      d << "GRID," << id(i, j) << ",," << num(6.0 * i / nx) << "," << num(0.2 * j / ny) << ",0.,,345\n";
      if (i == 0) d << "SPC1,1,126," << id(i, j) << "\n";
      if (i == nx) d << "FORCE,2," << id(i, j) << ",," << num(1.0 / (ny + 1)) << ",0.,1.,0.\n";
    }
  int eid = 1;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), e = id(i, j + 1);
      if (!tri) d << card << "," << eid++ << ",7," << a << "," << b << "," << c << "," << e << "\n";
      else d << card << "," << eid++ << ",7," << a << "," << b << "," << c << "\n" << card << "," << eid++ << ",7," << a << "," << c << "," << e << "\n";
    }
  d << "ENDDATA\n";
  return d.str();
}

/// Mean tip displacement component `component` over the tip grids.
double tip(const std::string& card, bool tri, int nx = 6, int ny = 1, int component = 2) {
  const fem::Model m = test::read_deck(cantilever(card, tri, nx, ny));
  const auto s = solutions::solve_static(m);
  double sum = 0;
  for (int j = 0; j <= ny; ++j) sum += test::displacement(m, s, 1000 * nx + j + 1, component);
  return sum / (ny + 1);
}

// Tip deflection / 0.1081 and tip rotation / (P L^2 / 2EI = 0.027), measured (this build):
//   mesh    CQUADR  CQUAD4  CTRIAR  CTRIA3  | CQUADR rotation
//   6 x 1   0.9036  0.9929  0.1449  0.0316  | 0.9102   (MacNeal-Harder's mesh, elements 1 x 0.2)
//   12 x 2  0.9711  0.9933  0.4018  0.1119  | 0.9744
//   24 x 4  0.9911  0.9964  0.7252  0.3339  | 0.9928
//   48 x 8  0.9967  0.9981  0.9107  0.6661  | 0.9979
// Both drilling elements converge to the beam's answer, CQUADR's error falling by 3.3 per halving;
// Allman's triangle is stiff on these elongated (5:1) triangles (its edges carry only linear
// tangential displacement, so in-plane bending is not exact) but far less so than the CST.
TEST(ShellDrilling, CantileverInPlaneShear) {
  const double ref = 0.1081, slope = 6.0 * 6.0 / (2 * 1e7 * 0.1 * 0.008 / 12);
  const double e12 = 1 - tip("CQUADR", false, 12, 2) / ref, e24 = 1 - tip("CQUADR", false, 24, 4) / ref;
  EXPECT_GT(e24, 0.0);
  EXPECT_GT(e12 / e24, 3.0);                                          // measured 3.25
  EXPECT_NEAR(tip("CQUADR", false, 48, 8) / ref, 1.0, 5e-3);          // measured 3.3e-3
  EXPECT_NEAR(tip("CQUADR", false, 48, 8, 6) / slope, 1.0, 5e-3);     // measured 2.1e-3
  const double triar48 = tip("CTRIAR", true, 48, 8) / ref;
  EXPECT_NEAR(triar48, 1.0, 0.1);                                     // measured 0.089
  // Allman's triangle on a mesh beats the CST on the mesh twice as fine
  EXPECT_LT(1 - tip("CTRIAR", true, 24, 4) / ref, 1 - tip("CTRIA3", true, 48, 8) / ref);  // 0.27 < 0.33
  EXPECT_LT(1 - triar48, 1 - tip("CTRIA3", true, 48, 8) / ref);
}

// A distorted patch (inner grid moved) of four CQUADR or eight CTRIAR in a constant membrane strain
// u = 1e-3 (x + 0.5 y), v = 1e-3 (-0.3 x + 2 y), theta_z = (v,x - u,y)/2 = -0.4e-3 given on the
// boundary: the inner grid follows the field exactly.
TEST(ShellDrilling, MembranePatchTest) {
  for (const bool tri : {false, true}) {
    std::ostringstream d;
    d << "SOL 101\nCEND\nSPC = 1\nBEGIN BULK\nMAT1,3,2.1+11,,0.3\nPSHELL,7,3,0.01,3,,3\n";
    const double X[9] = {0, 1, 2, 0, 1.1, 2, 0, 1, 2}, Y[9] = {0, 0, 0, 1, 0.9, 1, 2, 2, 2};
    for (int k = 0; k < 9; ++k) {
      d << "GRID," << k + 1 << ",," << num(X[k]) << "," << num(Y[k]) << ",0.\nSPC1,1,345," << k + 1 << "\n";
      if (k == 4) continue;
      const double u = 1e-3 * (X[k] + 0.5 * Y[k]), v = 1e-3 * (-0.3 * X[k] + 2 * Y[k]);
      d << "SPC,1," << k + 1 << ",1," << num(u) << "\nSPC,1," << k + 1 << ",2," << num(v) << "\nSPC,1," << k + 1 << ",6,-0.0004\n";
    }
    int eid = 1;
    for (const auto& [a, b, c, e] : {std::array<int, 4>{1, 2, 5, 4}, {2, 3, 6, 5}, {4, 5, 8, 7}, {5, 6, 9, 8}}) {
      if (tri) d << "CTRIAR," << eid++ << ",7," << a << "," << b << "," << c << "\nCTRIAR," << eid++ << ",7," << a << "," << c << "," << e << "\n";
      else d << "CQUADR," << eid++ << ",7," << a << "," << b << "," << c << "," << e << "\n";
    }
    const fem::Model m = test::read_deck(d.str() + "ENDDATA\n");
    const auto s = solutions::solve_static(m);
    EXPECT_NEAR(test::displacement(m, s, 5, 1), 1e-3 * (1.1 + 0.45), 1e-17) << tri;  // measured 0 to 4e-19
    EXPECT_NEAR(test::displacement(m, s, 5, 2), 1e-3 * (-0.33 + 1.8), 1e-17) << tri;
    EXPECT_NEAR(test::displacement(m, s, 5, 6), -0.4e-3, 1e-17) << tri;
  }
}

/// Rigid-body modes and the count of zero eigenvalues of an element's stiffness.
template <int N>
void expect_six_rigid_modes(const fem::NodeMatrix<N>& K, const std::array<Eigen::Vector3d, N>& x, const char* what) {
  const auto R = fem::rigid_body_modes<N>(x, Eigen::Vector3d(0.3, 0.2, 0.1));
  EXPECT_LT((K * R).norm(), 1e-12 * K.norm()) << what;
  const Eigen::MatrixXd Kd = K;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Kd);
  int zero = 0;
  for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) zero += es.eigenvalues()[i] < 1e-10 * es.eigenvalues().maxCoeff();
  EXPECT_EQ(zero, 6) << what << ": " << es.eigenvalues().head(8).transpose();
}

TEST(ShellDrilling, RigidBodyModesK6rotAndThePlatePart) {
  const fem::Model m = test::read_deck(
      "MAT1,3,2.1+11,,0.3\nPSHELL,7,3,0.01,3,,3\nGRID,1,,0.,0.,0.02\nGRID,2,,1.1,0.1,-0.02\nGRID,3,,1.,0.9,0.02\n"
      "GRID,4,,-0.1,1.,-0.02\nCQUADR,1,7,1,2,3,4\nCQUAD4,2,7,1,2,3,4\nCTRIAR,3,7,1,2,3\nCTRIA3,4,7,1,2,3\n");
  ASSERT_EQ(m.shells.size(), 4u);
  EXPECT_TRUE(m.shells[0].drilling);
  EXPECT_FALSE(m.shells[1].drilling);
  const fem::Quad4Element qr = fem::make_quad4_element(m, m.shells[0]), q4 = fem::make_quad4_element(m, m.shells[1]);
  const fem::Tria3Element tr = fem::make_tria3_element(m, m.shells[2]);
  expect_six_rigid_modes<4>(fem::quad4_stiffness(qr, 100.0), qr.x, "CQUADR");
  expect_six_rigid_modes<3>(fem::tria3_stiffness(tr, 100.0), tr.x, "CTRIAR");
  // K6ROT has no effect on them
  EXPECT_EQ((fem::quad4_stiffness(qr, 100.0) - fem::quad4_stiffness(qr, 0.0)).norm(), 0.0);
  EXPECT_EQ((fem::tria3_stiffness(tr, 100.0) - fem::tria3_stiffness(tr, 0.0)).norm(), 0.0);
  // a flat element without membrane-bending coupling: the plate block (w, theta_x, theta_y) is CQUAD4's
  fem::Quad4Element flat_r = qr, flat_4 = q4;
  for (auto* e : {&flat_r, &flat_4})
    for (auto& x : e->x) x.z() = 0.0;
  const fem::NodeMatrix<4> Kr = fem::quad4_stiffness(flat_r, 0.0), K4 = fem::quad4_stiffness(flat_4, 0.0);
  double diff = 0, norm = 0;
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j)
      if (i % 6 >= 2 && i % 6 <= 4 && j % 6 >= 2 && j % 6 <= 4) {
        diff = std::max(diff, std::abs(Kr(i, j) - K4(i, j)));
        norm = std::max(norm, std::abs(K4(i, j)));
      }
  EXPECT_LE(diff, 1e-15 * norm);
  // the writer gives back CQUADR and CTRIAR
  std::ostringstream out;
  io::write_nastran(m, out);
  const fem::Model back = test::read_deck(out.str(), "converted.bdf");
  ASSERT_EQ(back.shells.size(), 4u);
  EXPECT_TRUE(back.shells[0].drilling && back.shells[2].drilling && !back.shells[1].drilling && !back.shells[3].drilling);
}

}  // namespace
}  // namespace seflex
