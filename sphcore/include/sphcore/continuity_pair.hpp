// The continuity pair term (docs/physics.md, "Continuity and delta-SPH"):
//   drho_i/dt = rho_i sum_j V_j v_ij . grad_i W_ij,   V_j = m_j / rho_j.
#pragma once

#include "sphcore/types.hpp"

namespace sph {

// Contribution of j to drho_i/dt (continuity): rho_i V_j v_ij . grad_i W_ij.
inline double continuity_pair(double rho_i, double V_j, const Vec2& v_ij, const Vec2& grad_W_ij) {
  return rho_i * V_j * v_ij.dot(grad_W_ij);
}

}  // namespace sph
