// The DKT (element_plate_dkt.hpp) on its own and as the bending part of CTRIA3 for sections without
// transverse shear flexibility:
//  - constant curvature: the corner values of any quadratic deflection w (theta_x = w,y, theta_y =
//    -w,x) give its curvature kappa = -(w,xx, w,yy, 2 w,xy) exactly at every point of any triangle, and
//    the strain energy A kappa^T D kappa / 2 (Batoz, Bathe & Ho 1980: the element passes the patch
//    test; the assembled patch test is in shell_patch_test.cpp);
//  - the three rigid plate motions are its only zero-energy modes; as part of CTRIA3 the free element
//    has exactly six rigid-body modes;
//  - the curvature is the derivative of the rotation field the element interpolates: along each edge
//    the tangential rotation is the quadratic through the corners and the midpoint value Batoz, Bathe
//    & Ho define (-dw/ds of the cubic edge deflection), and kappa's tangential component is its slope.
#include <gtest/gtest.h>

#include <cmath>

#include "fem_test_util.hpp"
#include "seflex/fem/element_plate_dkt.hpp"
#include "seflex/fem/element_shell_tria3.hpp"
#include "seflex/fem/section.hpp"

namespace seflex::fem {
namespace {

// A distorted triangle (corners counter-clockwise) away from the origin.
const std::array<Eigen::Vector2d, 3> kTriangle = {Eigen::Vector2d(0.31, -0.12), Eigen::Vector2d(1.47, 0.21),
                                                  Eigen::Vector2d(0.52, 0.93)};

// Corner dofs (w, theta_x, theta_y) of w = c0 + c1 x + c2 y + (c3 x^2 + c4 x y + c5 y^2) / 2.
PlateVector3 quadratic_dofs(const std::array<Eigen::Vector2d, 3>& p, const Eigen::Matrix<double, 6, 1>& c) {
  PlateVector3 q;
  for (int i = 0; i < 3; ++i) {
    const double x = p[i].x(), y = p[i].y();
    q[3 * i] = c[0] + c[1] * x + c[2] * y + 0.5 * (c[3] * x * x + c[4] * x * y + c[5] * y * y);
    q[3 * i + 1] = c[2] + 0.5 * c[4] * x + c[5] * y;     // theta_x = w,y
    q[3 * i + 2] = -(c[1] + c[3] * x + 0.5 * c[4] * y);  // theta_y = -w,x
  }
  return q;
}

Eigen::Matrix3d orthotropic_D() {  // a symmetric, fully populated bending stiffness (an angle-ply laminate)
  Eigen::Matrix3d D;
  D << 12.0, 3.1, 1.7, 3.1, 7.5, -0.9, 1.7, -0.9, 4.2;
  return D;
}

TEST(DktElement, ConstantCurvatureIsExactOnAnyTriangle) {
  Eigen::Matrix<double, 6, 1> c;
  c << 0.3, -0.2, 0.7, 1.3, -0.8, 0.55;
  const PlateVector3 q = quadratic_dofs(kTriangle, c);
  const Eigen::Vector3d kappa(-c[3], -c[5], -c[4]);  // -(w,xx, w,yy, 2 w,xy)
  const DktCurvature C = dkt_curvature(kTriangle);
  for (const Eigen::Vector3d& L : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.2, 0.3, 0.5),
                                   Eigen::Vector3d(0.5, 0.5, 0), Eigen::Vector3d(1.0 / 3, 1.0 / 3, 1.0 / 3)}) {
    EXPECT_LE((C.at(L) * q - kappa).norm(), 1e-12 * kappa.norm()) << L.transpose();
  }
  const Eigen::Matrix3d D = orthotropic_D();
  const double area = 0.5 * ((kTriangle[1] - kTriangle[0]).x() * (kTriangle[2] - kTriangle[0]).y() -
                             (kTriangle[1] - kTriangle[0]).y() * (kTriangle[2] - kTriangle[0]).x());
  EXPECT_NEAR(C.area, area, 1e-15);
  const double U = 0.5 * q.dot(dkt_stiffness(kTriangle, D) * q), U_exact = 0.5 * area * kappa.dot(D * kappa);
  EXPECT_NEAR(U / U_exact, 1.0, 1e-12);
}

TEST(DktElement, RigidPlateMotionsAreTheOnlyZeroEnergyModes) {
  const PlateMatrix3 K = dkt_stiffness(kTriangle, orthotropic_D());
  EXPECT_LE((K - K.transpose()).norm(), 1e-14 * K.norm());
  for (int k = 0; k < 3; ++k) {  // w = 1, x, y
    Eigen::Matrix<double, 6, 1> c = Eigen::Matrix<double, 6, 1>::Zero();
    c[k] = 1.0;
    EXPECT_LE((K * quadratic_dofs(kTriangle, c)).norm(), 1e-13 * K.norm()) << "rigid motion " << k;
  }
  EXPECT_EQ(test::null_space_dimension(K, 1e-12), 3);
  // invariant to where the origin is
  std::array<Eigen::Vector2d, 3> moved = kTriangle;
  for (auto& p : moved) p += Eigen::Vector2d(-7.0, 3.0);
  EXPECT_LE((dkt_stiffness(moved, orthotropic_D()) - K).norm(), 1e-12 * K.norm());
}

// beta = (theta_y, -theta_x) is quadratic; kappa its derivative. The DKT's beta at the midpoint of
// edge i-j is defined by its corner dofs (element_plate_dkt.hpp); check that the curvature the element
// uses is the derivative of that field: along the edge, d(beta . s)/ds at the midpoint is the mean of
// the corners' (quadratic along the edge), and the tangential derivative s^T grad beta s follows from
// kappa = (beta_x,x, beta_y,y, beta_x,y + beta_y,x) as kxx s_x^2 + kyy s_y^2 + kxy s_x s_y.
TEST(DktElement, CurvatureIsTheDerivativeOfTheInterpolatedRotation) {
  PlateVector3 q;
  q << 0.013, -0.21, 0.34, -0.027, 0.18, -0.05, 0.041, 0.09, 0.27;  // any corner dofs
  const DktCurvature C = dkt_curvature(kTriangle);
  for (int e = 0; e < 3; ++e) {
    const int i = e, j = (e + 1) % 3;
    const Eigen::Vector2d d = kTriangle[j] - kTriangle[i];
    const double l = d.norm();
    const Eigen::Vector2d s = d / l;
    auto beta = [&](int k) { return Eigen::Vector2d(q[3 * k + 2], -q[3 * k + 1]); };
    // the DKT's tangential rotation at the midpoint: -dw/ds of the cubic Hermite edge deflection
    const double ws_i = -s.dot(beta(i)), ws_j = -s.dot(beta(j));
    const double bs_mid = -(1.5 * (q[3 * j] - q[3 * i]) / l - 0.25 * (ws_i + ws_j));
    // beta . s along the edge is the quadratic through (0, bs_i), (l/2, bs_mid), (l, bs_j): its slope at
    // s = 0, l/2, l
    const double b0 = s.dot(beta(i)), b1 = bs_mid, b2 = s.dot(beta(j));
    const double slope[3] = {(-3 * b0 + 4 * b1 - b2) / l, (b2 - b0) / l, (b0 - 4 * b1 + 3 * b2) / l};
    const Eigen::Vector3d L_at[3] = {Eigen::Vector3d::Unit(i), 0.5 * (Eigen::Vector3d::Unit(i) + Eigen::Vector3d::Unit(j)),
                                     Eigen::Vector3d::Unit(j)};
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d kappa = C.at(L_at[k]) * q;
      const double along = kappa[0] * s.x() * s.x() + kappa[1] * s.y() * s.y() + kappa[2] * s.x() * s.y();
      EXPECT_NEAR(along, slope[k], 1e-12 * (std::abs(slope[k]) + 1.0)) << "edge " << e << " point " << k;
    }
  }
}

ShellSection kirchhoff_section() {  // PSHELL MID1 = MID2, MID3 blank
  Mat1 al;
  al.id = 1;
  al.E = 7e10;
  al.nu = 0.3;
  al.G = al.E / 2.6;
  al.rho = 2700;
  const ShellMaterial m = shell_material(al);
  PshellInput in;
  in.mid1 = in.mid2 = &m;
  in.t = 0.004;
  return pshell_section(in);
}

TEST(DktElement, FreeKirchhoffCtria3HasExactlySixRigidBodyModes) {
  Tria3Element e;
  const Eigen::Vector3d o(-1, 0.5, 2);
  const Eigen::Matrix3d R = so3::exp(Eigen::Vector3d(0.4, -0.7, 1.1));
  e.x = {o, o + R * Eigen::Vector3d(1.1, 0.2, 0), o + R * Eigen::Vector3d(0.3, 0.8, 0)};
  e.section = kirchhoff_section();
  ASSERT_FALSE(e.section.shear_flexible);
  const NodeMatrix<3> K = tria3_stiffness(e, 100.0);
  EXPECT_LE((K - K.transpose()).norm(), 1e-12 * K.norm());
  const auto D = rigid_body_modes<3>(e.x, Eigen::Vector3d(0.3, 0.1, -0.2));
  EXPECT_LE((K * D).norm(), 1e-9 * K.norm() * D.norm());
  EXPECT_EQ(test::null_space_dimension(K, 1e-12), 6);
  // K6ROT = 0 leaves two corner patterns of the rotation about the normal free (as MITC3)
  EXPECT_EQ(test::null_space_dimension(tria3_stiffness(e, 0.0), 1e-12), 8);
  // the plate block is the DKT's in the element plane
  Tria3Element flat;
  flat.x = {Eigen::Vector3d(kTriangle[0].x(), kTriangle[0].y(), 0), Eigen::Vector3d(kTriangle[1].x(), kTriangle[1].y(), 0),
            Eigen::Vector3d(kTriangle[2].x(), kTriangle[2].y(), 0)};
  flat.section = kirchhoff_section();
  // element axes: e1 along G1-G2, so compare in a frame turned to it
  const NodeMatrix<3> Kf = tria3_stiffness(flat, 100.0);
  const Eigen::Vector2d e1 = (kTriangle[1] - kTriangle[0]).normalized();
  const double phi = std::atan2(e1.y(), e1.x());
  // the DKT is invariant under rotation of the plane for an isotropic D, so rotate the corners
  std::array<Eigen::Vector2d, 3> local;
  const Eigen::Rotation2Dd back(-phi);
  for (int i = 0; i < 3; ++i) local[i] = back * kTriangle[i];
  const PlateMatrix3 Kp = dkt_stiffness(local, flat.section.D);
  // plate dofs of Kf in basic: w = T3, theta = R(phi) (theta_x', theta_y')
  Eigen::Matrix<double, 9, 18> T = Eigen::Matrix<double, 9, 18>::Zero();
  const Eigen::Rotation2Dd rot(phi);
  for (int i = 0; i < 3; ++i) {
    T(3 * i, 6 * i + 2) = 1.0;
    T.block<2, 2>(3 * i + 1, 6 * i + 3) = rot.toRotationMatrix().transpose();
  }
  EXPECT_LE((T * Kf * T.transpose() - Kp).norm(), 1e-10 * Kp.norm());
}

}  // namespace
}  // namespace seflex::fem
