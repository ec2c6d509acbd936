// Deviatoric stress rate of a linear elastic solid with the Jaumann
// (co-rotational) derivative (docs/physics.md, "Jaumann solid"; Gray, Monaghan & Swift 2001):
//   ds_ab/dt = 2G ( e_ab - (1/3) delta_ab e_cc ) + s_ac w_bc + s_cb w_ac
//   e_ab = (dv_a/dx_b + dv_b/dx_a)/2,  w_ab = (dv_a/dx_b - dv_b/dx_a)/2
// In matrix form the rotation terms are s w^T + w s: a body turning rigidly
// carries its stress round with it instead of straining it.
// The 1/3 is the plane-strain choice (e_zz = 0) of the study.
#pragma once

#include "sphcore/types.hpp"

namespace cosph::solid::jaumann {

using sph::Mat2;

// grad_v(a, b) = dv_a/dx_b. By components: in 2D the spin has one component,
// w_xy = omega = -w_yx, and
//   s w^T + w s = omega [ s_xy + s_yx    s_yy - s_xx ]
//                       [ s_yy - s_xx  -(s_xy + s_yx) ].
// As 2x2 Eigen products the terms were built on the stack and read back
// whole, a store-forwarding stall in every particle's rate.
inline Mat2 jaumann_rate(double G, const Mat2& s, const Mat2& grad_v) {
  const double e_xx = grad_v(0, 0), e_yy = grad_v(1, 1);
  const double e_xy = 0.5 * (grad_v(0, 1) + grad_v(1, 0));
  const double omega = 0.5 * (grad_v(0, 1) - grad_v(1, 0));
  const double third_of_trace = (e_xx + e_yy) / 3.0;
  const double shear_sum = s(0, 1) + s(1, 0), normal_difference = s(1, 1) - s(0, 0);
  Mat2 rate;
  rate(0, 0) = 2.0 * G * (e_xx - third_of_trace) + omega * shear_sum;
  rate(1, 1) = 2.0 * G * (e_yy - third_of_trace) - omega * shear_sum;
  rate(0, 1) = rate(1, 0) = 2.0 * G * e_xy + omega * normal_difference;
  return rate;
}

}  // namespace cosph::solid::jaumann
