// CQUAD4 membrane stress resultants and differential stiffness (see element_shell_quad4.hpp).
// The mean-plane geometry and the QM6 membrane strain are those of element_shell_quad4.cpp.
#include <Eigen/LU>
#include <cmath>

#include "seflex/common/error.hpp"
#include "seflex/fem/element_shell_quad4.hpp"

namespace seflex::fem {
namespace {

constexpr double kXi[4] = {-1, 1, 1, -1};
constexpr double kEta[4] = {-1, -1, 1, 1};
const double kGauss = 1.0 / std::sqrt(3.0);

struct Plane {
  Eigen::Matrix3d R_BL;              // columns e1 e2 e3 in basic
  std::array<Eigen::Vector2d, 4> p;  // projected corners, relative to the centroid
};

Plane mean_plane(const Quad4Element& e) {
  const auto& x = e.x;
  const Eigen::Vector3d c = 0.25 * (x[0] + x[1] + x[2] + x[3]);
  const Eigen::Vector3d n = (x[2] - x[0]).cross(x[3] - x[1]);
  SEFLEX_DEMAND(n.norm() > 0.0, "CQUAD4 with zero area");
  const Eigen::Vector3d e3 = n.normalized();
  const Eigen::Vector3d a = (x[1] - x[0]) - (x[1] - x[0]).dot(e3) * e3;
  SEFLEX_DEMAND(a.norm() > 0.0, "CQUAD4 with a degenerate edge");
  Plane g;
  g.R_BL.col(0) = a.normalized();
  g.R_BL.col(1) = e3.cross(g.R_BL.col(0));
  g.R_BL.col(2) = e3;
  for (int i = 0; i < 4; ++i) g.p[i] = (g.R_BL.transpose() * (x[i] - c)).head<2>();
  return g;
}

// Shape values, Cartesian derivatives (rows d/dx, d/dy) and Jacobian determinant at (xi, eta).
struct Point {
  Eigen::Vector4d N;
  Eigen::Matrix<double, 2, 4> dN;
  Eigen::Matrix2d J;
  double det = 0;
};

Point at(const Plane& g, double xi, double eta) {
  Point q;
  Eigen::Matrix<double, 2, 4> dnat;
  for (int i = 0; i < 4; ++i) {
    q.N[i] = 0.25 * (1 + xi * kXi[i]) * (1 + eta * kEta[i]);
    dnat(0, i) = 0.25 * kXi[i] * (1 + eta * kEta[i]);
    dnat(1, i) = 0.25 * kEta[i] * (1 + xi * kXi[i]);
  }
  q.J.setZero();
  for (int i = 0; i < 4; ++i) {
    q.J(0, 0) += dnat(0, i) * g.p[i].x();
    q.J(0, 1) += dnat(0, i) * g.p[i].y();
    q.J(1, 0) += dnat(1, i) * g.p[i].x();
    q.J(1, 1) += dnat(1, i) * g.p[i].y();
  }
  q.det = q.J.determinant();
  SEFLEX_DEMAND(q.det > 0.0, "CQUAD4 with a non-positive Jacobian (non-convex or misordered corners)");
  q.dN = q.J.inverse() * dnat;
  return q;
}

constexpr double kPoints[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};  // times kGauss

}  // namespace

std::array<Eigen::Vector3d, 4> quad4_membrane_resultants(const Quad4Element& e,
                                                         const Eigen::Matrix<double, 24, 1>& u_basic) {
  const Plane g = mean_plane(e);
  const ShellSection& sec = e.section;
  // Corner displacements and rotations in the mean-plane axes.
  Eigen::Matrix<double, 8, 1> um;   // (u, v) per corner
  Eigen::Matrix<double, 8, 1> rot;  // (theta_x, theta_y) per corner
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d t = g.R_BL.transpose() * u_basic.segment<3>(6 * i);
    const Eigen::Vector3d r = g.R_BL.transpose() * u_basic.segment<3>(6 * i + 3);
    um.segment<2>(2 * i) = t.head<2>();
    rot.segment<2>(2 * i) = r.head<2>();
  }
  const Point c0 = at(g, 0, 0);
  const Eigen::Matrix2d J0inv = c0.J.inverse();
  std::array<Eigen::Matrix<double, 3, 8>, 4> Bm, Bb;
  std::array<Eigen::Matrix<double, 3, 4>, 4> Gm;
  Eigen::Matrix4d Kaa = Eigen::Matrix4d::Zero();
  Eigen::Vector4d r_a = Eigen::Vector4d::Zero();  // incompatible-mode load: int Gm^T (A Bm u + B Bb theta)
  for (int k = 0; k < 4; ++k) {
    const double xi = kPoints[k][0] * kGauss, eta = kPoints[k][1] * kGauss;
    const Point q = at(g, xi, eta);
    Bm[k].setZero();
    Bb[k].setZero();
    for (int i = 0; i < 4; ++i) {
      Bm[k](0, 2 * i) = q.dN(0, i);
      Bm[k](1, 2 * i + 1) = q.dN(1, i);
      Bm[k](2, 2 * i) = q.dN(1, i);
      Bm[k](2, 2 * i + 1) = q.dN(0, i);
      // kappa = (theta_y,x, -theta_x,y, theta_y,y - theta_x,x)
      Bb[k](0, 2 * i + 1) = q.dN(0, i);
      Bb[k](1, 2 * i) = -q.dN(1, i);
      Bb[k](2, 2 * i + 1) = q.dN(1, i);
      Bb[k](2, 2 * i) = -q.dN(0, i);
    }
    const Eigen::Vector2d P1 = (c0.det / q.det) * (J0inv * Eigen::Vector2d(-2 * xi, 0));
    const Eigen::Vector2d P2 = (c0.det / q.det) * (J0inv * Eigen::Vector2d(0, -2 * eta));
    Gm[k] << P1.x(), P2.x(), 0, 0, 0, 0, P1.y(), P2.y(), P1.y(), P2.y(), P1.x(), P2.x();
    Kaa += q.det * Gm[k].transpose() * sec.A * Gm[k];
    r_a += q.det * Gm[k].transpose() * (sec.A * (Bm[k] * um) + sec.B * (Bb[k] * rot));
  }
  Eigen::Vector4d alpha = Eigen::Vector4d::Zero();
  if (Kaa.trace() > 0.0) alpha = -Kaa.inverse() * r_a;
  std::array<Eigen::Vector3d, 4> N;
  for (int k = 0; k < 4; ++k) N[k] = sec.A * (Bm[k] * um + Gm[k] * alpha) + sec.B * (Bb[k] * rot);
  return N;
}

NodeMatrix<4> quad4_geometric_stiffness(const Quad4Element& e, const std::array<Eigen::Vector3d, 4>& N_gauss) {
  const Plane g = mean_plane(e);
  Eigen::Matrix4d S = Eigen::Matrix4d::Zero();  // scalar pattern int grad N_i^T Nmat grad N_j dA
  for (int k = 0; k < 4; ++k) {
    const Point q = at(g, kPoints[k][0] * kGauss, kPoints[k][1] * kGauss);
    Eigen::Matrix2d Nm;
    Nm << N_gauss[k](0), N_gauss[k](2), N_gauss[k](2), N_gauss[k](1);
    S += q.det * q.dN.transpose() * Nm * q.dN;
  }
  NodeMatrix<4> K = NodeMatrix<4>::Zero();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) K.block<3, 3>(6 * i, 6 * j) = S(i, j) * Eigen::Matrix3d::Identity();
  return K;
}

}  // namespace seflex::fem
