#pragma once
// Torsion spring on one hinge angle (solar-array.md "Hinge springs and locks"):
//   linear:  tau(phi) = tau0 + (tau1 - tau0) phi / phi_ref          (tau1 = torque at phi_ref)
//   table:   tau(phi) piecewise linear through (table_phi[i], table_tau[i]); phi strictly increasing;
//            outside the table the end segments are extended linearly.
// Energy V(phi) = -integral_0^phi tau, so that V + kinetic energy is conserved without damping.
#include <vector>

#include "seflex/mbd/forces/hinge_force.hpp"

namespace seflex::mbd {

struct TorsionSpring {
  HingeIndex hinge;
  double tau0 = 0.0;
  double tau1 = 0.0;
  double phi_ref = 1.0;            ///< [rad], nonzero
  std::vector<double> table_phi;   ///< if non-empty, the table replaces the linear law
  std::vector<double> table_tau;
};

/// Throws InputError (naming `name`) when the table is malformed or phi_ref is zero.
void validate(const TorsionSpring& s, const std::string& name);
double torque(const TorsionSpring& s, double phi);
double stiffness(const TorsionSpring& s, double phi);  ///< d tau / d phi
double energy(const TorsionSpring& s, double phi);
void evaluate(const TorsionSpring& s, const HingeValues& h, HingeForceResult& r);  // r resized and overwritten (no allocation once sized)

}  // namespace seflex::mbd
