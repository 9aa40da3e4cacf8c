#pragma once
// The membrane of CQUADR and CTRIAR (MSC's shells with drilling stiffness): Allman-type membranes
// whose drilling rotations theta_z enter the in-plane displacement field.
//
// - CTRIAR: Allman's triangle (D. J. Allman, "A compatible triangular element including vertex
//   rotations for plane elasticity analysis", Comput. Struct. 19 (1984) 1-8): the six-node
//   quadratic triangle whose mid-side displacements are those of the edge bent by its end rotations,
//     u_k = (u_i + u_j)/2 + (L/8) (theta_j - theta_i) n_ij,
//   n_ij the outward unit normal of edge i -> j (corners counterclockwise), L its length.
// - CQUADR: the same construction on the eight-node serendipity quadrilateral (Ibrahimbegovic,
//   Taylor & Wilson, "A robust quadrilateral membrane finite element with drilling degrees of
//   freedom", IJNME 30 (1990) 445-457), straight edges.
// Both have one spurious zero-energy mode (equal corner rotations, no translation); the Hughes-Brezzi
// term gamma A (mean(theta) - omega)^2 at the centre (gamma = G t, omega = (v,x - u,y)/2 of the
// element's field: Hughes & Brezzi, CMAME 72 (1989) 105-121) removes it and keeps rigid rotations
// and constant-strain states (theta = omega) free of energy, so both pass the patch test.
//
// Dofs: (u, v, theta_z) of each corner in the element plane, 3 per corner; positions p (2-D,
// counterclockwise).
#include <Eigen/Core>
#include <array>
#include <vector>

namespace seflex::fem {

/// A point of a drilling membrane's integration rule: the membrane strain (xx, yy, xy engineering)
/// rows over the corner dofs, and the weight (area) of the point.
template <int N>
struct DrillingMembranePoint {
  Eigen::Matrix<double, 3, 3 * N> B;
  double weight = 0;
  Eigen::Vector2d xi;  ///< natural coordinates (quadrilateral: xi, eta; triangle: L2, L3)
};

/// CQUADR: the 3 x 3 Gauss points of the Allman-type quadrilateral.
std::vector<DrillingMembranePoint<4>> drilling_membrane_points(const std::array<Eigen::Vector2d, 4>& p);
/// CTRIAR: the 3 points (edge midpoints) of Allman's triangle, exact for its linear strain.
std::vector<DrillingMembranePoint<3>> drilling_membrane_points(const std::array<Eigen::Vector2d, 3>& p);

/// The Hughes-Brezzi row mean(theta) - omega at the element centre, over the corner dofs.
Eigen::Matrix<double, 1, 12> drilling_membrane_defect(const std::array<Eigen::Vector2d, 4>& p);
Eigen::Matrix<double, 1, 9> drilling_membrane_defect(const std::array<Eigen::Vector2d, 3>& p);

/// The membrane stiffness on the corner dofs (u, v, theta_z) x N: sum_points w B^T A B +
/// gamma area d^T d (d the defect row), gamma the in-plane shear stiffness G t.
template <int N>
Eigen::Matrix<double, 3 * N, 3 * N> drilling_membrane_stiffness(const std::array<Eigen::Vector2d, N>& p, const Eigen::Matrix3d& A,
                                                                double gamma) {
  Eigen::Matrix<double, 3 * N, 3 * N> K = Eigen::Matrix<double, 3 * N, 3 * N>::Zero();
  double area = 0;
  for (const auto& q : drilling_membrane_points(p)) {
    K.noalias() += q.weight * q.B.transpose() * A * q.B;
    area += q.weight;
  }
  const Eigen::Matrix<double, 1, 3 * N> d = drilling_membrane_defect(p);
  K.noalias() += (gamma * area) * d.transpose() * d;
  return K;
}

}  // namespace seflex::fem
