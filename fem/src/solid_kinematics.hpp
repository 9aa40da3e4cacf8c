#pragma once
// Internal: strain-displacement matrices of the isoparametric solids (element_solid.hpp), shared by
// the stiffness (element_solid.cpp) and the thermal load (element_solid_thermal.cpp).
// Voigt order xx yy zz xy yz zx, engineering shear strains.
#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "seflex/fem/element_solid.hpp"
#include "solid_shapes.hpp"

namespace seflex::fem::detail {

/// Shape values, x-gradients (rows a: dN_a/dx) and det J at natural point xi.
struct SolidPointData {
  ShapeValues s;
  Eigen::Matrix<double, kMaxSolidNodes, 3> dNdx;
  double detJ = 0;
  Eigen::Matrix3d J;  ///< J(i, j) = dx_i / dxi_j
};

inline void evaluate(const SolidElement& e, const Eigen::Vector3d& xi, SolidPointData& p) {
  solid_shape(e.shape, e.nnode, e.missing_mid, xi, p.s);
  p.J.setZero();
  for (int a = 0; a < e.nnode; ++a)
    for (int j = 0; j < 3; ++j) p.J.col(j) += p.s.dN[a][j] * e.x[static_cast<std::size_t>(a)];
  p.detJ = p.J.determinant();
  const Eigen::Matrix3d Jit = p.J.inverse().transpose();
  for (int a = 0; a < e.nnode; ++a)
    p.dNdx.row(a) = (Jit * Eigen::Vector3d(p.s.dN[a][0], p.s.dN[a][1], p.s.dN[a][2])).transpose();
}

/// Strain-displacement columns of one displacement gradient g (3 columns: u, v, w).
inline void strain_columns(const Eigen::Vector3d& g, Eigen::Ref<Eigen::Matrix<double, 6, 3>> B) {
  B.setZero();
  B(0, 0) = g[0];
  B(1, 1) = g[1];
  B(2, 2) = g[2];
  B(3, 0) = g[1], B(3, 1) = g[0];
  B(4, 1) = g[2], B(4, 2) = g[1];
  B(5, 0) = g[2], B(5, 2) = g[0];
}

/// B (6 x 3N) at a point.
inline Eigen::MatrixXd strain_matrix(const SolidElement& e, const SolidPointData& p) {
  Eigen::MatrixXd B(6, 3 * e.nnode);
  for (int a = 0; a < e.nnode; ++a) {
    Eigen::Matrix<double, 6, 3> b;
    strain_columns(p.dNdx.row(a).transpose(), b);
    B.middleCols<3>(3 * a) = b;
  }
  return B;
}

/// Centre Jacobian data of the CHEXA 8 bubble modes (IncompatibleModes).
struct BubbleCentre {
  Eigen::Matrix3d J0it = Eigen::Matrix3d::Identity();
  double detJ0 = 0;
};
inline BubbleCentre bubble_centre(const SolidElement& e) {
  SolidPointData c;
  evaluate(e, Eigen::Vector3d::Zero(), c);
  return {c.J.inverse().transpose(), c.detJ};
}

/// Strains (6 x 9) of the bubble modes P_k = 1 - xi_k^2 (k = 0..2) for each component at natural
/// point xi; gradient with the centre Jacobian, scaled by det J0 / det J so that int Bi dV = 0 (the
/// constant-strain patch test on any shape).
inline Eigen::Matrix<double, 6, 9> bubble_strain_matrix(const BubbleCentre& c, const Eigen::Vector3d& xi, double detJ) {
  Eigen::Matrix<double, 6, 9> Bi;
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d dP = Eigen::Vector3d::Zero();
    dP[k] = -2 * xi[k];
    const Eigen::Vector3d g = (c.detJ0 / detJ) * (c.J0it * dP);
    strain_columns(g, Bi.middleCols<3>(3 * k));
  }
  return Bi;
}

/// CHEXA 8 reduced shear integration (PSOLID IN = TWO, ISOP blank or REDUCED), on the 2 x 2 x 2 Gauss
/// points `B` (6 x 24 each) with their det J: each shear strain row is replaced by its det J weighted
/// average over the four points of the natural plane it acts in, separately for the two layers of
/// points across that plane: gamma_xy over (xi1, xi2) at each xi3, gamma_yz over (xi2, xi3) at each
/// xi1, gamma_zx over (xi3, xi1) at each xi2. The selective substitution of MYSTRAN's HEXA8
/// (MYSTRAN Source/EMG/EMG5/HEXA.f90, RED_INT_SHEAR with IORD = 2): one point in the plane of the
/// shear, so a rectangular brick has no shear locking in bending; the direct strains stay fully
/// integrated, so there is no spurious zero-energy mode.
inline void reduce_shear_rows(const std::vector<QuadraturePoint>& q, const std::vector<double>& detJ,
                              std::vector<Eigen::MatrixXd>& B) {
  const int across[3] = {2, 0, 1};  // row 3 (xy) layers by xi3, row 4 (yz) by xi1, row 5 (zx) by xi2
  for (int r = 0; r < 3; ++r) {
    const int row = 3 + r, k = across[r];
    for (const double side : {-1.0, 1.0}) {
      Eigen::RowVectorXd sum = Eigen::RowVectorXd::Zero(B.front().cols());
      double w = 0;
      for (std::size_t i = 0; i < q.size(); ++i)
        if (q[i].xi[k] * side > 0) {
          sum += detJ[i] * B[i].row(row);
          w += detJ[i];
        }
      for (std::size_t i = 0; i < q.size(); ++i)
        if (q[i].xi[k] * side > 0) B[i].row(row) = sum / w;
    }
  }
}

}  // namespace seflex::fem::detail
