// Assembly: scatter into the connectivity pattern, rotation to displacement (CD) systems, springs,
// concentrated masses, WTMASS, and the load vector.
#include <gtest/gtest.h>

#include <cmath>

#include "fem_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_bar.hpp"
#include "seflex/fem/element_conm2.hpp"
#include "seflex/fem/loads.hpp"

namespace seflex::fem {
namespace {

// Three grids, two bars in different directions, a CONM2 with offset and inertia.
Model frame_model() {
  Model m;
  test::add_grid(m, 10, 0, 0, 0);
  test::add_grid(m, 20, 1.0, 0.2, 0.1);
  test::add_grid(m, 30, 1.5, 1.1, -0.3);
  test::add_mat1(m, 1, 7e10, 0.3, 2700);
  BarProperty& p = test::add_pbar(m, 5, 1, 1e-3, 2e-6, 1e-6, 3e-6, 0.2);
  p.K1 = p.K2 = 0.8;
  test::add_cbar(m, 1, 5, 10, 20, {0, 0, 1});
  test::add_cbar(m, 2, 5, 20, 30, {0.3, 0.1, 1});
  Conm2& c = test::add_conm2(m, 7, 30, 4.0);
  c.x = {0.1, -0.2, 0.3};
  c.I11 = 0.5;
  c.I22 = 0.4;
  c.I33 = 0.3;
  c.I21 = 0.05;
  c.I31 = -0.02;
  c.I32 = 0.01;
  test::finalize_for_test(m);
  return m;
}

// Dense reference assembly of the same model from the element functions.
void dense_reference(const Model& m, Eigen::MatrixXd& K, Eigen::MatrixXd& M, MassKind kind) {
  K = Eigen::MatrixXd::Zero(18, 18);
  M = Eigen::MatrixXd::Zero(18, 18);
  for (const Bar& b : m.bars) {
    const BarElement e = make_bar_element(m, b);
    const NodeMatrix<2> Ke = bar_stiffness(e), Me = bar_mass(e, kind);
    const int n[2] = {static_cast<int>(m.grid_index.at(b.ga)), static_cast<int>(m.grid_index.at(b.gb))};
    for (int a = 0; a < 2; ++a)
      for (int c = 0; c < 2; ++c) {
        K.block<6, 6>(6 * n[a], 6 * n[c]) += Ke.block<6, 6>(6 * a, 6 * c);
        M.block<6, 6>(6 * n[a], 6 * n[c]) += Me.block<6, 6>(6 * a, 6 * c);
      }
  }
  M.block<6, 6>(12, 12) += conm2_mass(make_conm2_element(m, m.conm2[0]));
}

TEST(Assembly, ScattersElementMatricesIntoConnectivityPattern) {
  const Model m = frame_model();
  for (MassKind kind : {MassKind::Lumped, MassKind::Coupled}) {
    AssemblyOptions o;
    o.mass = kind;
    const GlobalMatrices g = assemble(m, o);
    Eigen::MatrixXd K, M;
    dense_reference(m, K, M, kind);
    EXPECT_LE((test::dense(g.K) - K).norm(), 1e-12 * K.norm());
    EXPECT_LE((test::dense(g.M) - M).norm(), 1e-12 * M.norm());
    // grids 10 and 30 share no element: no entries between them
    for (int r = 0; r < 6; ++r)
      for (int c = 12; c < 18; ++c) EXPECT_EQ(g.K.coeff(r, c), 0.0);
    // the pattern follows the connectivity: K has exactly the coupled blocks (after pruning the
    // exact zeros there are at most 3 x 36 + 2 x 2 x 36 entries)
    EXPECT_LE(g.K.nonZeros(), 7 * 36);
    EXPECT_TRUE(g.K.isCompressed());
  }
}

TEST(Assembly, WtmassScalesEveryMass) {
  const Model m = frame_model();
  AssemblyOptions o;
  const GlobalMatrices g1 = assemble(m, o);
  o.wtmass = 0.002591;
  const GlobalMatrices g2 = assemble(m, o);
  EXPECT_LE((test::dense(g2.M) - 0.002591 * test::dense(g1.M)).norm(), 1e-15 * test::dense(g1.M).norm());
  EXPECT_LE((test::dense(g2.K) - test::dense(g1.K)).norm(), 0.0);
}

// A grid whose displacement system CD is a rotated rectangular system: its dofs are the basic ones
// rotated, K_cd = T^T K_basic T with T = blockdiag(A, A) on that grid (A: CD axes in basic).
TEST(Assembly, RotatesGridBlocksToDisplacementSystem) {
  Model m = frame_model();
  const GlobalMatrices gb = assemble(m, AssemblyOptions{});
  const Eigen::Matrix3d R4 = so3::exp(Eigen::Vector3d(0.3, -0.5, 0.8));
  test::add_rect_coord(m, 4, {5, 6, 7}, R4);
  m.grids[1].cd = 4;
  m.bars[1].offt = "BGG";  // keep bar 2's orientation vector in basic (it is in GA's CD by default)
  test::finalize_for_test(m);
  const GlobalMatrices gc = assemble(m, AssemblyOptions{});
  Eigen::MatrixXd T = Eigen::MatrixXd::Identity(18, 18);
  T.block<3, 3>(6, 6) = R4;
  T.block<3, 3>(9, 9) = R4;
  EXPECT_LE((test::dense(gc.K) - T.transpose() * test::dense(gb.K) * T).norm(), 1e-12 * test::dense(gb.K).norm());
  EXPECT_LE((test::dense(gc.M) - T.transpose() * test::dense(gb.M) * T).norm(), 1e-12 * test::dense(gb.M).norm());
}

// CONM2 of mass m at offset d with inertia J about its CG: the rigid-body mass about the grid is
// [m I, -m [d]x; m [d]x, J + m (|d|^2 I - d d^T)] (parallel-axis theorem).
TEST(Assembly, Conm2OffsetAndInertia) {
  const Model m = frame_model();
  const Conm2Element e = make_conm2_element(m, m.conm2[0]);
  const Matrix6 M = conm2_mass(e);
  const Eigen::Vector3d d(0.1, -0.2, 0.3);
  Eigen::Matrix3d J;
  J << 0.5, -0.05, 0.02, -0.05, 0.4, -0.01, 0.02, -0.01, 0.3;
  EXPECT_LE((M.topLeftCorner<3, 3>() - 4.0 * Eigen::Matrix3d::Identity()).norm(), 1e-15);
  EXPECT_LE((M.topRightCorner<3, 3>() + 4.0 * so3::skew(d)).norm(), 1e-14);
  const Eigen::Matrix3d Jg = J + 4.0 * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  EXPECT_LE((M.bottomRightCorner<3, 3>() - Jg).norm(), 1e-14);
}

TEST(Assembly, ScalarSpringsBetweenComponentsAndToGround) {
  Model m;
  test::add_grid(m, 1, 0, 0, 0);
  test::add_grid(m, 2, 1, 0, 0);
  ScalarPoint sp;
  sp.id = 50;
  m.spoints.push_back(sp);
  SpringProperty pe;
  pe.id = 3;
  pe.k = 250.0;
  m.spring_props.push_back(pe);
  Spring s1;  // CELAS1 between 1-T3 and 2-R2
  s1.id = 1;
  s1.pid = 3;
  s1.g1 = 1;
  s1.c1 = 3;
  s1.g2 = 2;
  s1.c2 = 5;
  Spring s2;  // CELAS2 grounded on scalar point 50
  s2.id = 2;
  s2.inline_property = true;
  s2.k = 40.0;
  s2.g1 = 50;
  m.springs = {s1, s2};
  test::finalize_for_test(m);
  const GlobalMatrices g = assemble(m, AssemblyOptions{});
  ASSERT_EQ(g.K.rows(), 13);
  EXPECT_EQ(g.K.coeff(2, 2), 250.0);
  EXPECT_EQ(g.K.coeff(10, 10), 250.0);
  EXPECT_EQ(g.K.coeff(2, 10), -250.0);
  EXPECT_EQ(g.K.coeff(10, 2), -250.0);
  EXPECT_EQ(g.K.coeff(12, 12), 40.0);
  EXPECT_EQ(g.K.nonZeros(), 5);
}

// FORCE in a rotated system CID at a grid whose CD is another rotated system:
// p_cd = A_cd^T A_cid (F N); MOMENT likewise on R1-R3; LOAD combines with scale factors.
TEST(Loads, ForceAndMomentRotatedAndCombined) {
  Model m = frame_model();
  const Eigen::Matrix3d Ra = so3::exp(Eigen::Vector3d(0.1, 0.2, 0.3)), Rb = so3::exp(Eigen::Vector3d(-0.4, 0.0, 0.9));
  test::add_rect_coord(m, 2, {1, 1, 1}, Ra);
  test::add_rect_coord(m, 3, {0, -2, 0}, Rb);
  m.grids[2].cd = 3;
  PointLoad f;
  f.sid = 11;
  f.grid = 30;
  f.cid = 2;
  f.scale = 10.0;
  f.n = {1, 2, -1};
  PointLoad mo = f;
  mo.kind = PointLoad::Kind::Moment;
  mo.cid = 0;
  mo.scale = 3.0;
  mo.n = {0, 0, 1};
  m.point_loads = {f, mo};
  LoadCombination lc;
  lc.sid = 12;
  lc.s = 2.0;
  lc.terms = {{-0.5, 11}};
  m.load_combinations = {lc};
  test::finalize_for_test(m);
  const DofMap dofs = make_dof_map(m);
  const Eigen::VectorXd p = load_vector(m, dofs, 11);
  const Eigen::Vector3d fcd = Rb.transpose() * Ra * Eigen::Vector3d(10, 20, -10);
  const Eigen::Vector3d mcd = Rb.transpose() * Eigen::Vector3d(0, 0, 3);
  EXPECT_LE((p.segment<3>(12) - fcd).norm(), 1e-13);
  EXPECT_LE((p.segment<3>(15) - mcd).norm(), 1e-13);
  EXPECT_EQ(p.head<12>().norm(), 0.0);
  const Eigen::VectorXd q = load_vector(m, dofs, 12);
  EXPECT_LE((q + p).norm(), 1e-13);
}

}  // namespace
}  // namespace seflex::fem
