#pragma once
// Classical lamination theory written out from the textbook for the fem tests (independent of
// seflex's section code): Kaw, Mechanics of Composite Materials, 2nd ed. (2006), ch. 2 (Q of an
// orthotropic lamina, Q-bar of an angle lamina) and ch. 4 (A, B, D); T300/5208 graphite/epoxy from
// Kaw's Table 2.1.
#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "seflex/fem/model.hpp"

namespace seflex::fem::test::clt {

const double kPi = 3.14159265358979323846;

// T300/5208 (Kaw Table 2.1), SI.
inline const double kE1 = 181e9, kE2 = 10.3e9, kNu12 = 0.28, kG12 = 7.17e9;
inline const double kPly = 0.125e-3;  // ply thickness (m)

inline Mat8 t300(double g1z = 0.0, double g2z = 0.0, double rho = 1600.0) {
  Mat8 m;
  m.id = 8;
  m.E1 = kE1;
  m.E2 = kE2;
  m.nu12 = kNu12;
  m.G12 = kG12;
  m.G1z = g1z;
  m.G2z = g2z;
  m.rho = rho;
  return m;
}

// Kaw ch. 2: Q11 = E1/(1 - nu12 nu21), Q12 = nu12 E2/(1 - nu12 nu21), Q22 = E2/(1 - nu12 nu21), Q66 = G12.
struct Q4 {
  double Q11, Q12, Q22, Q66;
};
inline Q4 lamina_Q() {
  const double nu21 = kNu12 * kE2 / kE1, d = 1 - kNu12 * nu21;
  return {kE1 / d, kNu12 * kE2 / d, kE2 / d, kG12};
}

// Kaw ch. 2, Q-bar of an angle lamina (theta in degrees, from x to the fibre, counterclockwise).
inline Eigen::Matrix3d Qbar(double theta_deg) {
  const Q4 q = lamina_Q();
  const double c = std::cos(theta_deg * kPi / 180), s = std::sin(theta_deg * kPi / 180);
  const double c2 = c * c, s2 = s * s, c4 = c2 * c2, s4 = s2 * s2;
  const double Q11 = q.Q11 * c4 + q.Q22 * s4 + 2 * (q.Q12 + 2 * q.Q66) * s2 * c2;
  const double Q12 = (q.Q11 + q.Q22 - 4 * q.Q66) * s2 * c2 + q.Q12 * (c4 + s4);
  const double Q22 = q.Q11 * s4 + q.Q22 * c4 + 2 * (q.Q12 + 2 * q.Q66) * s2 * c2;
  const double Q16 = (q.Q11 - q.Q12 - 2 * q.Q66) * c2 * c * s - (q.Q22 - q.Q12 - 2 * q.Q66) * s2 * s * c;
  const double Q26 = (q.Q11 - q.Q12 - 2 * q.Q66) * c * s2 * s - (q.Q22 - q.Q12 - 2 * q.Q66) * c2 * c * s;
  const double Q66 = (q.Q11 + q.Q22 - 2 * q.Q12 - 2 * q.Q66) * s2 * c2 + q.Q66 * (s4 + c4);
  Eigen::Matrix3d Q;
  Q << Q11, Q12, Q16, Q12, Q22, Q26, Q16, Q26, Q66;
  return Q;
}

struct Abd {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero(), B = Eigen::Matrix3d::Zero(), D = Eigen::Matrix3d::Zero();
};
// Kaw ch. 4: A, B, D as sums over the plies, bottom up, equal thickness, the stack centred on z = 0.
inline Abd hand_abd(const std::vector<double>& angles_deg, double t = kPly) {
  Abd r;
  const double h = t * angles_deg.size();
  double z = -h / 2;
  for (double a : angles_deg) {
    const Eigen::Matrix3d Q = Qbar(a);
    r.A += Q * t;
    r.B += Q * ((z + t) * (z + t) - z * z) / 2;
    r.D += Q * ((z + t) * (z + t) * (z + t) - z * z * z) / 3;
    z += t;
  }
  return r;
}

}  // namespace seflex::fem::test::clt
