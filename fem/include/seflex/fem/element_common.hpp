#pragma once
// What every structural element shares: the mass convention, the 6-dof node ordering, rigid links
// and rotations of node blocks.
//
// Every element exposes its stiffness and mass as fixed-size 6N x 6N matrices on the dofs of its N
// nodes, node after node, each node (T1 T2 T3 R1 R2 R3) in the BASIC system. Assembly rotates the
// node blocks to each grid's displacement (CD) system.
#include <Eigen/Core>
#include <array>

#include "seflex/common/so3.hpp"

namespace seflex::fem {

/// Nastran's default lumped mass or, with PARAM COUPMASS > 0, the coupled (consistent) mass.
enum class MassKind : unsigned char { Lumped, Coupled };

/// PARAM QUAD4TYP MIN4T: MYSTRAN's plate bending + transverse shear elements instead of MITC4/MITC3
/// (CQUAD4: MIN4T, element_plate_min4t.hpp; CTRIA3: MIN3, element_plate_min3.hpp), with their shear
/// factors (assembly.hpp: mystran_plate).
struct MystranPlate {
  double cb_tria = 2.0;  ///< CTRIA3 (MIN3): PARAM CBMIN3
  double cb_quad = 3.6;  ///< the four MIN3 sub-triangles of CQUAD4 (MIN4T): PARAM CBMIN4T
};

using Matrix6 = Eigen::Matrix<double, 6, 6>;
template <int N>
using NodeMatrix = Eigen::Matrix<double, 6 * N, 6 * N>;  ///< element matrix on N nodes x 6 dofs

/// A plate load (w, theta_x, theta_y per corner, element axes) as grid loads (6 per corner, basic):
/// w along e3, the moments in the e1-e2 plane; R_BL has the element axes e1 e2 e3 as columns.
template <int N>
Eigen::Matrix<double, 6 * N, 1> plate_load_to_basic(const Eigen::Matrix3d& R_BL, const Eigen::Matrix<double, 3 * N, 1>& f) {
  Eigen::Matrix<double, 6 * N, 1> r;
  for (int i = 0; i < N; ++i) {
    r.template segment<3>(6 * i) = f[3 * i] * R_BL.col(2);
    r.template segment<3>(6 * i + 3) = R_BL.template leftCols<2>() * Eigen::Vector2d(f[3 * i + 1], f[3 * i + 2]);
  }
  return r;
}

/// Rigid link: dofs of a point P from the dofs of node O with d = p_P - p_O (any common frame):
/// u_P = u_O + theta_O x d, theta_P = theta_O, i.e. q_P = rigid_link(d) q_O.
inline Matrix6 rigid_link(const Eigen::Vector3d& d) {
  Matrix6 T = Matrix6::Identity();
  T.block<3, 3>(0, 3) = -so3::skew(d);
  return T;
}

/// K <- T^T K T with T = blockdiag(R_LB, ..., R_LB) (2N blocks), R_LB = R_BL^T: turns a matrix on
/// node dofs in local axes L into one on dofs in basic B. R_BL has the local axes as columns.
template <int N>
void rotate_local_to_basic(const Eigen::Matrix3d& R_BL, NodeMatrix<N>& K) {
  if (R_BL == Eigen::Matrix3d::Identity()) return;  // local axes are the basic ones (exactly)
  for (int j = 0; j < 2 * N; ++j)
    for (int i = 0; i < 2 * N; ++i) {
      const Eigen::Matrix3d b = R_BL * K.template block<3, 3>(3 * i, 3 * j) * R_BL.transpose();
      K.template block<3, 3>(3 * i, 3 * j) = b;
    }
}

/// K <- T^T K T for per-node rigid links, T = blockdiag(rigid_link(d_1), ..., rigid_link(d_N)):
/// K given on the dofs of points P_n = O_n + d_n becomes K on the dofs of nodes O_n.
template <int N>
void apply_node_offsets(const std::array<Eigen::Vector3d, N>& d, NodeMatrix<N>& K) {
  for (int n = 0; n < N; ++n) {
    if (d[n].squaredNorm() == 0.0) continue;
    const Eigen::Matrix3d S = so3::skew(d[n]);
    // columns: K(:, rot_n) -= K(:, trans_n) * S ; then rows: K(rot_n, :) -= S^T K(trans_n, :)
    K.template middleCols<3>(6 * n + 3) -= K.template middleCols<3>(6 * n) * S;
    K.template middleRows<3>(6 * n + 3) -= S.transpose() * K.template middleRows<3>(6 * n);
  }
}

/// Rigid-body modes of N nodes at basic positions x about the point `ref` (6N x 6): column k is the
/// node motion for a unit translation (k < 3) or unit rotation (k >= 3) about basic axis k mod 3.
template <int N>
Eigen::Matrix<double, 6 * N, 6> rigid_body_modes(const std::array<Eigen::Vector3d, N>& x,
                                                 const Eigen::Vector3d& ref = Eigen::Vector3d::Zero()) {
  Eigen::Matrix<double, 6 * N, 6> D = Eigen::Matrix<double, 6 * N, 6>::Zero();
  for (int n = 0; n < N; ++n) D.template block<6, 6>(6 * n, 0) = rigid_link(x[n] - ref);
  return D;
}

}  // namespace seflex::fem
