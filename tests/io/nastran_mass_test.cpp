// Mass properties of read decks, the way Nastran's grid point weight generator reports them, against
// values derived by hand: Nastran's default lumped mass puts half of a bar's or rod's mass
// (rho A + NSM) L on each end, a quarter (third) of a CQUAD4 (CTRIA3) mass (rho t + NSM) area on each
// corner; CONM2 adds its mass at grid + offset and its inertia about its CG. The GPWG sums these point
// masses: M0 = sum m [I, -S(r); S(r), -S(r)^2], CG = first moment / mass, inertia about the CG.
// WTMASS is not applied (GPWG prints the deck's units) and GRDPNT sets the reference point.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <sstream>

#include "nastran_test_util.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/fem/mass_properties.hpp"
#include "seflex/io/nastran.hpp"
#include "test_support.hpp"

using namespace seflex;

namespace {

/// Point masses summed by hand.
struct PointMasses {
  double mass = 0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  std::vector<std::pair<double, Eigen::Vector3d>> points;
  Eigen::Matrix3d extra_inertia = Eigen::Matrix3d::Zero();  ///< inertias of CONM2 about their own CG

  void add(double m, const Eigen::Vector3d& x) {
    mass += m;
    moment += m * x;
    points.emplace_back(m, x);
  }
  Eigen::Vector3d cg() const { return moment / mass; }
  /// Inertia tensor about point p: sum m (|r|^2 I - r r^T), r = x - p.
  Eigen::Matrix3d inertia_about(const Eigen::Vector3d& p) const {
    Eigen::Matrix3d I = extra_inertia;
    for (const auto& [m, x] : points) {
      const Eigen::Vector3d r = x - p;
      I += m * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
    }
    return I;
  }
};

const Eigen::Vector3d& xb(const fem::Model& m, int grid) { return m.grids.at(m.grid_index.at(grid)).x_basic; }

/// Lumped point masses of bars, rods, shells and CONM2 of a deck (no rotary inertia from elements).
PointMasses lumped(const fem::Model& m) {
  PointMasses pm;
  auto rho = [&](int mid) { return m.mat1.at(m.mat1_index.at(mid)).rho; };
  for (const auto& b : m.bars) {
    const auto& p = m.bar_props.at(m.bar_prop_index.at(b.pid));
    const double mass = (rho(p.mid) * p.A + p.nsm) * (xb(m, b.gb) - xb(m, b.ga)).norm();
    pm.add(mass / 2, xb(m, b.ga));
    pm.add(mass / 2, xb(m, b.gb));
  }
  for (const auto& r : m.rods) {
    const auto& p = m.rod_props.at(m.rod_prop_index.at(r.pid));
    const double mass = (rho(p.mid) * p.A + p.nsm) * (xb(m, r.gb) - xb(m, r.ga)).norm();
    pm.add(mass / 2, xb(m, r.ga));
    pm.add(mass / 2, xb(m, r.gb));
  }
  for (const auto& s : m.shells) {
    const auto& p = m.shell_props.at(m.shell_prop_index.at(s.pid));
    const Eigen::Vector3d a = xb(m, s.g[0]), b = xb(m, s.g[1]), c = xb(m, s.g[2]);
    double area = 0.5 * (b - a).cross(c - a).norm();
    if (s.nnode == 4) area += 0.5 * (c - a).cross(xb(m, s.g[3]) - a).norm();  // flat quad: two triangles
    const double mass = (rho(p.mid1) * p.t + p.nsm) * area;
    for (int k = 0; k < s.nnode; ++k) pm.add(mass / s.nnode, xb(m, s.g[k]));
  }
  for (const auto& c : m.conm2) {
    EXPECT_EQ(c.cid, 0) << "lumped() handles CONM2 with CID 0 only";
    pm.add(c.m, xb(m, c.grid) + c.x);
    Eigen::Matrix3d I;
    I << c.I11, -c.I21, -c.I31, -c.I21, c.I22, -c.I32, -c.I31, -c.I32, c.I33;
    pm.extra_inertia += I;
  }
  return pm;
}

void expect_matches(const fem::MassProperties& mp, const PointMasses& pm, const Eigen::Vector3d& ref) {
  const double scale = pm.mass;
  EXPECT_NEAR(mp.mass, pm.mass, 1e-12 * scale);
  EXPECT_LT((mp.cg - pm.cg()).norm(), 1e-10 * (1.0 + pm.cg().norm()));
  const Eigen::Matrix3d I = pm.inertia_about(pm.cg());
  EXPECT_LT((mp.I_cg - I).norm(), 1e-10 * I.norm()) << "got\n" << mp.I_cg << "\nexpected\n" << I;
  // M0 about the reference point: translation block m I, rotation block = inertia about the reference
  EXPECT_NEAR(mp.M0(0, 0), pm.mass, 1e-12 * scale);
  const Eigen::Matrix3d Iref = pm.inertia_about(ref);
  EXPECT_LT((mp.M0.bottomRightCorner<3, 3>() - Iref).norm(), 1e-10 * Iref.norm());
  EXPECT_LT((mp.reference - ref).norm(), 1e-14);
}

fem::Model read(const char* rel) { return io::read_nastran(test::validation_dir() / rel); }

}  // namespace

TEST(NastranMassProperties, CantileverBarByHand) {
  // 4 CBAR, rho A = 0.1 x 0.1, total length 100: mass 1.0 at CG x = 50; lumped: 1/8 at the ends and
  // 1/4 at the inner grids, so Iyy = Izz = 2 (1/8) 50^2 + 2 (1/4) 25^2 = 937.5 about the CG, and no
  // rotary inertia (Ixx = 0). WTMASS .002591 is not applied; GRDPNT 0 = basic origin.
  const fem::Model m = read("mystran_cbar_cantilever_and_freefree_modes/BAR-CC-GIV.DAT");
  const fem::MassProperties mp = fem::mass_properties(m);
  EXPECT_DOUBLE_EQ(mp.wtmass, 0.002591);
  EXPECT_NEAR(mp.mass, 1.0, 1e-14);
  EXPECT_NEAR(mp.cg.x(), 50.0, 1e-12);
  EXPECT_NEAR(mp.I_cg(0, 0), 0.0, 1e-12);
  EXPECT_NEAR(mp.I_cg(1, 1), 937.5, 1e-10);
  EXPECT_NEAR(mp.I_cg(2, 2), 937.5, 1e-10);
  EXPECT_EQ(mp.reference_grid, 0);
}

TEST(NastranMassProperties, CraigBamptonFrameAndGrdpnt) {
  // 10 CBAR (rho 0.1; A .36, .1, 6.) lumped to their ends, 5 CONM2 of 150 at grid + (0, 0, -5).
  const fem::Model m = read("mystran_craig_bampton_cbar_frame/CB-EXAMPLE-12.DAT");
  const PointMasses pm = lumped(m);
  // total by hand: 0.1 (2 x .36 x sqrt(15000) + 4 x .1 x 100 + 4 x 6 x sqrt(5000)) + 5 x 150
  EXPECT_NEAR(pm.mass, 0.1 * (0.72 * std::sqrt(15000.) + 40. + 24. * std::sqrt(5000.)) + 750., 1e-9);
  expect_matches(fem::mass_properties(m), pm, Eigen::Vector3d::Zero());
  // a reference grid (as PARAM GRDPNT 12 or seflex info --grdpnt 12 would set)
  const fem::MassProperties at12 = fem::mass_properties(m, 12);
  EXPECT_EQ(at12.reference_grid, 12);
  expect_matches(at12, pm, Eigen::Vector3d(100, 0, 0));
}

TEST(NastranMassProperties, MixedElementsShelfByHand) {
  // shells: area 2 x 2500 + 4 x 1250 = 10000, rho t = .1 x .125 -> 125; bars: 14 x 50 x A 2 x .1 = 140;
  // rods: A 1, 3 x 50 + 3 x sqrt(100^2 + 50^2), x .1.
  const fem::Model m = read("mystran_mixed_cbar_crod_cquad4_ctria3_celas_modes/ALL-ELEM-TEST-GIV.DAT");
  const PointMasses pm = lumped(m);
  EXPECT_NEAR(pm.mass, 125. + 140. + 0.1 * (150. + 3. * std::sqrt(12500.)), 1e-9);
  expect_matches(fem::mass_properties(m), pm, Eigen::Vector3d::Zero());
}

TEST(NastranMassProperties, NsmConm2OffsetsAndInertia) {
  const std::string deck =
      "MAT1,1,2.1+11,,.3,2.\n"
      "GRID,1,,0.,0.,0.\nGRID,2,,2.,0.,0.\nGRID,3,,2.,3.,0.\nGRID,4,,0.,3.,0.\nGRID,5,,1.,2.,3.\n"
      "PBAR,1,1,.5,1.,1.,1.,.25\nCBAR,1,1,1,2,0.,0.,1.\n"         // (2 x .5 + .25) x 2 = 2.5
      "PSHELL,2,1,.1,,,,,.3\nCQUAD4,2,2,1,2,3,4\n"               // (2 x .1 + .3) x 6 = 3
      "CONM2,3,5,,4.,.1,.2,.3\n,1.,.1,2.,.2,.3,3.\n";            // at (1.1, 2.2, 3.3)
  const fem::Model m = test::read_deck(deck);
  const PointMasses pm = lumped(m);
  EXPECT_NEAR(pm.mass, 2.5 + 3. + 4., 1e-14);
  expect_matches(fem::mass_properties(m), pm, Eigen::Vector3d::Zero());
}

TEST(NastranMassProperties, InfoPrintsTheGpwgSummary) {
  const auto p = test::validation_dir() / "mystran_cbar_cantilever_and_freefree_modes/BAR-CC-GIV.DAT";
  const auto r = test::run_seflex("info '" + p.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream in(r.out.substr(r.out.find("mass properties")));
  std::string line;
  double mass = 0, x = 0, y = 0, z = 0, wtmass = 0;
  while (std::getline(in, line)) {
    std::sscanf(line.c_str(), "  total mass %lf", &mass);
    std::sscanf(line.c_str(), "  centre of gravity %lf %lf %lf", &x, &y, &z);
    std::sscanf(line.c_str(), "  PARAM WTMASS %lf", &wtmass);
  }
  EXPECT_DOUBLE_EQ(mass, 1.0);
  EXPECT_DOUBLE_EQ(x, 50.0);
  EXPECT_DOUBLE_EQ(wtmass, 0.002591);
  // --grdpnt moves the reference point; a grid that does not exist is a usage error
  const auto g = test::run_seflex("info '" + p.string() + "' --grdpnt 5");
  EXPECT_EQ(g.exit_code, 0) << g.err;
  EXPECT_NE(g.out.find("reference point           grid 5 at (100, 0, 0)"), std::string::npos) << g.out;
  EXPECT_EQ(test::run_seflex("info '" + p.string() + "' --grdpnt 77").exit_code, 2);
}

TEST(NastranMassProperties, Conm2InOtherSystems) {
  // QRG CONM2: CID -1 -> X is the CG position in basic; CID > 0 -> X is the offset from the grid and
  // the inertia matrix [I11 -I21 -I31; -I21 I22 -I32; -I31 -I32 I33] is given in that system's axes.
  // CORD2R 9: z along basic x, x along basic z, so R = [e1 e2 e3] = [[0,0,1],[0,-1,0],[1,0,0]].
  const std::string deck =
      "GRID,1,,1.,2.,3.\n"
      "CORD2R,9,,5.,5.,5.,6.,5.,5.\n,5.,5.,6.\n"
      "CONM2,1,1,9,2.,.1,.2,.3\n,1.,.1,2.,.2,.3,3.\n"
      "CONM2,2,1,-1,3.,10.,20.,30.\n,4.,,5.,,,6.\n";
  const fem::Model m = test::read_deck(deck);
  Eigen::Matrix3d R;
  R << 0, 0, 1, 0, -1, 0, 1, 0, 0;
  Eigen::Matrix3d T;
  T << 1, -.1, -.2, -.1, 2, -.3, -.2, -.3, 3;
  PointMasses pm;
  pm.add(2., Eigen::Vector3d(1, 2, 3) + R * Eigen::Vector3d(.1, .2, .3));  // (1.3, 1.8, 3.1)
  pm.add(3., Eigen::Vector3d(10, 20, 30));
  pm.extra_inertia = R * T * R.transpose() + Eigen::Vector3d(4, 5, 6).asDiagonal().toDenseMatrix();
  EXPECT_LT((pm.points[0].second - Eigen::Vector3d(1.3, 1.8, 3.1)).norm(), 1e-15);
  expect_matches(fem::mass_properties(m), pm, Eigen::Vector3d::Zero());
}
