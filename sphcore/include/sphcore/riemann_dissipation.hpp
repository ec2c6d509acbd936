// The dissipation of Riemann-solver SPH (Zhang, Hu & Adams 2017, J. Comput.
// Phys. 340:439, "A weakly compressible SPH method based on a low-dissipation
// Riemann solver"). Each pair solves a linearised acoustic Riemann problem
// along e_ij = (x_j - x_i) / r_ij, i on the left (U = v . e_ij):
//   U* = U_bar + (P_i - P_j) / (2 rho0 c0),
//   P* = P_bar + rho_bar beta (U_i - U_j) / 2,  beta = min(eta max(U_i - U_j, 0), c0),
// with the dissipation limiter eta = 3 (the paper's value) that leaves the
// pressure undamped where the pair separates and nearly so in slow
// compression. The continuity and momentum equations take v* and P*:
//   drho_i/dt = 2 rho_i sum_j V_j (v_i - v*) . grad_i W_ij,
//   dv_i/dt   = -2 sum_j m_j P* / (rho_i rho_j) grad_i W_ij.
// Written against the central terms (sphcore's continuity_pair.hpp and
// momentum_bracket.hpp), each is that term plus one dissipative term, which
// is what lives here: the fluid takes them between its particles and against
// its own walls (fluid.dissipation riemann), and the coupler against the
// solid's particles seen as a moving wall, so the water meets both walls alike.
#pragma once

#include <algorithm>
#include <cmath>

#include "sphcore/types.hpp"

namespace sph {

// Continuity's dissipative part for one pair,
//   -2 rho_i V_j (U* - U_bar) e_ij . grad_i W_ij = rho_i V_j (P_i - P_j) / (rho0 c0) F_ij r_ij,
// with grad_i W_ij = F_ij x_ij (F_ij = W'(r)/r < 0, e_ij . grad_i W_ij = -F_ij r_ij):
// density flows from the higher pressure to the lower.
inline double riemann_density_dissipation_pair(double rho_i, double V_j, double P_i, double P_j,
                                               double F_ij, double r_ij, double inverse_rho0_c0) {
  return rho_i * V_j * (P_i - P_j) * inverse_rho0_c0 * F_ij * r_ij;
}
inline double riemann_density_dissipation_pair(double rho_i, double V_j, double P_i, double P_j,
                                               double F_ij, const Vec2& x_ij,
                                               double inverse_rho0_c0) {
  return riemann_density_dissipation_pair(rho_i, V_j, P_i, P_j, F_ij, x_ij.norm(), inverse_rho0_c0);
}

// The pressure of a wall particle j on the wall's side of water particle i's
// Riemann problem: i's own pressure carried hydrostatically to j,
//   P_j = P_i + rho_i (g - a_w) . (x_j - x_i),
// the one-sided Riemann problem of the paper's wall condition (the wall
// mirrors the water particle), as SPHinXsys solves it against walls
// (p_j_in_wall in fluid_integration.hpp; it also drops the term where
// (g - a_w) points away from the wall, kept here linear as Adami's
// extrapolation is). Not the wall's extrapolated pressure, a kernel mean of the
// water within 2h: where the pressure rises towards a wall (a flow stagnating
// on it) that mean lies below the pressure of the water next to the wall, and
// the water there would lose density into the wall, which gives none back.
inline double riemann_wall_pressure(double P_i, double rho_i, const Vec2& body_force,
                                    const Vec2& x_ij) {
  return P_i - rho_i * body_force.dot(x_ij);
}

// Momentum's dissipative part as the Pi_ij of the pair's bracket
// (momentum_bracket.hpp: ((sigma_i + sigma_j) / (rho_i rho_j) - Pi_ij I) . grad_i W_ij):
// the paper's P* in place of (P_i + P_j) / 2 adds
//   Pi_ij = 2 (rho_i rho_j / (rho_i + rho_j)) beta (U_i - U_j) / (rho_i rho_j)
//         = beta (U_i - U_j) / rho_bar,   U_i - U_j = -v_ij . x_ij / r_ij.
// It replaces Monaghan's artificial viscosity.
class RiemannLimitedDissipation {
 public:
  static constexpr double kLimiter = 3.0;  // eta of the paper

  explicit RiemannLimitedDissipation(double c0) : c0_(c0) {}

  double operator()(const Vec2& x_ij, const Vec2& v_ij, double rho_bar) const {
    return (*this)(x_ij, v_ij, rho_bar, x_ij.norm());
  }
  // With r = |x_ij| known.
  double operator()(const Vec2& x_ij, const Vec2& v_ij, double rho_bar, double r) const {
    const double approach = r > 0.0 ? -v_ij.dot(x_ij) / r : 0.0;  // U_i - U_j
    const double beta = std::min(kLimiter * std::max(approach, 0.0), c0_);
    return beta * approach / rho_bar;
  }

 private:
  double c0_;
};

}  // namespace sph
