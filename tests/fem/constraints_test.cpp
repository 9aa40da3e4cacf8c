// SPC and RBE2 elimination: exactness against independent constructions.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cmath>

#include "fem_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/loads.hpp"

namespace seflex::fem {
namespace {

// Cantilever of n bars along x from grid 1 (clamped by SPC set 1), tip grid n + 1.
Model cantilever(int n, double L) {
  Model m;
  for (int i = 0; i <= n; ++i) test::add_grid(m, i + 1, L * i / n, 0, 0);
  test::add_mat1(m, 1, 2e11, 0.3, 7800);
  test::add_pbar(m, 2, 1, 1e-3, 2e-7, 3e-7, 4e-7, 0.1);
  for (int i = 0; i < n; ++i) test::add_cbar(m, 10 + i, 2, i + 1, i + 2, {0, 1, 0});
  test::add_spc1(m, 1, test::mask("123456"), 1);
  return m;
}

std::vector<double> eigenvalues(const Model& m, int spc) {
  const GlobalMatrices g = assemble(m, AssemblyOptions{});
  const ConstrainedSystem c = apply_constraints(m, g, spc);
  return test::dense_eigenvalues(test::dense(c.K_ff), test::dense(c.M_ff));
}

// A CONM2 hung on an RBE2 at point P is the same mass as a CONM2 at the tip grid with offset P - tip:
// two independent code paths (constraint elimination vs. the CONM2 offset transformation).
TEST(Constraints, Rbe2CarriesMassExactly) {
  const Eigen::Vector3d P(2.3, 0.2, -0.4);
  Conm2 c;
  c.id = 90;
  c.m = 3.0;
  c.I11 = 0.02;
  c.I22 = 0.03;
  c.I33 = 0.04;
  c.I21 = 0.004;

  Model a = cantilever(4, 2.0);
  test::add_grid(a, 100, P.x(), P.y(), P.z());
  test::add_rbe2(a, 200, 5, "123456", {100});
  c.grid = 100;
  a.conm2.push_back(c);
  test::finalize_for_test(a);

  Model b = cantilever(4, 2.0);
  c.grid = 5;
  c.x = P - Eigen::Vector3d(2.0, 0, 0);
  b.conm2.push_back(c);
  test::finalize_for_test(b);

  const auto la = eigenvalues(a, 1), lb = eigenvalues(b, 1);
  ASSERT_EQ(la.size(), lb.size());
  for (std::size_t i = 0; i < la.size(); ++i) EXPECT_NEAR(la[i] / lb[i], 1.0, 1e-10) << "mode " << i;
}

// RBE2 dependent grid follows the rigid motion of its independent grid, also through a chain and
// with a dependent grid in a rotated displacement system.
TEST(Constraints, Rbe2ChainIsRigid) {
  Model m = cantilever(2, 1.0);
  test::add_grid(m, 50, 1.2, 0.3, 0.1);
  test::add_grid(m, 60, 1.5, -0.2, 0.4, 7);
  const Eigen::Matrix3d R7 = so3::exp(Eigen::Vector3d(0.2, 0.7, -0.3));
  test::add_rect_coord(m, 7, {0.5, 0.5, 0.5}, R7);
  Rbe2 r1, r2;
  r1.id = 1;
  r1.gn = 3;
  r1.cm = test::mask("123456");
  r1.gm = {50};
  r2.id = 2;
  r2.gn = 50;
  r2.cm = test::mask("123456");
  r2.gm = {60};
  m.rbe2 = {r2, r1};  // order does not matter
  PointLoad f;
  f.sid = 5;
  f.grid = 60;
  f.scale = 100.0;
  f.n = {0.3, 1, -0.5};
  m.point_loads.push_back(f);
  test::finalize_for_test(m);
  const GlobalMatrices g = assemble(m, AssemblyOptions{});
  const ConstrainedSystem c = apply_constraints(m, g, 1);
  const Eigen::VectorXd pf = reduce_load(c, g, load_vector(m, g.dofs, 5));
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(c.K_ff);
  const Eigen::VectorXd u = expand(c, ldlt.solve(pf));
  const Eigen::Vector3d u3 = u.segment<3>(12), th3 = u.segment<3>(15);
  const Eigen::Vector3d u60 = R7 * u.segment<3>(24), th60 = R7 * u.segment<3>(27);
  const Eigen::Vector3d d = Eigen::Vector3d(1.5, -0.2, 0.4) - Eigen::Vector3d(1.0, 0, 0);
  EXPECT_LE((u60 - (u3 + th3.cross(d))).norm(), 1e-12 * u3.norm());
  EXPECT_LE((th60 - th3).norm(), 1e-12 * th3.norm());
  // the load reached the structure: tip deflection nonzero and equilibrium of work
  EXPECT_GT(u3.norm(), 0.0);
  const Eigen::VectorXd p = load_vector(m, g.dofs, 5);
  EXPECT_NEAR(p.dot(u), pf.dot(ldlt.solve(pf)), 1e-12 * std::abs(p.dot(u)));
}

// RBE2 with CM = 123 (translations only): the dependent grid's translations follow the rigid motion
// of the independent grid, u_m = u_n + theta_n x d, and its rotations stay its own (here nothing
// else reaches them, so AUTOSPC removes them). A force F at the dependent grid therefore reaches
// the tip as F and the moment d x F: the same displacements as a cantilever loaded so at the tip,
// and the tip deflection in plane 1 is the Euler-Bernoulli closed form
// v = F_y L^3 / (3 E I1) + M_z L^2 / (2 E I1) (exact with cubic elements).
TEST(Constraints, Rbe2TranslationalComponentsOnly) {
  const double L = 2.0, EI1 = 2e11 * 2e-7;
  const Eigen::Vector3d P(2.3, 0.2, -0.4), d = P - Eigen::Vector3d(L, 0, 0), F(10.0, 40.0, -25.0);
  Model a = cantilever(4, L);
  test::add_grid(a, 100, P.x(), P.y(), P.z());
  test::add_rbe2(a, 200, 5, "123", {100});
  PointLoad f;
  f.sid = 5;
  f.grid = 100;
  f.scale = 1.0;
  f.n = F;
  a.point_loads.push_back(f);
  test::finalize_for_test(a);

  Model b = cantilever(4, L);
  f.grid = 5;
  PointLoad mo = f;
  mo.kind = PointLoad::Kind::Moment;
  mo.n = d.cross(F);
  b.point_loads = {f, mo};
  test::finalize_for_test(b);

  const auto solve = [](const Model& m, ConstrainedSystem& c) {
    const GlobalMatrices g = assemble(m, AssemblyOptions{});
    c = apply_constraints(m, g, 1);
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(c.K_ff);
    EXPECT_EQ(ldlt.info(), Eigen::Success);
    return Eigen::VectorXd(expand(c, ldlt.solve(reduce_load(c, g, load_vector(m, g.dofs, 5)))));
  };
  ConstrainedSystem ca, cb;
  const Eigen::VectorXd ua = solve(a, ca), ub = solve(b, cb);
  ASSERT_EQ(ua.size(), 36);
  ASSERT_EQ(ub.size(), 30);
  EXPECT_LE((ua.head(30) - ub).norm(), 1e-12 * ub.norm());
  const Eigen::Vector3d u5 = ua.segment<3>(24), th5 = ua.segment<3>(27);
  EXPECT_LE((ua.segment<3>(30) - (u5 + th5.cross(d))).norm(), 1e-12 * u5.norm());
  for (int k = 0; k < 3; ++k) EXPECT_EQ(ca.status[30 + k], DofStatus::Dependent) << "component " << k + 1;
  for (int k = 3; k < 6; ++k) EXPECT_EQ(ca.status[30 + k], DofStatus::AutoSpc) << "component " << k + 1;
  const double v = F.y() * L * L * L / (3 * EI1) + d.cross(F).z() * L * L / (2 * EI1);
  EXPECT_NEAR(u5.y(), v, 1e-10 * std::abs(v));
}

// Enforced displacement (SPC with D): a cantilever whose tip deflection is prescribed as delta
// needs the tip force 3 EI delta / L^3 (Euler-Bernoulli, exact with cubic elements).
TEST(Constraints, EnforcedDisplacement) {
  const double L = 2.0, delta = 0.01;
  Model m = cantilever(4, L);
  SpcEntry e;
  e.sid = 1;
  e.grid = 5;
  e.c = test::mask("2");
  e.d = delta;
  m.spcs.push_back(e);
  test::finalize_for_test(m);
  const GlobalMatrices g = assemble(m, AssemblyOptions{});
  const ConstrainedSystem c = apply_constraints(m, g, 1);
  EXPECT_EQ(c.u_g0[4 * 6 + 1], delta);
  const Eigen::VectorXd pf = reduce_load(c, g, Eigen::VectorXd::Zero(g.dofs.size()));
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(c.K_ff);
  const Eigen::VectorXd u = expand(c, ldlt.solve(pf));
  const Eigen::VectorXd reaction = g.K * u;
  const double EI = 2e11 * 2e-7;  // plane 1 (x-y) uses I1
  EXPECT_NEAR(reaction[4 * 6 + 1], 3 * EI * delta / (L * L * L), 1e-9 * 3 * EI * delta / (L * L * L));
  EXPECT_NEAR(u[4 * 6 + 1], delta, 0.0);
}

// AUTOSPC removes the rotations of a grid that only rods reach, and nothing else;
// GRID PS and extra fixed dofs are honoured; the f-set is numbered in g order.
TEST(Constraints, SetsAndAutospc) {
  Model m = cantilever(2, 1.0);
  test::add_grid(m, 9, 1.0, 1.0, 0.0, 0, test::mask("3"));
  test::add_conrod(m, 70, 3, 9, 1, 1e-4);
  test::add_conrod(m, 71, 2, 9, 1, 1e-4);
  test::finalize_for_test(m);
  const GlobalMatrices g = assemble(m, AssemblyOptions{});
  const ConstrainedSystem c = apply_constraints(m, g, 1, {6 + 2});  // hold grid 2 T3
  const Eigen::Index g9 = 3 * 6;
  EXPECT_EQ(c.status[g9 + 2], DofStatus::Spc);
  for (int k = 3; k < 6; ++k) EXPECT_EQ(c.status[g9 + k], DofStatus::AutoSpc);
  EXPECT_EQ(c.status[g9 + 0], DofStatus::Free);
  EXPECT_EQ(c.status[g9 + 1], DofStatus::Free);
  EXPECT_EQ(c.status[8], DofStatus::Fixed);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(c.status[k], DofStatus::Spc);
  int n_free = 0;
  for (Eigen::Index d = 0; d < g.dofs.size(); ++d) n_free += c.status[d] == DofStatus::Free;
  EXPECT_EQ(c.n_free(), n_free);
  EXPECT_EQ(n_free, 6 + 5 + 2);
  for (Eigen::Index j = 1; j < c.n_free(); ++j) EXPECT_LT(c.f_to_g[j - 1], c.f_to_g[j]);
  // K_ff is the principal submatrix of K on the free dofs
  for (Eigen::Index i = 0; i < c.n_free(); ++i)
    for (Eigen::Index j = 0; j < c.n_free(); ++j)
      EXPECT_EQ(c.K_ff.coeff(i, j), g.K.coeff(c.f_to_g[i], c.f_to_g[j]));
}

}  // namespace
}  // namespace seflex::fem
