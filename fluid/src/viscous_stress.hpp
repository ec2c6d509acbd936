// Newtonian viscous stress (docs/physics.md, "Physical viscosity"):
//   tau_ab = mu ( dv_b/dx_a + dv_a/dx_b - (2/3) (div v) delta_ab )
// from the renormalised velocity gradient grad_v(a, b) = dv_a/dx_b.
#pragma once

#include "sphcore/types.hpp"

namespace cosph::fluid {

using sph::Mat2;

inline Mat2 viscous_stress(double mu, const Mat2& grad_v) {
  return mu * (grad_v + grad_v.transpose() - (2.0 / 3.0) * grad_v.trace() * Mat2::Identity());
}

}  // namespace cosph::fluid
