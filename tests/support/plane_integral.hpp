// The integral of a radial kernel W(r, h) over the plane, by the midpoint
// rule on a fine Cartesian grid over its support [-2h, 2h]^2: checks a 2-D
// normalisation without assuming the kernel's symmetry.
#pragma once

#include <cmath>

namespace cosph::testing {

template <class Kernel>
double plane_integral(const Kernel& W, double h, int n = 1000) {
  const double cell = 4.0 * h / n;
  double integral = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = -2.0 * h + (i + 0.5) * cell, y = -2.0 * h + (j + 0.5) * cell;
      integral += W(std::hypot(x, y), h) * cell * cell;
    }
  return integral;
}

}  // namespace cosph::testing
