// The explicit stable step (docs/physics.md, "Time step"):
//   dt <= C_cfl h / (c + |v|_max),  0.25 sqrt(h / |a|_max),  0.125 h^2 / nu.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace sph {

struct StepLimits {
  double sound;    // acoustic (CFL) limit
  double force;    // acceleration limit
  double viscous;  // viscous diffusion limit; infinite without viscosity

  double smallest() const { return std::min({sound, force, viscous}); }
};

// nu: kinematic viscosity mu / rho (0 for none).
inline StepLimits step_limits(double cfl, double h, double c, double v_max, double a_max,
                              double nu) {
  constexpr double kInfinite = std::numeric_limits<double>::infinity();
  return {cfl * h / (c + v_max), a_max > 0.0 ? 0.25 * std::sqrt(h / a_max) : kInfinite,
          nu > 0.0 ? 0.125 * h * h / nu : kInfinite};
}

}  // namespace sph
