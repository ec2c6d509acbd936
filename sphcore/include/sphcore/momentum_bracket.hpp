// The momentum pair term (docs/physics.md, "Momentum"):
//   dv_i/dt = sum_j m_j ( (sigma_i + sigma_j) / (rho_i rho_j) - Pi_ij I ) . grad_i W_ij.
// momentum_pair is the reference form, the one the coupler uses for a
// fluid-solid pair. The phases' own pairs, the bulk of the work, use the same
// bracket by components: no 2x2 matrix is built and nothing divided per pair
// (1/rho is worked out once per particle). The solid's sigma L need not be
// symmetric (MomentumBracket); the water's stress is (SymmetricStress). Tests
// hold both equal to momentum_pair.
#pragma once

#include "sphcore/types.hpp"

namespace sph {

// Contribution of j to dv_i/dt:
//   m_j ( (sigma_i + sigma_j) / (rho_i rho_j) - Pi_ij I ) . grad_i W_ij.
// The bracket is symmetric in i, j and grad_j W_ji = -grad_i W_ij exactly, so
// m_i a_i = -m_j a_j: exactly for equal masses, to round-off (the order of the
// products differs) otherwise. The exchange conserves momentum.
inline Vec2 momentum_pair(double m_j, const Mat2& sigma_i, const Mat2& sigma_j, double rho_i,
                          double rho_j, double Pi_ij, const Vec2& grad_W_ij) {
  const Mat2 bracket = (sigma_i + sigma_j) / (rho_i * rho_j) - Pi_ij * Mat2::Identity();
  return m_j * (bracket * grad_W_ij);
}

// The bracket ( (a_i + a_j) / (rho_i rho_j) - Pi_ij I ) of two momentum fluxes
// a (sigma, or the solid's sigma L), by components.
struct MomentumBracket {
  double xx, xy, yx, yy;

  // The bracket times grad_i W_ij.
  Vec2 times(const Vec2& grad_W_ij) const {
    return Vec2(xx * grad_W_ij.x() + xy * grad_W_ij.y(), yx * grad_W_ij.x() + yy * grad_W_ij.y());
  }
};

inline MomentumBracket momentum_bracket(const Mat2& a_i, const Mat2& a_j,
                                        double inverse_rho_i_rho_j, double Pi_ij) {
  return {(a_i(0, 0) + a_j(0, 0)) * inverse_rho_i_rho_j - Pi_ij,
          (a_i(0, 1) + a_j(0, 1)) * inverse_rho_i_rho_j,
          (a_i(1, 0) + a_j(1, 0)) * inverse_rho_i_rho_j,
          (a_i(1, 1) + a_j(1, 1)) * inverse_rho_i_rho_j - Pi_ij};
}

// A symmetric 2-D stress, by its three components.
struct SymmetricStress {
  double xx, xy, yy;
};

// The pair's bracket times grad_i W_ij for symmetric stresses,
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

}  // namespace sph
