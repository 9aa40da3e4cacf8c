// RBE3, RBAR and MPC elimination and AUTOSPC's singular directions, against independent closed forms
// and equivalent models built another way.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cmath>

#include "fem_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/loads.hpp"

namespace seflex::fem {
namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;

/// Four independent grids on grounded springs (all six components, so that every independent dof is
/// free), the reference grid 100 at `ref`; RBE3 7 with weights w_i on components `ci`.
Model rbe3_model(const Eigen::Vector3d& ref, const std::array<Eigen::Vector3d, 4>& x, const std::array<double, 4>& w,
                 ComponentMask ci) {
  Model m;
  for (int i = 0; i < 4; ++i) {
    test::add_grid(m, i + 1, x[i].x(), x[i].y(), x[i].z());
    for (int c = 1; c <= 6; ++c) test::add_celas2(m, 10 * (i + 1) + c, i + 1, c, 1e3 * (1 + c + i));
  }
  test::add_grid(m, 100, ref.x(), ref.y(), ref.z());
  Rbe3 r;
  r.id = 7;
  r.refgrid = 100;
  r.refc = test::mask("123456");
  for (int i = 0; i < 4; ++i) {
    Rbe3::Group g;
    g.weight = w[i];
    g.c = ci;
    g.grids = {i + 1};
    r.groups.push_back(g);
  }
  m.rbe3.push_back(r);
  test::finalize_for_test(m);
  return m;
}

/// The nodal loads a load p_ref (force, moment; basic) at the reference grid reaches the independent
/// grids with: T^T p (the f-set load of the elimination), per independent grid.
std::array<Vector6, 4> distributed(const Model& m, const Vector6& p_ref) {
  const GlobalMatrices g = assemble(m, AssemblyOptions{});
  const ConstrainedSystem c = apply_constraints(m, g, std::nullopt);
  Eigen::VectorXd p = Eigen::VectorXd::Zero(g.dofs.size());
  p.segment<6>(6 * 4) = p_ref;  // grid 100 is the fifth grid
  const Eigen::VectorXd pf = reduce_load(c, g, p);
  std::array<Vector6, 4> out;
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 6; ++k) {
      const Eigen::Index f = c.g_to_f[static_cast<std::size_t>(6 * i + k)];
      out[static_cast<std::size_t>(i)](k) = f >= 0 ? pf(f) : 0.0;
    }
  return out;
}

// RBE3 load distribution, closed form (MSC Nastran Reference Manual, "RBE3"; the "wiffletree" of the
// MSC Nastran linear-static seminar NAS105 section 2): the reference load (F, M) is moved to the
// weighted centroid c of the independent grids, M_c = M + (x_ref - c) x F, and spread as
//   f_i = w_i (F / sum w + alpha x r_i),  alpha = J^-1 M_c,  J = sum w_i (|r_i|^2 I - r_i r_i^T),
// r_i = x_i - c: forces proportional to the weights plus the couples that balance M_c (translational
// components 123 only). Unequal weights, a rectangle and an off-centre reference point.
TEST(Rbe3, LoadDistributionMatchesTheClosedForm) {
  const std::array<Eigen::Vector3d, 4> x = {Eigen::Vector3d(2, 1, 0), Eigen::Vector3d(-2, 1, 0),
                                            Eigen::Vector3d(-2, -1, 0.5), Eigen::Vector3d(2, -1, 0)};
  const std::array<double, 4> w = {1.0, 2.0, 0.5, 1.5};
  const Eigen::Vector3d ref(0.3, -0.2, 5.0);
  const Model m = rbe3_model(ref, x, w, test::mask("123"));
  Vector6 p;
  p << 100.0, -250.0, 40.0, 30.0, -70.0, 120.0;
  const auto f = distributed(m, p);

  double W = 0;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int i = 0; i < 4; ++i) {
    W += w[i];
    c += w[i] * x[i];
  }
  c /= W;
  const Eigen::Vector3d F = p.head<3>(), Mc = p.tail<3>() + (ref - c).cross(F);
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d r = x[i] - c;
    J += w[i] * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  const Eigen::Vector3d alpha = J.inverse() * Mc;
  Eigen::Vector3d sum_f = Eigen::Vector3d::Zero(), sum_m = Eigen::Vector3d::Zero();
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d expected = w[i] * (F / W + alpha.cross(x[i] - c));
    EXPECT_LT((f[i].head<3>() - expected).norm(), 1e-10 * F.norm()) << "grid " << i + 1 << ": " << f[i].transpose();
    EXPECT_EQ(f[i].tail<3>().norm(), 0.0) << "no moments at independent grids with Ci = 123";
    sum_f += f[i].head<3>();
    sum_m += (x[i] - ref).cross(f[i].head<3>());
  }
  // statics: the distributed loads are equivalent to the reference load
  EXPECT_LT((sum_f - F).norm(), 1e-10 * F.norm());
  EXPECT_LT((sum_m - p.tail<3>()).norm(), 1e-10 * p.tail<3>().norm());
}

// MYSTRAN's RBE3-01-CBAR-08 (MYSTRANsolver/MYSTRAN_Benchmark, 12.0 test runs; answers in
// Static/Sparse/Archive/RBE3-01-CBAR-08.arc, "M P C   F O R C E S"): a 1e5 force along y at the
// reference point (0, 0, 10) over four grids (+-2, +-2, 5), WT 1, C 123: each grid takes 2.5e4 along
// y and -+6.25e4 along z (the couple of the 5 long lever). The MPC forces MYSTRAN prints are minus
// the loads reaching the independent grids.
TEST(Rbe3, MystranBenchmarkMpcForces) {
  const std::array<Eigen::Vector3d, 4> x = {Eigen::Vector3d(2, 2, 5), Eigen::Vector3d(-2, 2, 5),
                                            Eigen::Vector3d(-2, -2, 5), Eigen::Vector3d(2, -2, 5)};
  const Model m = rbe3_model({0, 0, 10}, x, {1, 1, 1, 1}, test::mask("123"));
  Vector6 p = Vector6::Zero();
  p(1) = 1e5;
  const auto f = distributed(m, p);
  const double mystran[4][3] = {{0, 2.5e4, -6.25e4}, {0, 2.5e4, -6.25e4}, {0, 2.5e4, 6.25e4}, {0, 2.5e4, 6.25e4}};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(f[i](k), mystran[i][k], 1e-6) << "grid " << i + 1 << " component " << k + 1;
}

// With rotations among Ci, the rotational weights are w Lc^2 (Lc: RMS distance of the independent
// grids from their centroid): the moment is shared between force couples and nodal moments,
//   f_i = w_i (F / W + alpha x r_i),  m_i = w_i Lc^2 alpha,  alpha = (J + sum w_i Lc^2 I)^-1 M_c.
TEST(Rbe3, RotationalWeightsScaleWithTheCharacteristicLength) {
  const std::array<Eigen::Vector3d, 4> x = {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 3, 0),
                                            Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(0, -3, 0)};
  const std::array<double, 4> w = {1, 1, 1, 1};
  const Eigen::Vector3d ref(0, 0, 0);
  const Model m = rbe3_model(ref, x, w, test::mask("123456"));
  Vector6 p;
  p << 0, 0, 0, 10.0, 20.0, 30.0;
  const auto f = distributed(m, p);
  const double Lc2 = (1 + 9 + 1 + 9) / 4.0;
  Eigen::Matrix3d J = 4 * Lc2 * Eigen::Matrix3d::Identity();
  for (int i = 0; i < 4; ++i) J += x[i].squaredNorm() * Eigen::Matrix3d::Identity() - x[i] * x[i].transpose();
  const Eigen::Vector3d alpha = J.inverse() * p.tail<3>();
  for (int i = 0; i < 4; ++i) {
    EXPECT_LT((f[i].head<3>() - alpha.cross(x[i])).norm(), 1e-12 * p.norm()) << "grid " << i + 1;
    EXPECT_LT((f[i].tail<3>() - Lc2 * alpha).norm(), 1e-12 * p.norm()) << "grid " << i + 1;
  }
}

// UM moves the dependent set to other dofs of the element without changing the constraint: the same
// stiffness, hence the same eigenvalues, as the default REFC dependents.
TEST(Rbe3, UmRedefinesTheDependentsWithoutChangingTheConstraint) {
  const std::array<Eigen::Vector3d, 4> x = {Eigen::Vector3d(2, 1, 0), Eigen::Vector3d(-2, 1, 0),
                                            Eigen::Vector3d(-2, -1, 0), Eigen::Vector3d(2, -1, 0)};
  Model a = rbe3_model({0.5, 0.2, 1.0}, x, {1, 2, 1, 2}, test::mask("123"));
  test::add_conm2(a, 500, 100, 2.0);
  for (int c = 1; c <= 6; ++c) test::add_celas2(a, 900 + c, 100, c, 50.0 * c);
  test::finalize_for_test(a);
  Model b = a;
  // the reference grid's translations become independent, grid 1's translations dependent instead
  // (the reference's rotations stay dependent). Not every choice works: T1 of grids 1 and 2, on a
  // line along x, leave a stretch along that line that the average does not see (an error).
  b.rbe3.front().um = {{100, test::mask("456")}, {1, test::mask("123")}};
  test::finalize_for_test(b);
  const GlobalMatrices ga = assemble(a, AssemblyOptions{}), gb = assemble(b, AssemblyOptions{});
  const ConstrainedSystem ca = apply_constraints(a, ga, std::nullopt), cb = apply_constraints(b, gb, std::nullopt);
  EXPECT_EQ(cb.status[6 * 4], DofStatus::Free);  // grid 100 T1 independent now
  EXPECT_EQ(cb.status[0], DofStatus::Dependent);  // grid 1 T1 dependent
  const auto la = test::dense_eigenvalues(test::dense(ca.K_ff), test::dense(ca.M_ff));
  const auto lb = test::dense_eigenvalues(test::dense(cb.K_ff), test::dense(cb.M_ff));
  ASSERT_EQ(la.size(), lb.size());
  for (std::size_t k = 0; k < la.size(); ++k) EXPECT_NEAR(lb[k] / la[k], 1.0, 1e-9) << "mode " << k;
}

// Cantilever of n bars along x from `first` (clamped), with second moment I about the bending axes.
void add_cantilever(Model& m, int first, double y, double I, int n, double L, int spc_set) {
  test::add_pbar(m, first, 1, 1e-3, I, I, 2 * I);
  for (int i = 0; i <= n; ++i) test::add_grid(m, first + i, L * i / n, y, 0);
  for (int i = 0; i < n; ++i) test::add_cbar(m, first + i, first, first + i, first + i + 1, {0, 1, 0});
  test::add_spc1(m, spc_set, test::mask("123456"), first);
}

Eigen::VectorXd solve(const Model& m, const ConstraintOptions& o, int load) {
  const GlobalMatrices g = assemble(m, AssemblyOptions{});
  const ConstrainedSystem c = apply_constraints(m, g, o);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(c.K_ff);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  return expand(c, ldlt.solve(reduce_load(c, g, load_vector(m, g.dofs, load))));
}

// MPC tying the tip deflections of two cantilevers (w_A - w_B = 0) under a tip load P on A: both
// deflect by w = P L^3 / (3 E (I_A + I_B)) (Euler-Bernoulli, exact with cubic elements); a stiff
// CELAS2 spring between the tips (k = 1e6 of the beams' tip stiffness) gives the same to 1e-5; an
// unselected MPC set changes nothing (the load stays on A alone).
TEST(Mpc, TiedCantileversMatchBeamTheoryAndAStiffSpring) {
  const double E = 2e11, L = 2.0, IA = 2e-7, IB = 5e-7, P = 1000.0;
  Model m;
  test::add_mat1(m, 1, E, 0.3, 7800);
  add_cantilever(m, 100, 0.0, IA, 4, L, 1);
  add_cantilever(m, 200, 1.0, IB, 4, L, 1);
  PointLoad f;
  f.sid = 9;
  f.grid = 104;
  f.scale = P;
  f.n = {0, 0, 1};
  m.point_loads.push_back(f);
  MpcEquation e;
  e.sid = 3;
  e.terms = {{104, 3, 1.0}, {204, 3, -1.0}};
  m.mpcs.push_back(e);
  MpcAdd add;
  add.sid = 30;
  add.sets = {3};
  m.mpcadds.push_back(add);
  test::finalize_for_test(m);
  ConstraintOptions o;
  o.spc_set = 1;
  o.mpc_set = 30;  // through MPCADD
  const Eigen::VectorXd u = solve(m, o, 9);
  const Eigen::Index a = 6 * static_cast<Eigen::Index>(m.grid_index.at(104)) + 2, b = 6 * static_cast<Eigen::Index>(m.grid_index.at(204)) + 2;
  const double w = P * L * L * L / (3 * E * (IA + IB));
  EXPECT_NEAR(u(a) / w, 1.0, 1e-12);
  EXPECT_NEAR(u(b) / w, 1.0, 1e-12);

  Model spring = m;
  spring.mpcs.clear();
  spring.mpcadds.clear();
  test::add_celas2(spring, 900, 104, 3, 1e6 * 3 * E * IA / (L * L * L), 204, 3);
  test::finalize_for_test(spring);
  ConstraintOptions os;
  os.spc_set = 1;
  const Eigen::VectorXd us = solve(spring, os, 9);
  EXPECT_NEAR(us(a) / u(a), 1.0, 1e-5);
  EXPECT_NEAR(us(b) / u(b), 1.0, 1e-5);

  const Eigen::VectorXd free = solve(m, os, 9);  // MPC not selected
  EXPECT_NEAR(free(a) / (P * L * L * L / (3 * E * IA)), 1.0, 1e-12);
  EXPECT_EQ(free(b), 0.0);
}

// RBAR with all six independent components at GA is RBE2 (GN = GA, CM = 123456); with the
// independent components split between the ends (CNA = 123, CNB = 456) it is the same rigid bar, so the
// same eigenvalues (the constraint subspace is the same, only its parametrisation differs).
TEST(Rbar, IsEquivalentToRbe2) {
  auto model = [](int kind) {
    Model m;
    test::add_mat1(m, 1, 7e10, 0.33, 2700);
    add_cantilever(m, 1, 0.0, 3e-7, 3, 1.5, 1);
    test::add_grid(m, 50, 1.9, 0.4, -0.3);
    test::add_conm2(m, 60, 50, 4.0).I11 = 0.1;
    if (kind == 0) {
      test::add_rbe2(m, 70, 4, "123456", {50});
    } else {
      Rbar r;
      r.id = 70;
      r.ga = 4;
      r.gb = 50;
      r.cna = kind == 1 ? test::mask("123456") : test::mask("123");
      r.cnb = kind == 1 ? 0 : test::mask("456");
      r.cma = static_cast<ComponentMask>(0x3F & ~r.cna);
      r.cmb = static_cast<ComponentMask>(0x3F & ~r.cnb);
      m.rbars.push_back(r);
    }
    test::finalize_for_test(m);
    return m;
  };
  std::vector<std::vector<double>> l;
  for (int kind = 0; kind < 3; ++kind) {
    const Model m = model(kind);
    const GlobalMatrices g = assemble(m, AssemblyOptions{});
    const ConstrainedSystem c = apply_constraints(m, g, 1);
    l.push_back(test::dense_eigenvalues(test::dense(c.K_ff), test::dense(c.M_ff)));
  }
  ASSERT_EQ(l[0].size(), l[1].size());
  ASSERT_EQ(l[0].size(), l[2].size());
  for (std::size_t k = 0; k < l[0].size(); ++k) {
    EXPECT_NEAR(l[1][k] / l[0][k], 1.0, 1e-10) << "mode " << k;
    EXPECT_NEAR(l[2][k] / l[0][k], 1.0, 1e-9) << "mode " << k;
  }
}

// AUTOSPC finds singular directions in the CD system, as Nastran: a bar along x with no axial and no
// torsional stiffness (A = J = 0) leaves basic x and rotation about x free at grid 2, whose CD system
// has e1 = (0.6, 0.8, 0): basic x = 0.6 e1 - 0.8 e2, so component 2 (the larger share) and 5 go
// (the expectation stated in MYSTRAN's BAR-AUTOSPC-CHECK deck); the diagonal alone shows none.
TEST(Autospc, SingularDirectionInARotatedDisplacementSystem) {
  Model m;
  test::add_mat1(m, 1, 1e7, 0.33, 0.1);
  test::add_pbar(m, 10, 1, 0.0, 0.1, 0.1, 0.0);
  Eigen::Matrix3d axes;
  axes.col(0) = Eigen::Vector3d(0.6, 0.8, 0);
  axes.col(2) = Eigen::Vector3d(0, 0, 1);
  axes.col(1) = axes.col(2).cross(axes.col(0));
  test::add_rect_coord(m, 25, Eigen::Vector3d::Zero(), axes);
  test::add_grid(m, 101, 0, 0, 0, 25, test::mask("123456"));
  test::add_grid(m, 102, 100, 0, 0, 25);
  test::add_cbar(m, 12, 10, 101, 102, {0, 1, 0});
  test::finalize_for_test(m);
  const GlobalMatrices g = assemble(m, AssemblyOptions{});
  const ConstrainedSystem c = apply_constraints(m, g, std::nullopt);
  const DofStatus expected[6] = {DofStatus::Free, DofStatus::AutoSpc, DofStatus::Free,
                                 DofStatus::Free, DofStatus::AutoSpc, DofStatus::Free};
  for (int k = 0; k < 6; ++k) EXPECT_EQ(c.status[static_cast<std::size_t>(6 + k)], expected[k]) << "component " << k + 1;
  // what is left is positive definite
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(c.K_ff);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  EXPECT_GT(ldlt.vectorD().minCoeff(), 0.0);
}

}  // namespace
}  // namespace seflex::fem
