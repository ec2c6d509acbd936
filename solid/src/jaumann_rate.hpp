// Deviatoric stress rate of a linear elastic solid with the Jaumann
// (co-rotational) derivative (SPEC.md "Solid"; Gray, Monaghan & Swift 2001):
//   ds_ab/dt = 2G ( e_ab - (1/3) delta_ab e_cc ) + s_ac w_bc + s_cb w_ac
//   e_ab = (dv_a/dx_b + dv_b/dx_a)/2,  w_ab = (dv_a/dx_b - dv_b/dx_a)/2
// In matrix form the rotation terms are s w^T + w s: a body turning rigidly
// carries its stress round with it instead of straining it.
// The 1/3 is the plane-strain choice (e_zz = 0) of the study.
#pragma once

#include "sphcore/types.hpp"

namespace cosph::solid {

using sph::Mat2;

// grad_v(a, b) = dv_a/dx_b.
inline Mat2 strain_rate(const Mat2& grad_v) {
  return 0.5 * (grad_v + grad_v.transpose());
}
inline Mat2 rotation_rate(const Mat2& grad_v) {
  return 0.5 * (grad_v - grad_v.transpose());
}

inline Mat2 jaumann_rate(double G, const Mat2& s, const Mat2& grad_v) {
  const Mat2 e = strain_rate(grad_v), w = rotation_rate(grad_v);
  return 2.0 * G * (e - (e.trace() / 3.0) * Mat2::Identity()) + s * w.transpose() + w * s;
}

}  // namespace cosph::solid
