// First bending mode of a clamped-free (cantilever) beam, the initial velocity
// profile of Gray, Monaghan & Swift 2001 sec. 6:
//   f(s) = (cosh ks - cos ks) - sigma (sinh ks - sin ks),
//   sigma = (sinh kL - sin kL) / (cosh kL + cos kL)
// with kL = 1.875 (the first root of cos kL cosh kL = -1). f(0) = f'(0) = 0 at
// the clamp, f''(L) = f'''(L) = 0 at the free end (no moment, no shear force);
// f(L) = 2 is the tip deflection of the mode. With the other signs,
// -(cos kL - cosh kL) / (sin kL + sinh kL) is not a mode: it leaves a bending
// moment at the free end and starts a mix of modes.
#pragma once

#include <cmath>

namespace cosph::solid {

inline constexpr double kFirstModeKL = 1.875;

inline double cantilever_mode_shape(double s, double L) {
  const double k = kFirstModeKL / L, kL = kFirstModeKL;
  const double sigma = (std::sinh(kL) - std::sin(kL)) / (std::cosh(kL) + std::cos(kL));
  return (std::cosh(k * s) - std::cos(k * s)) - sigma * (std::sinh(k * s) - std::sin(k * s));
}

// Thin-plate (plane-strain) angular frequency of the first mode:
//   omega^2 = E H^2 k^4 / (12 rho (1 - nu^2)),  k = 1.875 / L.
inline double cantilever_angular_frequency(double E, double nu, double rho, double H, double L) {
  const double k = kFirstModeKL / L;
  return std::sqrt(E * H * H * k * k * k * k / (12.0 * rho * (1.0 - nu * nu)));
}

}  // namespace cosph::solid
