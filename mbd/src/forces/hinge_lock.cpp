#include "seflex/mbd/forces/hinge_lock.hpp"

#include <cmath>

#include "seflex/common/error.hpp"

namespace seflex::mbd {

void validate(const HingeLock& l, const std::string& name) {
  if (!(l.k_lock > 0.0) || !std::isfinite(l.k_lock))
    throw InputError("lock '" + name + "': lock stiffness must be a positive number (N m/rad)");
  if (!(l.c_lock >= 0.0) || !std::isfinite(l.c_lock))
    throw InputError("lock '" + name + "': lock damping must be a non-negative number (N m s/rad)");
  if (!std::isfinite(l.phi_lock)) throw InputError("lock '" + name + "': lock angle must be a finite number");
}

void evaluate(const HingeLock& l, const HingeValues& h, bool latched, HingeForceResult& r) {
  r.resize(1);
  r.hinges[0] = l.hinge;
  if (!latched) return;
  const double d = h.phi[l.hinge.value] - l.phi_lock;
  r.tau[0] = -l.k_lock * d - l.c_lock * h.phidot[l.hinge.value];
  r.dtau_dphi(0, 0) = -l.k_lock;
  r.dtau_dphidot(0, 0) = -l.c_lock;
  r.value = r.tau[0];
  r.energy = 0.5 * l.k_lock * d * d;
}

}  // namespace seflex::mbd
