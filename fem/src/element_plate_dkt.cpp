// DKT plate triangle (see element_plate_dkt.hpp for the formulation and reference).
#include "seflex/fem/element_plate_dkt.hpp"

#include "seflex/common/error.hpp"

namespace seflex::fem {
namespace {

using Beta = Eigen::Matrix<double, 2, 9>;  // beta = (theta_y, -theta_x) at a node, from the plate dofs
constexpr int kW = 0, kRx = 1, kRy = 2;

}  // namespace

DktCurvature dkt_curvature(const std::array<Eigen::Vector2d, 3>& p) {
  const Eigen::Vector2d a = p[1] - p[0], b = p[2] - p[0];
  const double twice = a.x() * b.y() - a.y() * b.x();
  SEFLEX_DEMAND(twice > 0.0, "DKT triangle with zero area or clockwise corners");
  std::array<Eigen::Vector2d, 3> grad;  // grad L_i
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    grad[i] = Eigen::Vector2d(p[j].y() - p[k].y(), p[k].x() - p[j].x()) / twice;
  }
  // beta at the corners and at the edge midpoints (edge e from corner e to e + 1)
  std::array<Beta, 3> corner, mid;
  for (int i = 0; i < 3; ++i) {
    corner[i].setZero();
    corner[i](0, 3 * i + kRy) = 1.0;
    corner[i](1, 3 * i + kRx) = -1.0;
  }
  for (int e = 0; e < 3; ++e) {
    const int i = e, j = (e + 1) % 3;
    const Eigen::Vector2d d = p[j] - p[i];
    const double l = d.norm();
    const Eigen::Vector2d s = d / l, n(s.y(), -s.x());
    const Beta sum = corner[i] + corner[j];
    Eigen::Matrix<double, 1, 9> bs = -0.25 * s.transpose() * sum;  // s . beta_ij
    bs(3 * j + kW) -= 1.5 / l;
    bs(3 * i + kW) += 1.5 / l;
    const Eigen::Matrix<double, 1, 9> bn = 0.5 * n.transpose() * sum;  // n . beta_ij
    mid[e] = s * bs + n * bn;
  }
  DktCurvature c;
  c.area = 0.5 * twice;
  for (int k = 0; k < 3; ++k) {
    // grad N at corner k (L = e_k) of the quadratic shape functions: corner c: (4 L_c - 1) grad L_c;
    // midpoint of edge (i, j): 4 (L_i grad L_j + L_j grad L_i)
    Eigen::Matrix<double, 3, 9>& C = c.at_corner[k];
    C.setZero();
    auto add = [&C](const Eigen::Vector2d& g, const Beta& beta) {
      C.row(0) += g.x() * beta.row(0);
      C.row(1) += g.y() * beta.row(1);
      C.row(2) += g.y() * beta.row(0) + g.x() * beta.row(1);
    };
    for (int n = 0; n < 3; ++n) add((n == k ? 3.0 : -1.0) * grad[n], corner[n]);
    for (int e = 0; e < 3; ++e) {
      const int i = e, j = (e + 1) % 3;
      if (i == k) add(4.0 * grad[j], mid[e]);
      if (j == k) add(4.0 * grad[i], mid[e]);
    }
  }
  return c;
}

PlateMatrix3 dkt_stiffness(const std::array<Eigen::Vector2d, 3>& p, const Eigen::Matrix3d& D) {
  const DktCurvature c = dkt_curvature(p);
  PlateMatrix3 K = PlateMatrix3::Zero();
  for (int e = 0; e < 3; ++e) {  // edge midpoints, weight A/3: exact for the quadratic integrand
    Eigen::Vector3d L = Eigen::Vector3d::Constant(0.5);
    L[(e + 2) % 3] = 0.0;
    const Eigen::Matrix<double, 3, 9> B = c.at(L);
    K.noalias() += (c.area / 3.0) * B.transpose() * D * B;
  }
  return 0.5 * (K + K.transpose());
}

}  // namespace seflex::fem
