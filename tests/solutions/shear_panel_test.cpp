// CSHEAR/PSHEAR, Nastran's shear panel, against closed forms: a rectangular panel in pure shear
// (edge force G t a delta / b), its extension through the effective rods of F1 (QRG PSHEAR remark 2:
// F1 <= 1.01 gives rods of area F1 T PA / (L12 + L34), F1 = 1 the fully effective panel E T b / a;
// F1 > 1.01 rods of F1 T^2 / 2), the strain energy of a skewed parallelogram against Garvey's
// flexibility (NASTRAN's Z = PA / (2 G t) (1 + 2 cot^2(alpha) / (1 + nu)), COSMIC NASTRAN kpanel.f,
// the parallelogram case), the rigid-body modes of a warped panel, the mass; the writer and back;
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
#include "seflex/fem/element_common.hpp"
#include "seflex/fem/element_shear_panel.hpp"
#include "seflex/fem/mass_properties.hpp"
#include "seflex/io/nastran_writer.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

using test::num;
constexpr double E = 7.0e10, nu = 0.3, G = E / (2 * (1 + nu)), rho = 2800.0, t = 0.002;
constexpr double a = 0.6, b = 0.4;  // panel along x (edge 1-2) and y

std::string panel_deck(const std::string& f12, const std::string& spc_load) {
  return "SOL 101\nCEND\nSPC = 1\nLOAD = 2\nBEGIN BULK\nMAT1,3," + num(E) + ",," + num(nu) + "," + num(rho) + "\n"
         "PSHEAR,7,3," + num(t) + ",0.," + f12 + "\nCSHEAR,5,7,1,2,3,4\n"
         "GRID,1,,0.,0.,0.,,3456\nGRID,2,," + num(a) + ",0.,0.,,3456\nGRID,3,," + num(a) + "," + num(b) + ",0.,,3456\n"
         "GRID,4,,0.," + num(b) + ",0.,,3456\n" + spc_load + "ENDDATA\n";
}

fem::Model round_trip(const fem::Model& m) {
  std::ostringstream out;
  io::write_nastran(m, out);
  return test::read_deck(out.str(), "converted.bdf");
}

// Bottom edge held, the top edge pushed along x by P/2 at each corner: the shear strain delta / b,
// the edge force G t a delta / b = P. The rods (F1 = F2 = 1) do not stretch: the top edge moves as
// one (symmetry) and the sides rotate.
TEST(Cshear, RectangleInPureShear) {
  const double P = 1000.0;
  const fem::Model m = test::read_deck(panel_deck("1.,1.", "SPC1,1,12,1,2\nSPC1,1,2,3,4\nFORCE,2,3,," + num(P / 2) +
                                                                 ",1.,0.,0.\nFORCE,2,4,," + num(P / 2) + ",1.,0.,0.\n"));
  const double delta = P * b / (G * t * a);
  for (const fem::Model& model : {m, round_trip(m)}) {
    const auto s = solutions::solve_static(model);
    EXPECT_NEAR(test::displacement(model, s, 3, 1), delta, 1e-14 * delta);  // measured 6e-16
    EXPECT_NEAR(test::displacement(model, s, 4, 1), delta, 1e-14 * delta);
  }
}

// Left edge held along x (grid 1 also along y), the right edge pulled by P/2 at each corner: the two
// rods along x carry it, u = P a / (2 E A_rod); F1 = 1: A_rod = T PA / (L12 + L34) = T b / 2;
// F1 = 30: A_rod = 15 T^2.
TEST(Cshear, ExtensionThroughTheEffectiveRods) {
  const double P = 1000.0;
  const std::string spc_load = "SPC1,1,1,1,4\nSPC1,1,2,1\nFORCE,2,2,," + num(P / 2) + ",1.,0.,0.\nFORCE,2,3,," + num(P / 2) + ",1.,0.,0.\n";
  for (const auto& [f1, area] : {std::pair{1.0, t * b / 2}, std::pair{0.5, 0.5 * t * b / 2}, std::pair{30.0, 15 * t * t}}) {
    const fem::Model m = test::read_deck(panel_deck(num(f1) + ",1.", spc_load));
    const auto s = solutions::solve_static(m);
    const double u = P * a / (2 * E * area);
    EXPECT_NEAR(test::displacement(m, s, 2, 1), u, 1e-14 * u) << "F1 = " << f1;  // measured 6e-16
    EXPECT_NEAR(test::displacement(m, s, 3, 1), u, 1e-14 * u) << "F1 = " << f1;
  }
}

// A parallelogram with edges e1 = x (length 0.6) and e2 at alpha = 60 degrees (length 0.5), in the
// plane z = 0. Garvey's panel carries a uniform shear flow q on all four edges: the stress
// sigma = s (e1 e2^T + e2 e1^T) (sigma_xx = 2 s cos(alpha), tau_xy = s sin(alpha), q = s t sin(alpha))
// with the complementary energy U = q^2 PA / (2 G t) (1 + 4 G cot^2(alpha) / E) (NASTRAN's Z with
// G = E / (2 (1 + nu))). The linear displacement field of that stress state, u = eps x with
// eps = compliance * sigma, has the panel strain energy u^T K u / 2 = U.
TEST(Cshear, SkewedParallelogramHasGarveysFlexibility) {
  const double alpha = 60.0 * 3.14159265358979323846 / 180.0, L1 = 0.6, L2 = 0.5, s = 2.0e6;
  const Eigen::Vector3d e1(1, 0, 0), e2(std::cos(alpha), std::sin(alpha), 0);
  fem::ShearPanelElement e;
  e.x = {Eigen::Vector3d::Zero(), L1 * e1, L1 * e1 + L2 * e2, L2 * e2};
  e.t = t;
  e.material = {3, E, G, nu, rho};
  const double sxx = 2 * s * std::cos(alpha), txy = s * std::sin(alpha);
  const double exx = sxx / E, eyy = -nu * sxx / E, gxy = txy / G;
  Eigen::Matrix<double, 24, 1> u = Eigen::Matrix<double, 24, 1>::Zero();
  for (int n = 0; n < 4; ++n) {
    const Eigen::Vector3d& x = e.x[static_cast<std::size_t>(n)];
    u[6 * n] = exx * x.x() + 0.5 * gxy * x.y();
    u[6 * n + 1] = 0.5 * gxy * x.x() + eyy * x.y();
  }
  const double PA = L1 * L2 * std::sin(alpha), q = s * t * std::sin(alpha);
  const double U = q * q * PA / (2 * G * t) * (1 + 4 * G / (E * std::tan(alpha) * std::tan(alpha)));
  const double Z_nastran = PA / (2 * G * t) * (1 + 2 / (std::tan(alpha) * std::tan(alpha) * (1 + nu)));
  EXPECT_NEAR(U, q * q * Z_nastran, 1e-12 * U);  // the same flexibility in NASTRAN's form
  const double energy = 0.5 * u.dot(fem::shear_panel_stiffness(e) * u);
  EXPECT_NEAR(energy, U, 1e-14 * U);  // measured 3e-16
  EXPECT_NEAR(fem::shear_panel_area(e), PA, 1e-15);
}

// A warped panel (corners alternately 0.05 above and below the mean plane) with rods: its stiffness
// leaves the six rigid-body motions force-free (the normal kick forces of the shear mode); K is
// symmetric with rank 1 + 4 (the shear mode and four rods).
TEST(Cshear, WarpedPanelRigidBodyModes) {
  fem::ShearPanelElement e;
  e.x = {Eigen::Vector3d(0, 0, 0.05), Eigen::Vector3d(0.7, 0.1, -0.05), Eigen::Vector3d(0.6, 0.5, 0.05),
         Eigen::Vector3d(-0.1, 0.4, -0.05)};
  e.t = t;
  e.f1 = 0.8;
  e.f2 = 2.0;
  e.material = {3, E, G, nu, rho};
  const fem::NodeMatrix<4> K = fem::shear_panel_stiffness(e);
  const Eigen::Matrix<double, 24, 6> R = fem::rigid_body_modes<4>(e.x, Eigen::Vector3d(0.3, 0.2, 0.0));
  EXPECT_LT((K * R).norm(), 1e-9 * K.norm()) << K * R;
  EXPECT_LT((K - K.transpose()).norm(), 1e-15 * K.norm());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(K);
  int rank = 0;
  for (int i = 0; i < 24; ++i) rank += es.eigenvalues()[i] > 1e-10 * es.eigenvalues().maxCoeff();
  EXPECT_EQ(rank, 5);
}

// Mass (rho T + NSM) PA, lumped: a quarter at each corner of a rectangle.
TEST(Cshear, LumpedMass) {
  const fem::Model m = test::read_deck(panel_deck("0.,0.", "SPC1,1,123,1\n"));
  const fem::MassProperties mp = fem::mass_properties(m);
  EXPECT_NEAR(mp.mass, rho * t * a * b, 1e-12 * rho * t * a * b);
  EXPECT_LT((mp.cg - Eigen::Vector3d(a / 2, b / 2, 0)).norm(), 1e-15);
}

TEST(Cshear, RefusalsNameCardFieldAndWhatWasExpected) {
  EXPECT_EQ(test::read_error("PSHEAR,7,3,0.\n"), "deck.bdf:1: PSHEAR 7, field 4 (T): got real '0.'; expected a thickness > 0");
  EXPECT_EQ(test::read_error("PSHEAR,7,3,0.002,,-1.\n"),
            "deck.bdf:1: PSHEAR 7, field 6 (F1): got real '-1.'; expected an effectiveness factor >= 0 (0 or blank: none)");
  EXPECT_EQ(test::read_error("CSHEAR,5,7,1,2,3,2\n"), "deck.bdf:1: CSHEAR 5, field 7 (G4): grid 2 repeats G2; expected distinct grids");
  const std::string grids = "MAT1,3,7.e10,,0.3\nPSHEAR,7,3,0.002\nGRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,0.2,0.2,0.\nGRID,4,,0.,1.,0.\n";
  EXPECT_EQ(test::read_error(grids + "CSHEAR,5,8,1,2,3,4\n"),
            "deck.bdf:7: CSHEAR 5, field 3 (PID): references property 8, which is not defined; expected the id of a PSHEAR card");
  // grid 3 inside the triangle 1-2-4: a re-entrant corner
  EXPECT_EQ(test::assembly_error(grids + "CSHEAR,5,7,1,2,3,4\n"),
            "deck.bdf:7: CSHEAR 5, field 6 (G3): the interior angle at G3 is 180 degrees or more; expected a convex panel "
            "with G1-G4 in order around it (QRG CSHEAR remark 3)");
}

}  // namespace
}  // namespace seflex
