// Volumetric part of linear elasticity (docs/physics.md, "Jaumann solid"; Gray, Monaghan &
// Swift 2001, CMAME 190:6641):  P = K (rho/rho0 - 1),  K = E / (3 (1 - 2 nu)).
// Compression (rho > rho0) gives P > 0, as stress is tension-positive and
// sigma = -P I + s.
#pragma once

#include <cmath>

namespace cosph::solid {

inline double bulk_modulus(double E, double nu) {
  return E / (3.0 * (1.0 - 2.0 * nu));
}
inline double shear_modulus(double E, double nu) {
  return E / (2.0 * (1.0 + nu));
}

inline double hooke_pressure(double K, double rho, double rho0) {
  return K * (rho / rho0 - 1.0);
}

// Speed of longitudinal (P) waves, sqrt((K + 4G/3) / rho0): it sets the step.
inline double longitudinal_sound_speed(double K, double G, double rho0) {
  return std::sqrt((K + 4.0 * G / 3.0) / rho0);
}

}  // namespace cosph::solid
