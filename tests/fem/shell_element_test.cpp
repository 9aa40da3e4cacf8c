// CQUAD4 / CTRIA3 element physics: symmetry, exactly six rigid-body modes, mass sums.
#include <gtest/gtest.h>

#include <cmath>

#include "fem_test_util.hpp"
#include "seflex/fem/element_shell_quad4.hpp"
#include "seflex/fem/element_shell_tria3.hpp"

namespace seflex::fem {
namespace {

ShellSection steel_section(double t) {
  Mat1 steel;
  steel.id = 1;
  steel.E = 2e11;
  steel.G = 2e11 / 2.6;
  steel.nu = 0.3;
  steel.rho = 7800;
  const ShellMaterial m = shell_material(steel);
  PshellInput in;
  in.mid1 = in.mid2 = in.mid3 = &m;
  in.t = t;
  in.nsm = 1.5;
  return pshell_section(in);
}

// An arbitrary orientation and a distorted (and for the quad, warped) shape.
Eigen::Matrix3d some_rotation() { return so3::exp(Eigen::Vector3d(0.4, -0.7, 1.1)); }

Quad4Element distorted_quad(double warp) {
  Quad4Element e;
  const Eigen::Vector3d o(1, 2, 3);
  const Eigen::Matrix3d R = some_rotation();
  e.x = {o + R * Eigen::Vector3d(0, 0, 0), o + R * Eigen::Vector3d(1.2, 0.1, warp),
         o + R * Eigen::Vector3d(1.0, 0.9, 0), o + R * Eigen::Vector3d(-0.1, 0.7, warp)};
  e.section = steel_section(0.02);
  return e;
}

Tria3Element distorted_tria() {
  Tria3Element e;
  const Eigen::Vector3d o(-1, 0.5, 2);
  const Eigen::Matrix3d R = some_rotation();
  e.x = {o, o + R * Eigen::Vector3d(1.1, 0.2, 0), o + R * Eigen::Vector3d(0.3, 0.8, 0)};
  e.section = steel_section(0.02);
  return e;
}

template <int N>
void expect_rigid_and_rank(const NodeMatrix<N>& K, const std::array<Eigen::Vector3d, N>& x, const char* what) {
  EXPECT_LE((K - K.transpose()).norm(), 1e-12 * K.norm()) << what;
  const auto D = rigid_body_modes<N>(x, Eigen::Vector3d(0.3, 0.1, -0.2));
  EXPECT_LE((K * D).norm(), 1e-9 * K.norm() * D.norm()) << what;
  // exactly six zero eigenvalues; the smallest non-zero one (a drilling mode) is still clearly
  // positive relative to the K6ROT scale
  EXPECT_EQ(test::null_space_dimension(K, 1e-12), 6) << what;
}

TEST(ShellElement, Quad4SymmetricWithExactlySixRigidModes) {
  for (double warp : {0.0, 0.08}) {
    const Quad4Element e = distorted_quad(warp);
    expect_rigid_and_rank<4>(quad4_stiffness(e, 100.0), e.x, warp == 0.0 ? "flat" : "warped");
  }
}

TEST(ShellElement, Tria3SymmetricWithExactlySixRigidModes) {
  const Tria3Element e = distorted_tria();
  expect_rigid_and_rank<3>(tria3_stiffness(e, 100.0), e.x, "tria");
}

// With K6ROT = 0 only the one-point (centroid) drilling coupling remains: it constrains the mean
// rotation about the normal, so the other corner patterns of the rotation about the normal are
// zero-energy modes on top of the six rigid modes: 6 + 3 for the quad, 6 + 2 for the triangle.
TEST(ShellElement, K6rotGivesEveryCornerDrillingStiffness) {
  const Quad4Element e = distorted_quad(0.0);
  EXPECT_EQ(test::null_space_dimension(quad4_stiffness(e, 0.0), 1e-12), 9);
  const Tria3Element t = distorted_tria();
  EXPECT_EQ(test::null_space_dimension(tria3_stiffness(t, 0.0), 1e-12), 8);
}

TEST(ShellElement, MassSumsToTotal) {
  const Quad4Element q = distorted_quad(0.0);
  const double area = 0.5 * (q.x[2] - q.x[0]).cross(q.x[3] - q.x[1]).norm();
  const double mq = (7800 * 0.02 + 1.5) * area;
  for (MassKind kind : {MassKind::Lumped, MassKind::Coupled}) {
    const NodeMatrix<4> M = quad4_mass(q, kind);
    const auto D = rigid_body_modes<4>(q.x);
    const Matrix6 M0 = D.transpose() * M * D;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(M0(k, k), mq, 1e-12 * mq);
    // the centroid of the quadrilateral area (not the corner average): first moments are exact
    // for both masses because sum N_i x_i = x
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    {  // area centroid from two triangles
      const double a1 = 0.5 * (q.x[1] - q.x[0]).cross(q.x[2] - q.x[0]).norm();
      const double a2 = 0.5 * (q.x[2] - q.x[0]).cross(q.x[3] - q.x[0]).norm();
      c = (a1 * (q.x[0] + q.x[1] + q.x[2]) / 3 + a2 * (q.x[0] + q.x[2] + q.x[3]) / 3) / (a1 + a2);
    }
    EXPECT_NEAR(M0(1, 5) / mq, c.x(), 1e-12);
    EXPECT_NEAR(M0(2, 3) / mq, c.y(), 1e-12);
    EXPECT_NEAR(M0(0, 4) / mq, c.z(), 1e-12);
  }
  const Tria3Element t = distorted_tria();
  const double mt = (7800 * 0.02 + 1.5) * 0.5 * (t.x[1] - t.x[0]).cross(t.x[2] - t.x[0]).norm();
  for (MassKind kind : {MassKind::Lumped, MassKind::Coupled}) {
    const NodeMatrix<3> M = tria3_mass(t, kind);
    const auto D = rigid_body_modes<3>(t.x);
    const Matrix6 M0 = D.transpose() * M * D;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(M0(k, k), mt, 1e-12 * mt);
  }
}

}  // namespace
}  // namespace seflex::fem
