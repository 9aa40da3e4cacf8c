#pragma once
// What every force element acting on hinge angles returns (torsion spring, lock, cable loop,
// damper): generalised forces tau on the hinge angles it touches (positive tau drives +phi) and
// their derivatives, one characteristic scalar for output, and the potential energy it stores.
#include <Eigen/Core>
#include <vector>

#include "seflex/mbd/ids.hpp"

namespace seflex::mbd {

struct HingeForceResult {
  std::vector<HingeIndex> hinges;  ///< hinges acted on (a hinge may appear once only)
  Eigen::VectorXd tau;             ///< generalised force on each hinge angle [N m]
  Eigen::MatrixXd dtau_dphi;       ///< d tau_i / d phi_j
  Eigen::MatrixXd dtau_dphidot;    ///< d tau_i / d phidot_j
  double value = 0.0;              ///< spring/lock/damper: torque; cable loop: net cable force T1 - T2 [N]
  double energy = 0.0;             ///< stored potential energy [J] (0 for dampers)

  void resize(int n) {
    hinges.resize(n);
    tau = Eigen::VectorXd::Zero(n);
    dtau_dphi = Eigen::MatrixXd::Zero(n, n);
    dtau_dphidot = Eigen::MatrixXd::Zero(n, n);
    value = 0.0;
    energy = 0.0;
  }
};

/// Hinge angles and rates of all hinges (indexed by HingeIndex::value).
struct HingeValues {
  const Eigen::VectorXd& phi;
  const Eigen::VectorXd& phidot;
};

}  // namespace seflex::mbd
