// The von Mises equivalent stress (docs/physics.md, "Von Mises failure"): the
// Jaumann solid's failure test, and a gauge and snapshot field of both solids.
#pragma once

#include <cmath>

#include "sphcore/types.hpp"

namespace sph {

// Von Mises equivalent stress of a 2-D stress tensor:
//   sqrt( (3 sigma_ab sigma_ab - sigma_aa sigma_bb) / 2 ).
inline double von_mises(const Mat2& sigma) {
  const double trace = sigma.trace();
  const double value = 0.5 * (3.0 * sigma.squaredNorm() - trace * trace);
  return value > 0.0 ? std::sqrt(value) : 0.0;
}

}  // namespace sph
