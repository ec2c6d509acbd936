// Artificial stress against the tensile instability (Gray, Monaghan & Swift
// 2001, sec. 4; Monaghan 2000; docs/physics.md, "Artificial stress").
//
// Under tension, SPH particles attract each other where the kernel's
// second derivative makes the pair force grow as they approach: they clump
// and the body tears apart without any physical cause. The cure adds to each
// solid pair a short-range repulsion f_ij^n (R_i + R_j), f_ij = W(r_ij)/W(dx),
// which only acts where particles come closer than the initial spacing, and
// only in the directions in which the stress is tensile:
//   R_i = Q diag(R'_1, R'_2) Q^T,  R'_k = -eps sigma'_k / rho_i^2 if sigma'_k > 0, else 0,
// with sigma_i = Q diag(sigma'_1, sigma'_2) Q^T.
#pragma once

#include <cmath>

#include "sphcore/types.hpp"

namespace cosph::solid::jaumann {

using sph::Mat2;
using sph::Vec2;

// Closed form for the symmetric 2x2 sigma: principal values m +- r, and the
// spectral projectors P_1 = (sigma - lambda_2 I) / (lambda_1 - lambda_2), P_2 = I - P_1.
inline Mat2 artificial_stress(const Mat2& sigma, double rho, double epsilon) {
  auto R_principal = [&](double value) {
    return value > 0.0 ? -epsilon * value / (rho * rho) : 0.0;
  };
  const double mean = 0.5 * (sigma(0, 0) + sigma(1, 1));
  const double half_difference = 0.5 * (sigma(0, 0) - sigma(1, 1));
  const double shear = 0.5 * (sigma(0, 1) + sigma(1, 0));
  // Not std::hypot: stresses are far from overflow, and the libm call was a
  // tenth of the solid's stress update.
  const double radius = std::sqrt(half_difference * half_difference + shear * shear);
  const double lambda_1 = mean + radius, lambda_2 = mean - radius;
  if (!(radius > 1e-12 * std::abs(mean))) return R_principal(mean) * Mat2::Identity();
  const Mat2 P_1 = (sigma - lambda_2 * Mat2::Identity()) / (lambda_1 - lambda_2);
  return R_principal(lambda_1) * P_1 + R_principal(lambda_2) * (Mat2::Identity() - P_1);
}

// j's contribution to dv_i/dt is m_j f_ij^n (R_i + R_j) . grad_i W_ij,
// antisymmetric in i, j like the momentum pair term, to which the momentum
// pass adds it (jaumann_dynamics.cpp).

}  // namespace cosph::solid::jaumann
