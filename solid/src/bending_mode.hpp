// First bending mode of a clamped-free (cantilever) beam, the initial velocity
// profile of Gray, Monaghan & Swift 2001 sec. 6:
//   f(s) = (cos ks - cosh ks) - (cos kL - cosh kL)/(sin kL + sinh kL) (sin ks - sinh ks)
// with kL = 1.875 (the first root of cos kL cosh kL = -1). f(0) = f'(0) = 0 at
// the clamp; f(L) is the tip deflection of the mode.
#pragma once

#include <cmath>

namespace cosph::solid {

inline constexpr double kFirstModeKL = 1.875;

inline double cantilever_mode_shape(double s, double L) {
  const double k = kFirstModeKL / L, kL = kFirstModeKL;
  const double ratio = (std::cos(kL) - std::cosh(kL)) / (std::sin(kL) + std::sinh(kL));
  return (std::cos(k * s) - std::cosh(k * s)) - ratio * (std::sin(k * s) - std::sinh(k * s));
}

// Thin-plate (plane-strain) angular frequency of the first mode:
//   omega^2 = E H^2 k^4 / (12 rho (1 - nu^2)),  k = 1.875 / L.
inline double cantilever_angular_frequency(double E, double nu, double rho, double H, double L) {
  const double k = kFirstModeKL / L;
  return std::sqrt(E * H * H * k * k * k * k / (12.0 * rho * (1.0 - nu * nu)));
}

}  // namespace cosph::solid
