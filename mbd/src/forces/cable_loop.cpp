#include "seflex/mbd/forces/cable_loop.hpp"

#include <algorithm>
#include <cmath>

#include "seflex/common/error.hpp"

namespace seflex::mbd {

void validate(const CableLoop& c, const std::string& name) {
  if (c.hinges_a.empty() || c.hinges_b.empty())
    throw InputError("cable loop '" + name + "': each pulley needs at least one hinge");
  if (!(c.r_a > 0.0) || !(c.r_b > 0.0) || !std::isfinite(c.r_a) || !std::isfinite(c.r_b))
    throw InputError("cable loop '" + name + "': pulley radii must be positive numbers (m)");
  if (!(c.k > 0.0) || !std::isfinite(c.k)) throw InputError("cable loop '" + name + "': cable stiffness must be a positive number (N/m)");
  if (!(c.preload >= 0.0) || !std::isfinite(c.preload))
    throw InputError("cable loop '" + name + "': preload must be a non-negative number (N)");
  for (auto a : c.hinges_a)
    if (std::find(c.hinges_b.begin(), c.hinges_b.end(), a) != c.hinges_b.end())
      throw InputError("cable loop '" + name + "': the same hinge carries both pulleys");
}

void evaluate(const CableLoop& c, const HingeValues& h, HingeForceResult& r) {
  const int na = static_cast<int>(c.hinges_a.size()), nb = static_cast<int>(c.hinges_b.size());
  r.resize(na + nb);
  Eigen::VectorXd& de = r.tau;  // d e / d phi_i first, the torques at the end
  double e = 0.0;
  for (int i = 0; i < na; ++i) {
    r.hinges[i] = c.hinges_a[i];
    de[i] = c.r_a / na;
    e += de[i] * h.phi[c.hinges_a[i].value];
  }
  for (int i = 0; i < nb; ++i) {
    r.hinges[na + i] = c.hinges_b[i];
    de[na + i] = -c.r_b / nb;
    e += de[na + i] * h.phi[c.hinges_b[i].value];
  }
  const double x1 = c.preload / c.k + e, x2 = c.preload / c.k - e;  // stretch of each cable
  const double T1 = c.k * std::max(0.0, x1), T2 = c.k * std::max(0.0, x2);
  const double N = T1 - T2;
  const double dN = (x1 > 0.0 ? c.k : 0.0) + (x2 > 0.0 ? c.k : 0.0);
  r.dtau_dphi.noalias() = -dN * de * de.transpose();
  r.tau *= -N;  // tau = -N de
  r.value = N;
  const double x0 = c.preload / c.k;
  r.energy = 0.5 * c.k * (std::pow(std::max(0.0, x1), 2) + std::pow(std::max(0.0, x2), 2) - 2.0 * x0 * x0);
}

}  // namespace seflex::mbd
