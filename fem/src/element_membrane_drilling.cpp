// Allman-type membranes of CQUADR and CTRIAR (see element_membrane_drilling.hpp).
#include "seflex/fem/element_membrane_drilling.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace seflex::fem {
namespace {

/// The quadratic element's (u, v) at its 2N nodes (corners, then the mid-side node of edge k -> k+1)
/// from the corner dofs (u, v, theta): 4N x 3N.
template <int N>
Eigen::Matrix<double, 4 * N, 3 * N> allman_map(const std::array<Eigen::Vector2d, N>& p) {
  Eigen::Matrix<double, 4 * N, 3 * N> T = Eigen::Matrix<double, 4 * N, 3 * N>::Zero();
  for (int i = 0; i < N; ++i) T(2 * i, 3 * i) = T(2 * i + 1, 3 * i + 1) = 1.0;
  for (int k = 0; k < N; ++k) {
    const int i = k, j = (k + 1) % N, m = N + k;
    const Eigen::Vector2d d = p[static_cast<std::size_t>(j)] - p[static_cast<std::size_t>(i)];
    // (L/8) (theta_j - theta_i) n, n = (d_y, -d_x)/L the outward normal of a counterclockwise edge
    T(2 * m, 3 * i) = T(2 * m, 3 * j) = 0.5;
    T(2 * m + 1, 3 * i + 1) = T(2 * m + 1, 3 * j + 1) = 0.5;
    T(2 * m, 3 * j + 2) = d.y() / 8, T(2 * m, 3 * i + 2) = -d.y() / 8;
    T(2 * m + 1, 3 * j + 2) = -d.x() / 8, T(2 * m + 1, 3 * i + 2) = d.x() / 8;
  }
  return T;
}

/// Cartesian derivatives (rows d/dx, d/dy) of the quadratic element's 2N shape functions and the
/// area element at natural point (a, b): quadrilateral (xi, eta) serendipity on the corners'
/// bilinear map; triangle (L2, L3) six-node on the affine map.
template <int N>
Eigen::Matrix<double, 2, 2 * N> quadratic_derivatives(const std::array<Eigen::Vector2d, N>& p, double a, double b, double& det);

template <>
Eigen::Matrix<double, 2, 8> quadratic_derivatives<4>(const std::array<Eigen::Vector2d, 4>& p, double xi, double eta, double& det) {
  static const double xn[4] = {-1, 1, 1, -1}, yn[4] = {-1, -1, 1, 1};
  Eigen::Matrix<double, 2, 8> dN;  // natural derivatives
  for (int i = 0; i < 4; ++i) {
    const double x = xn[i], y = yn[i];
    dN(0, i) = 0.25 * x * (1 + eta * y) * (2 * xi * x + eta * y);
    dN(1, i) = 0.25 * y * (1 + xi * x) * (xi * x + 2 * eta * y);
  }
  // mid-sides: edge 0 (eta = -1), 1 (xi = 1), 2 (eta = 1), 3 (xi = -1)
  dN(0, 4) = -xi * (1 - eta), dN(1, 4) = -0.5 * (1 - xi * xi);
  dN(0, 5) = 0.5 * (1 - eta * eta), dN(1, 5) = -eta * (1 + xi);
  dN(0, 6) = -xi * (1 + eta), dN(1, 6) = 0.5 * (1 - xi * xi);
  dN(0, 7) = -0.5 * (1 - eta * eta), dN(1, 7) = -eta * (1 - xi);
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();  // the corners' bilinear map (straight edges)
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d d(0.25 * xn[i] * (1 + eta * yn[i]), 0.25 * yn[i] * (1 + xi * xn[i]));
    J += d * p[static_cast<std::size_t>(i)].transpose();
  }
  det = J.determinant();
  return J.inverse() * dN;
}

template <>
Eigen::Matrix<double, 2, 6> quadratic_derivatives<3>(const std::array<Eigen::Vector2d, 3>& p, double L2, double L3, double& det) {
  const double L[3] = {1 - L2 - L3, L2, L3};
  Eigen::Matrix2d Jt;  // x = sum L_i p_i: rows d(x, y)/dL2, d(x, y)/dL3
  Jt.row(0) = (p[1] - p[0]).transpose();
  Jt.row(1) = (p[2] - p[0]).transpose();
  det = Jt.determinant();
  const Eigen::Matrix2d Ji = Jt.inverse();
  Eigen::Matrix<double, 2, 3> dL;  // Cartesian derivatives of L1, L2, L3
  dL.col(1) = Ji.col(0);
  dL.col(2) = Ji.col(1);
  dL.col(0) = -dL.col(1) - dL.col(2);
  Eigen::Matrix<double, 2, 6> dN;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    dN.col(i) = (4 * L[i] - 1) * dL.col(i);
    dN.col(3 + i) = 4 * (L[i] * dL.col(j) + L[j] * dL.col(i));
  }
  return dN;
}

/// Strain rows (3 x 4N on the quadratic element's u, v) from shape derivatives.
template <int N>
Eigen::Matrix<double, 3, 4 * N> strain_rows(const Eigen::Matrix<double, 2, 2 * N>& dN) {
  Eigen::Matrix<double, 3, 4 * N> B = Eigen::Matrix<double, 3, 4 * N>::Zero();
  for (int k = 0; k < 2 * N; ++k) {
    B(0, 2 * k) = dN(0, k);
    B(1, 2 * k + 1) = dN(1, k);
    B(2, 2 * k) = dN(1, k);
    B(2, 2 * k + 1) = dN(0, k);
  }
  return B;
}

template <int N>
Eigen::Matrix<double, 1, 3 * N> defect(const std::array<Eigen::Vector2d, N>& p, double a, double b) {
  double det = 0;
  const Eigen::Matrix<double, 2, 2 * N> dN = quadratic_derivatives<N>(p, a, b, det);
  Eigen::Matrix<double, 1, 4 * N> omega = Eigen::Matrix<double, 1, 4 * N>::Zero();  // (v,x - u,y)/2
  for (int k = 0; k < 2 * N; ++k) {
    omega(2 * k + 1) = 0.5 * dN(0, k);
    omega(2 * k) = -0.5 * dN(1, k);
  }
  Eigen::Matrix<double, 1, 3 * N> d = -omega * allman_map<N>(p);
  for (int i = 0; i < N; ++i) d(3 * i + 2) += 1.0 / N;
  return d;
}

}  // namespace

std::vector<DrillingMembranePoint<4>> drilling_membrane_points(const std::array<Eigen::Vector2d, 4>& p) {
  const Eigen::Matrix<double, 16, 12> T = allman_map<4>(p);
  const double g = std::sqrt(0.6), x[3] = {-g, 0, g}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  std::vector<DrillingMembranePoint<4>> out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double det = 0;
      const Eigen::Matrix<double, 2, 8> dN = quadratic_derivatives<4>(p, x[i], x[j], det);
      out.push_back({strain_rows<4>(dN) * T, w[i] * w[j] * det, Eigen::Vector2d(x[i], x[j])});
    }
  return out;
}

std::vector<DrillingMembranePoint<3>> drilling_membrane_points(const std::array<Eigen::Vector2d, 3>& p) {
  const Eigen::Matrix<double, 12, 9> T = allman_map<3>(p);
  std::vector<DrillingMembranePoint<3>> out;
  for (const auto& [L2, L3] : {std::pair{0.5, 0.0}, std::pair{0.5, 0.5}, std::pair{0.0, 0.5}}) {
    double det = 0;
    const Eigen::Matrix<double, 2, 6> dN = quadratic_derivatives<3>(p, L2, L3, det);
    out.push_back({strain_rows<3>(dN) * T, det / 6.0, Eigen::Vector2d(L2, L3)});
  }
  return out;
}

Eigen::Matrix<double, 1, 12> drilling_membrane_defect(const std::array<Eigen::Vector2d, 4>& p) { return defect<4>(p, 0, 0); }
Eigen::Matrix<double, 1, 9> drilling_membrane_defect(const std::array<Eigen::Vector2d, 3>& p) {
  return defect<3>(p, 1.0 / 3, 1.0 / 3);
}

}  // namespace seflex::fem
