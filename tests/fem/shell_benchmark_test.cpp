// MacNeal-Harder standard shell problems (MacNeal & Harder, "A proposed standard set of problems to
// test finite element accuracy", Finite Elements in Analysis and Design 1 (1985) 3-20): each within
// 2 % of the published reference at a moderate mesh, and converging under refinement.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cmath>

#include "shell_mesh.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/loads.hpp"

namespace seflex::fem {
namespace {

const double kPi = 3.14159265358979323846;

// Static solution u_g for SPC set 1 and load set `load` (or the given g-set load vector).
Eigen::VectorXd solve_static(const Model& m, int load, const Eigen::VectorXd* p_given = nullptr) {
  const GlobalMatrices g = assemble(m, assembly_options(m));
  const ConstrainedSystem c = apply_constraints(m, g, 1);
  const Eigen::VectorXd p = p_given ? *p_given : load_vector(m, g.dofs, load);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(c.K_ff);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  return expand(c, ldlt.solve(reduce_load(c, g, p)));
}

double dof(const Model& m, const Eigen::VectorXd& u, int grid, int component) {
  return u[6 * m.grid_index.at(grid) + component - 1];
}

// ---------------------------------------------------------------------------------------------
// Straight cantilever: L = 6, width 0.2, thickness 0.1, E = 1e7, nu = 0.3, clamped at x = 0, unit
// tip load split between the two tip nodes. References (MH table 2): extension 3.0e-5, in-plane
// shear 0.1081, out-of-plane shear 0.4321 (tip displacement in the load direction).
struct CantileverCase {
  Eigen::Vector3d load;
  int component;
  double reference;
};

double straight_cantilever(int nx, int ny, double skew, const CantileverCase& cs) {
  Model m;
  test::add_mat1(m, 1, 1e7, 0.3, 0);
  test::add_pshell(m, 1, 1, 0.1);
  // skew: x-offset of interior node lines between y = 0 and y = 0.2 (MH parallelogram mesh: 45 deg)
  const auto mesh = test::add_shell_mesh(m, nx, ny, [&](double s, double r) {
    const bool interior = s > 0 && s < 1;
    return Eigen::Vector3d(6.0 * s + (interior ? skew * (r - 0.5) : 0.0), 0.2 * r, 0.0);
  });
  for (int j = 0; j <= ny; ++j) {
    test::add_spc(m, 1, mesh.id(0, j), "123456");
    test::add_force(m, 2, mesh.id(nx, j), cs.load / (ny + 1));
  }
  test::finalize_for_test(m);
  const Eigen::VectorXd u = solve_static(m, 2);
  double tip = 0;
  for (int j = 0; j <= ny; ++j) tip += dof(m, u, mesh.id(nx, j), cs.component) / (ny + 1);
  return tip;
}

TEST(MacNealHarder, StraightCantilever) {
  const CantileverCase cases[3] = {{{1, 0, 0}, 1, 3.0e-5}, {{0, 1, 0}, 2, 0.1081}, {{0, 0, 1}, 3, 0.4321}};
  for (const auto& cs : cases) {
    // the MH mesh: 6 x 1 rectangles of aspect ratio 5; then refined
    const double r1 = straight_cantilever(6, 1, 0.0, cs) / cs.reference;
    const double r2 = straight_cantilever(12, 2, 0.0, cs) / cs.reference;
    const double r4 = straight_cantilever(24, 4, 0.0, cs) / cs.reference;
    std::printf("straight cantilever, load %d: 6x1 %.4f 12x2 %.4f 24x4 %.4f\n", cs.component, r1, r2, r4);
    for (double r : {r1, r2, r4}) EXPECT_NEAR(r, 1.0, 0.02) << "load component " << cs.component;
    EXPECT_LE(std::abs(r4 - 1.0), std::abs(r1 - 1.0) + 1e-4) << "load component " << cs.component;
    // MH's 45-degree parallelogram mesh: fine for extension and out-of-plane bending. (In-plane
    // bending of 45-degree parallelograms of aspect ratio 5 is a known weakness of 4-node membranes,
    // QM6 included: about 0.63 here; MacNeal & Harder report similar values for most elements.)
    if (cs.component != 2) {
      const double para = straight_cantilever(6, 1, 0.2, cs) / cs.reference;
      EXPECT_NEAR(para, 1.0, 0.025) << "load component " << cs.component;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Twisted beam: L = 12, width 1.1, thickness 0.32, twisted 90 deg from root to tip, E = 29e6,
// nu = 0.22; unit tip load. References (MH table 5): load along the root's width direction
// (basic Y) 1.754e-3, along Z 5.424e-3.
double twisted_beam(int nx, int ny, int load_axis) {
  Model m;
  test::add_mat1(m, 1, 29e6, 0.22, 0);
  test::add_pshell(m, 1, 1, 0.32);
  const auto mesh = test::add_shell_mesh(m, nx, ny, [](double s, double r) {
    const double a = 0.5 * kPi * s, y = 1.1 * (r - 0.5);
    return Eigen::Vector3d(12.0 * s, y * std::cos(a), y * std::sin(a));
  });
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  f[load_axis - 1] = 1.0 / (ny + 1);
  for (int j = 0; j <= ny; ++j) {
    test::add_spc(m, 1, mesh.id(0, j), "123456");
    test::add_force(m, 2, mesh.id(nx, j), f);
  }
  test::finalize_for_test(m);
  const Eigen::VectorXd u = solve_static(m, 2);
  double tip = 0;
  for (int j = 0; j <= ny; ++j) tip += dof(m, u, mesh.id(nx, j), load_axis) / (ny + 1);
  return tip;
}

TEST(MacNealHarder, TwistedBeam) {
  for (const auto& [axis, ref] : {std::pair{2, 1.754e-3}, std::pair{3, 5.424e-3}}) {
    const double r1 = twisted_beam(12, 2, axis) / ref;  // the MH mesh
    const double r2 = twisted_beam(24, 4, axis) / ref;
    const double r3 = twisted_beam(48, 8, axis) / ref;
    std::printf("twisted beam, load along %d: 12x2 %.4f 24x4 %.4f 48x8 %.4f\n", axis, r1, r2, r3);
    // measured (2026-11-28), worse of the two axes: 2.8e-3, 1.7e-3, 1.4e-3 (the references' 4 digits
    // are good to 3e-4); tolerances about twice those
    EXPECT_NEAR(r1, 1.0, 0.005) << "axis " << axis;
    EXPECT_NEAR(r2, 1.0, 0.0035) << "axis " << axis;
    EXPECT_NEAR(r3, 1.0, 0.003) << "axis " << axis;
    EXPECT_LE(std::abs(r3 - r2), std::abs(r2 - r1) + 1e-4);
  }
}

// ---------------------------------------------------------------------------------------------
// Scordelis-Lo roof: cylinder R = 25, length 50, 80 deg arc, t = 0.25, E = 4.32e8, nu = 0, weight
// 90 per unit area, ends on rigid diaphragms (u_y = u_z = 0). Reference (MH table 6): vertical
// displacement at the midside of the free edge 0.3024. One quarter is modelled (symmetry at the
// mid-length x = 25 and the crown y = 0).
double scordelis_lo(int n, bool triangles) {
  Model m;
  test::add_mat1(m, 1, 4.32e8, 0.0, 0);
  ShellProperty& p = test::add_pshell(m, 1, 1, 0.25);
  p.nsm = 90.0;  // the roof's weight per area as a mass, so that the load is M g (consistent lumping)
  const double R = 25, phi0 = 40.0 * kPi / 180;
  const auto mesh = test::add_shell_mesh(
      m, n, n,
      [&](double s, double r) {
        const double phi = phi0 * r;  // from the crown (y = 0) to the free edge
        return Eigen::Vector3d(25.0 * s, R * std::sin(phi), R * std::cos(phi));
      },
      triangles);
  for (int j = 0; j <= n; ++j) {
    test::add_spc(m, 1, mesh.id(0, j), "23");     // diaphragm at x = 0
    test::add_spc(m, 1, mesh.id(n, j), "156");    // symmetry x = 25: u_x, theta_y, theta_z
  }
  for (int i = 0; i <= n; ++i) test::add_spc(m, 1, mesh.id(i, 0), "246");  // symmetry y = 0
  test::finalize_for_test(m);
  const GlobalMatrices g = assemble(m, assembly_options(m));
  Eigen::VectorXd a = Eigen::VectorXd::Zero(g.dofs.size());
  for (Eigen::Index k = 0; k < g.dofs.n_grids; ++k) a[6 * k + 2] = -1.0;  // unit gravity along -z
  const Eigen::VectorXd pg = g.M * a;
  const Eigen::VectorXd u = solve_static(m, 0, &pg);
  return -dof(m, u, mesh.id(n, n), 3);
}

TEST(MacNealHarder, ScordelisLoRoof) {
  const double ref = 0.3024;
  const double q8 = scordelis_lo(8, false) / ref, q16 = scordelis_lo(16, false) / ref,
               q32 = scordelis_lo(32, false) / ref;
  std::printf("Scordelis-Lo CQUAD4: 8x8 %.4f 16x16 %.4f 32x32 %.4f\n", q8, q16, q32);
  // measured (2026-11-28): 1.4e-3 and 1.8e-3 (the reference's 4 digits are good to 1.7e-4); twice those
  EXPECT_NEAR(q16, 1.0, 0.003);
  EXPECT_NEAR(q32, 1.0, 0.0035);
  EXPECT_LE(std::abs(q32 - q16), std::abs(q16 - q8));
  const double t16 = scordelis_lo(16, true) / ref, t32 = scordelis_lo(32, true) / ref;
  std::printf("Scordelis-Lo CTRIA3: 16x16x2 %.4f 32x32x2 %.4f\n", t16, t32);
  EXPECT_NEAR(t32, 1.0, 0.025);  // measured 1.3e-2 (2026-11-28)
  EXPECT_LT(std::abs(t32 - 1.0), std::abs(t16 - 1.0));
}

// ---------------------------------------------------------------------------------------------
// Pinched hemisphere with an 18 deg hole: R = 10, t = 0.04, E = 6.825e7, nu = 0.3, radial loads of
// 2 alternating in and out at 90 deg on the equator. Reference (MH table 7): 0.094 radial
// displacement at the load points (the converged thin-shell value is 0.0924, Simo, Fox & Rifai,
// CMAME 79 (1990) 21-70). One quarter is modelled, with the loads halved on the symmetry planes.
double hemisphere(int n) {
  Model m;
  test::add_mat1(m, 1, 6.825e7, 0.3, 0);
  test::add_pshell(m, 1, 1, 0.04);
  const double R = 10, th0 = 18.0 * kPi / 180;
  const auto mesh = test::add_shell_mesh(m, n, n, [&](double s, double r) {
    const double az = 0.5 * kPi * s;                      // azimuth from the x axis
    const double th = 0.5 * kPi - (0.5 * kPi - th0) * r;  // polar angle: equator (r = 0) to the hole
    return Eigen::Vector3d(R * std::sin(th) * std::cos(az), R * std::sin(th) * std::sin(az), R * std::cos(th));
  });
  for (int j = 0; j <= n; ++j) {
    test::add_spc(m, 1, mesh.id(0, j), "246");  // plane y = 0
    test::add_spc(m, 1, mesh.id(n, j), "156");  // plane x = 0
  }
  test::add_spc(m, 1, mesh.id(0, 0), "3");  // rigid motion along z
  test::add_force(m, 2, mesh.id(0, 0), {1, 0, 0});
  test::add_force(m, 2, mesh.id(n, 0), {0, -1, 0});
  test::finalize_for_test(m);
  const Eigen::VectorXd u = solve_static(m, 2);
  return dof(m, u, mesh.id(0, 0), 1);
}

TEST(MacNealHarder, PinchedHemisphere) {
  const double ref = 0.094;
  const double h16 = hemisphere(16) / ref, h32 = hemisphere(32) / ref, h64 = hemisphere(64) / ref;
  std::printf("pinched hemisphere: 16x16 %.4f 32x32 %.4f 64x64 %.4f\n", h16, h32, h64);
  // measured (2026-11-28): 0.8e-3, 2.2e-3, 3.1e-3. The tolerance is the reference's own uncertainty, not
  // the element's error: MH's 0.094 has two digits (+-0.5 %) and the converged thin-shell value 0.0924
  // lies 1.7 % below it.
  for (double h : {h16, h32, h64}) EXPECT_NEAR(h, 1.0, 0.02);
  EXPECT_LT(std::abs(h64 - h32), 0.75 * std::abs(h32 - h16));  // differences shrink (about halve)
}

}  // namespace
}  // namespace seflex::fem
