#pragma once
// Checks shared by the Craig-Bampton tests: the identities of formulation.md test T1 (sections
// 1.2-1.3), asserted with GoogleTest.
#include <gtest/gtest.h>

#include <string>

#include "seflex/common/so3.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"
#include "seflex/superelement/superelement.hpp"

namespace seflex::cbtest {

using so3::skew;


inline double max_abs(const Eigen::MatrixXd& A) { return A.cwiseAbs().maxCoeff(); }

/// Psi Phi_rig0 = Phi_rig^FE (every grid), Phi_f Phi_rig0 = I6, K_el Phi_rig0 = 0 and the block sums
/// of section 1.3, each to 1e-10 (relative to the matrices' largest entries).
inline void expect_t1_identities(const se::Superelement& s, const std::string& label) {
  const int N = s.num_interfaces();
  const Eigen::MatrixXd R0 = reduction::interface_rigid_modes(s);
  const auto nfe = static_cast<Eigen::Index>(s.fe_node_ids.size());
  Eigen::MatrixXd R_fe = Eigen::MatrixXd::Zero(6 * nfe, 6);
  for (Eigen::Index i = 0; i < nfe; ++i) {
    R_fe.block<6, 6>(6 * i, 0).setIdentity();
    R_fe.block<3, 3>(6 * i, 3) = -skew(s.p_BoI_B.col(i));
  }
  EXPECT_LT(max_abs(s.recovery.leftCols(6 * N) * R0 - R_fe), 1e-10 * max_abs(R_fe)) << label;
  const Eigen::MatrixXd A = s.Phi_f.leftCols(6 * N);
  EXPECT_LT(max_abs(A * R0 - Eigen::MatrixXd::Identity(6, 6)), 1e-10) << label;
  const Eigen::MatrixXd K_el = s.K.topLeftCorner(6 * N, 6 * N);
  EXPECT_LT(max_abs(K_el * R0), 1e-10 * max_abs(K_el) * max_abs(R0)) << label;
  Eigen::Matrix3d uu = Eigen::Matrix3d::Zero(), tu = uu, ut = uu, tt = uu;
  for (int j = 0; j < N; ++j) {
    const Eigen::Matrix<double, 6, 6> Aj = A.block<6, 6>(0, 6 * j);
    const Eigen::Matrix3d x = skew(s.interfaces[static_cast<std::size_t>(j)].p_BoN_B);
    uu += Aj.topLeftCorner<3, 3>();
    tu += Aj.bottomLeftCorner<3, 3>();
    ut += Aj.topRightCorner<3, 3>() - Aj.topLeftCorner<3, 3>() * x;
    tt += Aj.bottomRightCorner<3, 3>() - Aj.bottomLeftCorner<3, 3>() * x;
  }
  EXPECT_LT(max_abs(uu - Eigen::Matrix3d::Identity()), 1e-10) << label << ": sum A_uu = I";
  EXPECT_LT(max_abs(tu), 1e-10) << label << ": sum A_theta_u = 0";
  EXPECT_LT(max_abs(ut), 1e-10) << label << ": sum (A_u_theta - A_uu x~) = 0";
  EXPECT_LT(max_abs(tt - Eigen::Matrix3d::Identity()), 1e-10) << label << ": sum (A_theta_theta - A_theta_u x~) = I";
}

}  // namespace seflex::cbtest
