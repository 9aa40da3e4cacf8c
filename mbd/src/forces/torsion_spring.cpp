#include "seflex/mbd/forces/torsion_spring.hpp"

#include <cmath>
#include <string>

#include "seflex/common/error.hpp"

namespace seflex::mbd {

void validate(const TorsionSpring& s, const std::string& name) {
  if (!s.table_phi.empty() || !s.table_tau.empty()) {
    if (s.table_phi.size() != s.table_tau.size() || s.table_phi.size() < 2)
      throw InputError("torsion spring '" + name + "': the torque table needs at least two (angle, torque) pairs of equal count");
    for (std::size_t i = 0; i < s.table_phi.size(); ++i) {
      if (!std::isfinite(s.table_phi[i]) || !std::isfinite(s.table_tau[i]))
        throw InputError("torsion spring '" + name + "': table entry " + std::to_string(i + 1) + " is not a finite number");
      if (i > 0 && !(s.table_phi[i] > s.table_phi[i - 1]))
        throw InputError("torsion spring '" + name + "': table angles must be strictly increasing (entry " + std::to_string(i + 1) + ")");
    }
    return;
  }
  if (!(std::abs(s.phi_ref) > 0.0) || !std::isfinite(s.phi_ref))
    throw InputError("torsion spring '" + name + "': reference angle must be a nonzero number");
  if (!std::isfinite(s.tau0) || !std::isfinite(s.tau1))
    throw InputError("torsion spring '" + name + "': torques must be finite numbers");
}

namespace {
// Segment index for phi (end segments extended).
std::size_t segment(const TorsionSpring& s, double phi) {
  std::size_t i = 0;
  while (i + 2 < s.table_phi.size() && phi > s.table_phi[i + 1]) ++i;
  return i;
}
double slope(const TorsionSpring& s, std::size_t i) {
  return (s.table_tau[i + 1] - s.table_tau[i]) / (s.table_phi[i + 1] - s.table_phi[i]);
}
double table_value(const TorsionSpring& s, double phi) {
  const std::size_t i = segment(s, phi);
  return s.table_tau[i] + slope(s, i) * (phi - s.table_phi[i]);
}
// Integral of the (extended) piecewise-linear table from a to b, a <= b: trapezoids between the
// interior breakpoints (exact, the function is linear in between).
double table_integral(const TorsionSpring& s, double a, double b) {
  double sum = 0.0, x = a;
  for (std::size_t i = 1; i + 1 < s.table_phi.size(); ++i) {
    const double bp = s.table_phi[i];
    if (bp <= x) continue;
    if (bp >= b) break;
    sum += 0.5 * (table_value(s, x) + table_value(s, bp)) * (bp - x);
    x = bp;
  }
  return sum + 0.5 * (table_value(s, x) + table_value(s, b)) * (b - x);
}
}  // namespace

double torque(const TorsionSpring& s, double phi) {
  if (!s.table_phi.empty()) return table_value(s, phi);
  return s.tau0 + (s.tau1 - s.tau0) * phi / s.phi_ref;
}

double stiffness(const TorsionSpring& s, double phi) {
  if (!s.table_phi.empty()) return slope(s, segment(s, phi));
  return (s.tau1 - s.tau0) / s.phi_ref;
}

double energy(const TorsionSpring& s, double phi) {
  if (!s.table_phi.empty()) return phi >= 0 ? -table_integral(s, 0.0, phi) : table_integral(s, phi, 0.0);
  return -(s.tau0 * phi + 0.5 * (s.tau1 - s.tau0) * phi * phi / s.phi_ref);
}

void evaluate(const TorsionSpring& s, const HingeValues& h, HingeForceResult& r) {
  r.resize(1);
  r.hinges[0] = s.hinge;
  const double phi = h.phi[s.hinge.value];
  r.tau[0] = torque(s, phi);
  r.dtau_dphi(0, 0) = stiffness(s, phi);
  r.value = r.tau[0];
  r.energy = energy(s, phi);
}

}  // namespace seflex::mbd
