// Momentum equation of the water (docs/physics.md, "Momentum"):
//   dv_i/dt = g + sum_j m_j ( (sigma_i + sigma_j) / (rho_i rho_j) - Pi_ij I ) . grad_i W_ij,
//   sigma = -p I + tau.
// sph::momentum_pair is this pair term for any two particles. The water's own
// pairs, the bulk of the work, use the same formula in a form that costs less
// per pair: the total stress is symmetric (tau is) and kept by its three
// components, and 1/rho is worked out once per particle, so a pair builds no
// 2x2 matrix and divides nothing. The bracket is still symmetric in i and j
// bit for bit, and each pair is worked out once for both particles
// (fluid_dynamics.cpp), so they exchange exactly opposite momentum.
#pragma once

#include "sphcore/types.hpp"

namespace cosph::fluid {

using sph::Mat2;
using sph::Vec2;

// A symmetric 2-D stress.
struct SymmetricStress {
  double xx, xy, yy;
};

// sigma = -p I + tau; tau is symmetric by construction (viscous_stress.hpp).
inline SymmetricStress total_stress(double p, const Mat2& tau) {
  return {-p + tau(0, 0), tau(0, 1), -p + tau(1, 1)};
}

// The pair's bracket times grad_i W_ij,
//   ( (sigma_i + sigma_j) / (rho_i rho_j) - Pi_ij I ) . grad_i W_ij:
// j's contribution to dv_i/dt is m_j times it, i's to dv_j/dt -m_i times it
// (the bracket is symmetric, grad_j W_ji = -grad_i W_ij).
inline Vec2 bracket_times_gradient(const SymmetricStress& sigma_i, const SymmetricStress& sigma_j,
                                   double inverse_rho_i, double inverse_rho_j, double Pi_ij,
                                   const Vec2& grad_W_ij) {
  const double inverse_rho_i_rho_j = inverse_rho_i * inverse_rho_j;
  const double b_xx = (sigma_i.xx + sigma_j.xx) * inverse_rho_i_rho_j - Pi_ij;
  const double b_xy = (sigma_i.xy + sigma_j.xy) * inverse_rho_i_rho_j;
  const double b_yy = (sigma_i.yy + sigma_j.yy) * inverse_rho_i_rho_j - Pi_ij;
  return Vec2(b_xx * grad_W_ij.x() + b_xy * grad_W_ij.y(),
              b_xy * grad_W_ij.x() + b_yy * grad_W_ij.y());
}

}  // namespace cosph::fluid
