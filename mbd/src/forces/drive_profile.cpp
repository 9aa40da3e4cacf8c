#include "seflex/mbd/forces/drive_profile.hpp"

#include <cmath>

namespace seflex::mbd {

DriveValue spin_up_drive(double w, double T, double t) {
  DriveValue v;
  const double c = 2.0 * M_PI / T;
  if (t < T) {
    v.phi = w / T * (t * t / 2.0 + (std::cos(c * t) - 1.0) / (c * c));
    v.phidot = w / T * (t - std::sin(c * t) / c);
    v.phiddot = w / T * (1.0 - std::cos(c * t));
  } else {
    v.phi = w * (t - T / 2.0);
    v.phidot = w;
  }
  return v;
}

}  // namespace seflex::mbd
