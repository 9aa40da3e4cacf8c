// CTRIA3 membrane stress resultants and differential stiffness (see element_shell_tria3.hpp).
#include "seflex/common/error.hpp"
#include "seflex/fem/element_shell_tria3.hpp"

namespace seflex::fem {
namespace {

// Element axes (columns e1 along G1->G2, e2, e3 the normal; as element_shell_tria3.cpp), area and
// the shape-function gradients dN_i/dx = b_i, dN_i/dy = c_i.
struct Plane {
  Eigen::Matrix3d R_BL;
  double area = 0;
  Eigen::Vector3d b, c;
};

Plane plane(const Tria3Element& e) {
  const auto& x = e.x;
  const Eigen::Vector3d n = (x[1] - x[0]).cross(x[2] - x[0]);
  SEFLEX_DEMAND(n.norm() > 0.0, "CTRIA3 with zero area");
  Plane g;
  g.R_BL.col(0) = (x[1] - x[0]).normalized();
  g.R_BL.col(2) = n.normalized();
  g.R_BL.col(1) = g.R_BL.col(2).cross(g.R_BL.col(0));
  std::array<Eigen::Vector2d, 3> p;
  for (int i = 0; i < 3; ++i) p[i] = (g.R_BL.transpose() * (x[i] - x[0])).head<2>();
  g.area = 0.5 * n.norm();
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    g.b[i] = (p[j].y() - p[k].y()) / (2 * g.area);
    g.c[i] = (p[k].x() - p[j].x()) / (2 * g.area);
  }
  return g;
}

}  // namespace

Eigen::Vector3d tria3_membrane_resultants(const Tria3Element& e, const Eigen::Matrix<double, 18, 1>& u_basic) {
  const Plane g = plane(e);
  Eigen::Vector3d eps = Eigen::Vector3d::Zero(), kappa = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d t = g.R_BL.transpose() * u_basic.segment<3>(6 * i);
    const Eigen::Vector3d r = g.R_BL.transpose() * u_basic.segment<3>(6 * i + 3);
    eps += Eigen::Vector3d(g.b[i] * t.x(), g.c[i] * t.y(), g.c[i] * t.x() + g.b[i] * t.y());
    kappa += Eigen::Vector3d(g.b[i] * r.y(), -g.c[i] * r.x(), g.c[i] * r.y() - g.b[i] * r.x());
  }
  return e.section.A * eps + e.section.B * kappa;
}

NodeMatrix<3> tria3_geometric_stiffness(const Tria3Element& e, const Eigen::Vector3d& N) {
  const Plane g = plane(e);
  Eigen::Matrix<double, 2, 3> dN;
  dN.row(0) = g.b.transpose();
  dN.row(1) = g.c.transpose();
  Eigen::Matrix2d Nm;
  Nm << N(0), N(2), N(2), N(1);
  const Eigen::Matrix3d S = g.area * dN.transpose() * Nm * dN;
  NodeMatrix<3> K = NodeMatrix<3>::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) K.block<3, 3>(6 * i, 6 * j) = S(i, j) * Eigen::Matrix3d::Identity();
  return K;
}

}  // namespace seflex::fem
