// Linear statics against beam theory and equilibrium; bad case control and unsupported models.
#include "seflex/solutions/statics.hpp"

#include <gtest/gtest.h>

#include "fem_models.hpp"
#include "seflex/solutions/grid_results.hpp"

namespace seflex::solutions {
namespace {

constexpr double kE = 7.0e10, kI = 2.0e-8, kL = 1.5, kP = 120.0;

/// Cantilever along x of 10 CBARs (A = 1e-4, I1 = I2 = 2e-8, J = 4e-8), clamped at grid 1
/// (SPC1 1 123456), tip FORCE 7 of kP along basic z; `tip_cd` gives the tip grid a displacement
/// system rotated 90 degrees about z.
fem::Model cantilever(int tip_cd = 0) {
  fem::Model m;
  m.files = {"cantilever.bdf"};
  const int n = 10;
  for (int i = 0; i <= n; ++i) test::add_grid(m, i + 1, kL * i / n, 0, 0);
  m.grids.back().cd = tip_cd;
  if (tip_cd != 0) {
    fem::CoordSys cs;
    cs.id = tip_cd;
    cs.abc = {0, 0, 0, 0, 0, 1, 0, 1, 0};  // CORD2R: A origin, B on z, C in the x-z plane
    cs.resolved = true;
    cs.axes << 0, -1, 0, 1, 0, 0, 0, 0, 1;  // e1 = basic y, e2 = -basic x, e3 = basic z
    m.coords.push_back(cs);
  }
  test::add_mat1(m, 1, kE, 0.3, 2700);
  test::add_pbar(m, 1, 1, 1e-4, kI, kI, 2 * kI);
  for (int i = 0; i < n; ++i) test::add_cbar(m, i + 1, 1, i + 1, i + 2, {0, 1, 0});
  test::add_spc1(m, 1, test::mask("123456"), 1);
  fem::PointLoad f;
  f.sid = 7;
  f.grid = n + 1;
  f.scale = kP;
  f.n = Eigen::Vector3d(0, 0, 1);
  m.point_loads.push_back(f);
  m.case_control.global.spc = 1;
  m.case_control.global.load = 7;
  test::finalize_for_test(m);
  return m;
}

// Euler-Bernoulli cantilever under a tip load (Timoshenko & Gere, Mechanics of Materials, table
// G-1): w(L) = P L^3 / (3 E I), dw/dx(L) = P L^2 / (2 E I); cubic beam elements are exact at the
// nodes. Nastran's R2 is the rotation about +y, i.e. -dw/dx.
TEST(Statics, CantileverTipLoadMatchesBeamTheory) {
  const fem::Model m = cantilever();
  const StaticSolution s = solve_static(m);
  const GridTable u = grid_vectors_basic(m, s.dofs, s.u_g);
  const double w = kP * kL * kL * kL / (3 * kE * kI), slope = kP * kL * kL / (2 * kE * kI);
  EXPECT_NEAR(u(10, 2) / w, 1.0, 1e-10);
  EXPECT_NEAR(u(10, 4) / -slope, 1.0, 1e-10);
  EXPECT_NEAR(u(5, 2) / (kP * std::pow(kL / 2, 2) * (3 * kL - kL / 2) / (6 * kE * kI)), 1.0, 1e-10);  // w(x) = P x^2 (3L - x) / 6EI
  EXPECT_LT(std::abs(u(10, 0)) + std::abs(u(10, 1)), 1e-12 * w);
  EXPECT_LT(s.backward_error, 1e-14);  // Cholesky is backward stable
  EXPECT_EQ(s.selection.load, 7);
}

// Equilibrium: the SPC forces balance the applied load (force and moment about the origin).
TEST(Statics, ReactionsBalanceTheAppliedLoad) {
  const fem::Model m = cantilever();
  const StaticSolution s = solve_static(m);
  const auto applied = resultant_basic(m, s.dofs, s.p_g), reaction = resultant_basic(m, s.dofs, s.q_g);
  EXPECT_NEAR(applied(2), kP, 1e-12 * kP);
  EXPECT_NEAR(applied(4), -kP * kL, 1e-12 * kP * kL);  // (L, 0, 0) x (0, 0, P) = (0, -P L, 0)
  EXPECT_LT((applied + reaction).norm(), 1e-9 * kP * kL);
  // the reaction sits on grid 1 only
  const GridTable q = grid_vectors_basic(m, s.dofs, s.q_g);
  EXPECT_NEAR(q(0, 2), -kP, 1e-9 * kP);
  EXPECT_NEAR(q(0, 4), kP * kL, 1e-9 * kP * kL);
  EXPECT_EQ(q.bottomRows(10).norm(), 0.0);
}

// The tip's displacement system is rotated: the g-set holds CD components, the basic results do not change.
TEST(Statics, ResultsInBasicDoNotDependOnTheDisplacementSystem) {
  const fem::Model plain = cantilever(), rotated = cantilever(5);
  const StaticSolution a = solve_static(plain), b = solve_static(rotated);
  const GridTable ua = grid_vectors_basic(plain, a.dofs, a.u_g), ub = grid_vectors_basic(rotated, b.dofs, b.u_g);
  EXPECT_LT((ua - ub).norm(), 1e-12 * ua.norm());
  // in CD the tip's w stays T3 and the rotation about basic y becomes -R1 (e2 = -x, e1 = y)
  EXPECT_NEAR(b.u_g(b.dofs.grid_dof(10, 4)), ua(10, 4), 1e-12 * std::abs(ua(10, 4)));
}

// Without LOAD, as in Nastran, a subcase is driven by its enforced displacements: SPC D = d on the
// tip's w gives the tip-loaded cantilever's cubic, w(x) = d x^2 (3L - x) / (2 L^3), exact at the nodes
// of cubic beam elements (Timoshenko & Gere, table G-1, with P = 3 E I d / L^3).
TEST(Statics, CaseControlWithoutLoadIsDrivenByEnforcedDisplacements) {
  fem::Model m = cantilever();
  m.case_control.global.load.reset();
  const StaticSolution zero = solve_static(m);
  EXPECT_EQ(zero.u_g.norm(), 0.0);
  const double d = 0.01, L = 1.5;
  fem::SpcEntry e;
  e.sid = *m.case_control.global.spc;
  e.grid = m.grids.back().id;
  e.c = 1u << 2;  // T3
  e.d = d;
  m.spcs.push_back(e);
  const StaticSolution s = solve_static(m);
  const GridTable u = grid_vectors_basic(m, s.dofs, s.u_g);
  for (std::size_t i = 0; i < m.grids.size(); ++i) {
    const double x = m.grids[i].x_basic.x();
    EXPECT_NEAR(u(static_cast<Eigen::Index>(i), 2), d * x * x * (3 * L - x) / (2 * L * L * L), 1e-12) << "grid " << m.grids[i].id;
  }
}

TEST(Statics, UnsupportedModelNamesAGrid) {
  fem::Model m = cantilever();
  m.case_control.global.spc.reset();  // nothing holds the beam
  try {
    solve_static(m);
    FAIL() << "no error for a free-floating model";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("singular at grid"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("SPC"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace seflex::solutions
