#pragma once
// Inertia wrench of a rigid body about a reference point o (internal; shared by the AIC rigid body
// and the floating-frame rigid kernel):
//   F_t = m (a_o + alpha x c + w x (w x c)),  F_r = I alpha + w x I w + c x F_t   (moment about o)
//   M6 = [[m, -m c~], [m c~, I - m c~ c~]],    kinetic = 1/2 m |v_o + w x c|^2 + 1/2 w . I w
// with c the vector o -> centre of mass and I the inertia about the centre of mass (world axes);
// gravity enters as a_o - g.
#include <Eigen/Core>

#include "seflex/common/so3.hpp"

namespace seflex::mbd::detail {

struct RigidWrench {
  Eigen::Matrix<double, 6, 1> F;
  Eigen::Matrix<double, 6, 6> M6;
  double kinetic = 0.0;
};

inline RigidWrench rigid_wrench(double m, const Eigen::Vector3d& c, const Eigen::Matrix3d& I, const Eigen::Vector3d& v_o,
                                const Eigen::Vector3d& w, const Eigen::Vector3d& a_o, const Eigen::Vector3d& alpha) {
  RigidWrench out;
  const Eigen::Vector3d acm = a_o + alpha.cross(c) + w.cross(w.cross(c));
  out.F.head<3>() = m * acm;
  out.F.tail<3>() = I * alpha + w.cross(I * w) + c.cross(out.F.head<3>());
  const Eigen::Matrix3d cx = so3::skew(c);
  out.M6 << m * Eigen::Matrix3d::Identity(), -m * cx, m * cx, I - m * cx * cx;
  out.kinetic = 0.5 * m * (v_o + w.cross(c)).squaredNorm() + 0.5 * w.dot(I * w);
  return out;
}

}  // namespace seflex::mbd::detail
