// MIN3 plate triangle (see element_plate_min3.hpp for the formulation and reference).
#include "seflex/fem/element_plate_min3.hpp"

#include "seflex/common/error.hpp"

namespace seflex::fem {
namespace {

using Row9 = Eigen::Matrix<double, 1, 9>;
constexpr int kW = 0, kRx = 1, kRy = 2;

struct Triangle {
  double area = 0;
  std::array<Eigen::Vector2d, 3> grad;      // grad L_i
  Eigen::Matrix<double, 3, 9> bubble;       // c_k (edge k from corner k to k+1) on the dofs
};

Triangle triangle(const std::array<Eigen::Vector2d, 3>& p) {
  Triangle t;
  const Eigen::Vector2d a = p[1] - p[0], b = p[2] - p[0];
  const double twice = a.x() * b.y() - a.y() * b.x();
  SEFLEX_DEMAND(twice > 0.0, "MIN3 triangle with zero area or clockwise corners");
  t.area = 0.5 * twice;
  t.bubble.setZero();
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    t.grad[i] = Eigen::Vector2d(p[j].y() - p[k].y(), p[k].x() - p[j].x()) / twice;
    // c = (beta_j - beta_i) . d / 8, beta = (theta_y, -theta_x), d = p_j - p_i
    const Eigen::Vector2d d = (p[j] - p[i]) / 8.0;
    t.bubble(i, 3 * j + kRy) += d.x();
    t.bubble(i, 3 * i + kRy) -= d.x();
    t.bubble(i, 3 * j + kRx) -= d.y();
    t.bubble(i, 3 * i + kRx) += d.y();
  }
  return t;
}

// Transverse shear strain (gamma_xz, gamma_yz) = grad w + beta at area coordinates L.
Eigen::Matrix<double, 2, 9> shear_rows(const Triangle& t, const Eigen::Vector3d& L) {
  Eigen::Matrix<double, 2, 9> B = Eigen::Matrix<double, 2, 9>::Zero();
  for (int i = 0; i < 3; ++i) {
    B.col(3 * i + kW) += t.grad[i];
    B(0, 3 * i + kRy) += L[i];
    B(1, 3 * i + kRx) -= L[i];
  }
  for (int e = 0; e < 3; ++e) {  // grad (4 L_i L_j) c_e, edge e = (i, j)
    const int i = e, j = (e + 1) % 3;
    const Eigen::Vector2d g = 4.0 * (L[j] * t.grad[i] + L[i] * t.grad[j]);
    B += g * t.bubble.row(e);
  }
  return B;
}

}  // namespace

PlateMatrix3 min3_stiffness(const std::array<Eigen::Vector2d, 3>& p, const Eigen::Matrix3d& D, const Eigen::Matrix2d& S,
                            double cb) {
  const Triangle t = triangle(p);
  Eigen::Matrix<double, 3, 9> Bb = Eigen::Matrix<double, 3, 9>::Zero();
  for (int i = 0; i < 3; ++i) {
    Bb(0, 3 * i + kRy) = t.grad[i].x();
    Bb(1, 3 * i + kRx) = -t.grad[i].y();
    Bb(2, 3 * i + kRy) = t.grad[i].y();
    Bb(2, 3 * i + kRx) = -t.grad[i].x();
  }
  const PlateMatrix3 Kb = t.area * Bb.transpose() * D * Bb;
  PlateMatrix3 Ks = PlateMatrix3::Zero();
  for (int e = 0; e < 3; ++e) {  // edge midpoints, weight A/3: exact for the quadratic integrand
    Eigen::Vector3d L = Eigen::Vector3d::Constant(0.5);
    L[(e + 2) % 3] = 0.0;
    const Eigen::Matrix<double, 2, 9> Bs = shear_rows(t, L);
    Ks.noalias() += (t.area / 3.0) * Bs.transpose() * S * Bs;
  }
  double bending = 0, shear = 0;  // sums of the rotation diagonals
  for (int i = 0; i < 3; ++i)
    for (const int r : {kRx, kRy}) {
      bending += Kb(3 * i + r, 3 * i + r);
      shear += Ks(3 * i + r, 3 * i + r);
    }
  const double psi = shear > 0.0 ? bending / shear : 0.0;
  const double phi2 = cb * psi / (1.0 + cb * psi);
  PlateMatrix3 K = Kb + phi2 * Ks;
  return 0.5 * (K + K.transpose());
}

PlateVector3 min3_pressure_load(const std::array<Eigen::Vector2d, 3>& p, double q) {
  const Triangle t = triangle(p);
  // int L_i dA = A / 3, int 4 L_i L_j dA = A / 3
  PlateVector3 f = (q * t.area / 3.0) * (t.bubble.row(0) + t.bubble.row(1) + t.bubble.row(2)).transpose();
  for (int i = 0; i < 3; ++i) f[3 * i + kW] += q * t.area / 3.0;
  return f;
}

}  // namespace seflex::fem
