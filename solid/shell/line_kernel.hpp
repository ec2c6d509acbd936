// The cubic spline along the shell's line: sphcore's kernel with the 1-D
// normalisation 2 / (3h) in place of the 2-D one, so that it integrates to 1
// along the line (the hourglass control weighs pairs with it; the corrected
// gradients of the strains do not depend on the normalisation).
#pragma once

#include "sphcore/kernel.hpp"

namespace cosph::solid::shell {

inline double line_W(double r, double h) {
  return sph::kernel::W(r, h) * (2.0 / (3.0 * h)) / sph::kernel::normalisation(h);
}

inline double line_dW_dr(double r, double h) {
  return sph::kernel::dW_dr(r, h) * (2.0 / (3.0 * h)) / sph::kernel::normalisation(h);
}

}  // namespace cosph::solid::shell
