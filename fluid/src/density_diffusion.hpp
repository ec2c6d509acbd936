// Continuity with delta-SPH density diffusion (docs/physics.md, "Continuity
// and delta-SPH"; Marrone et al. 2011, CMAME 200:1526):
//   drho_i/dt = rho_i sum_j V_j v_ij . grad_i W_ij
//             + delta h c0 sum_j V_j psi_ij . grad_i W_ij,   V_j = m_j / rho_j
//   psi_ij = 2 (rho_j - rho_i) (x_j - x_i) / r_ij^2 - (<grad rho>_i + <grad rho>_j)
// The gradient term makes the diffusion vanish for a linear density field, so
// it does not smear the hydrostatic profile.
#pragma once

#include "sphcore/types.hpp"

namespace cosph::fluid {

using sph::Vec2;

// One pair's share of the diffusion sum, without the factor delta h c0 that is
// the same for every pair. With grad_i W_ij = F_ij x_ij (F_ij = W'(r)/r), the
// first part of psi_ij . grad_i W_ij is 2 (rho_j - rho_i) (x_j - x_i) . x_ij F_ij
// / r_ij^2 = -2 (rho_j - rho_i) F_ij: no square root, no division.
inline double density_diffusion_pair(double rho_i, double rho_j, double F_ij,
                                     const Vec2& grad_rho_i, const Vec2& grad_rho_j, double V_j,
                                     const Vec2& grad_W_ij) {
  return V_j * (-2.0 * (rho_j - rho_i) * F_ij - (grad_rho_i + grad_rho_j).dot(grad_W_ij));
}

}  // namespace cosph::fluid
