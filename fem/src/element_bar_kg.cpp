// CBAR / CBEAM differential stiffness and axial force (see element_bar.hpp).
#include <Eigen/Cholesky>
#include <vector>

#include "seflex/common/error.hpp"
#include "seflex/fem/components.hpp"
#include "seflex/fem/element_bar.hpp"

namespace seflex::fem {
namespace {

using Matrix12 = NodeMatrix<2>;
using Vector12 = Eigen::Matrix<double, 12, 1>;

// T (12 x 12, element axes) with u = T u: the released (pinned) dofs follow the retained ones by
// the elastic static condensation u_p = -K_pp^-1 K_pr u_r; identity when nothing is released.
Matrix12 pin_transform(const BarElement& e, const Matrix12& K) {
  Matrix12 T = Matrix12::Identity();
  std::vector<int> p, r;
  for (int i = 0; i < 12; ++i) (has_component(i < 6 ? e.pin_A : e.pin_B, i % 6 + 1) ? p : r).push_back(i);
  if (p.empty()) return T;
  const int np = static_cast<int>(p.size()), nr = static_cast<int>(r.size());
  Eigen::MatrixXd Kpp(np, np), Kpr(np, nr);
  for (int i = 0; i < np; ++i) {
    for (int j = 0; j < np; ++j) Kpp(i, j) = K(p[i], p[j]);
    for (int j = 0; j < nr; ++j) Kpr(i, j) = K(p[i], r[j]);
  }
  const Eigen::LLT<Eigen::MatrixXd> llt(Kpp);
  SEFLEX_DEMAND(llt.info() == Eigen::Success, "bar pin flags release dofs without stiffness");
  const Eigen::MatrixXd G = -llt.solve(Kpr);
  T.setZero();
  for (int i = 0; i < nr; ++i) T(r[i], r[i]) = 1.0;
  for (int i = 0; i < np; ++i)
    for (int j = 0; j < nr; ++j) T(p[i], r[j]) = G(i, j);
  return T;
}

// Grid displacements (basic) -> bar-end displacements in element axes.
Vector12 end_displacements(const BarElement& e, const Eigen::Matrix3d& R_BE, const Vector12& u_basic) {
  Vector12 q;
  const std::array<Eigen::Vector3d, 2> w = {e.w_A, e.w_B};
  for (int n = 0; n < 2; ++n) {
    const Eigen::Matrix<double, 6, 1> end = rigid_link(w[n]) * u_basic.segment<6>(6 * n);
    q.segment<3>(6 * n) = R_BE.transpose() * end.head<3>();
    q.segment<3>(6 * n + 3) = R_BE.transpose() * end.tail<3>();
  }
  return q;
}

}  // namespace

Vector12 bar_end_forces(const BarElement& e, const Vector12& u_basic) {
  const Matrix12 K = bar_stiffness_element_axes(e);
  const Matrix12 T = pin_transform(e, K);
  const Vector12 q = end_displacements(e, bar_axes(e), u_basic);
  return T.transpose() * (K * (T * q));
}

double bar_axial_force(const BarElement& e, const Vector12& u_basic) {
  return bar_end_forces(e, u_basic)(6);  // x force on end B: tension positive
}

NodeMatrix<2> bar_geometric_stiffness(const BarElement& e, double N) {
  const double L = bar_length(e);
  SEFLEX_DEMAND(L > 0.0, "bar of zero length");
  Matrix12 G = Matrix12::Zero();
  auto add2 = [&](int a, int b, double k) {
    G(a, a) += k;
    G(b, b) += k;
    G(a, b) -= k;
    G(b, a) -= k;
  };
  add2(0, 6, N / L);  // axial: u_B - u_A
  const BarSection& s = e.section;
  if (s.A > 0.0) add2(3, 9, N * (s.I1 + s.I2) / (s.A * L));  // torsion (Wagner term of a doubly symmetric section)
  Eigen::Matrix4d H;  // cubic Hermite, dofs (v_A, theta_A, v_B, theta_B) with theta = v'
  H << 36, 3 * L, -36, 3 * L, 3 * L, 4 * L * L, -3 * L, -L * L, -36, -3 * L, 36, -3 * L, 3 * L, -L * L, -3 * L,
      4 * L * L;
  H *= N / (30.0 * L);
  const int p1[4] = {1, 5, 7, 11};  // v, theta_z: theta_z = v'
  const int p2[4] = {2, 4, 8, 10};  // w, theta_y: theta_y = -w'
  const double sgn[4] = {1, -1, 1, -1};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      G(p1[i], p1[j]) += H(i, j);
      G(p2[i], p2[j]) += sgn[i] * sgn[j] * H(i, j);
    }
  if (e.pin_A || e.pin_B) {
    const Matrix12 T = pin_transform(e, bar_stiffness_element_axes(e));
    G = (T.transpose() * G * T).eval();
  }
  rotate_local_to_basic<2>(bar_axes(e), G);
  apply_node_offsets<2>({e.w_A, e.w_B}, G);
  return G;
}

}  // namespace seflex::fem
