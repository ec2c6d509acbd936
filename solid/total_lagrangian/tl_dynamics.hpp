// The two passes of one total-Lagrangian step, over the fixed reference
// neighbours (reference_configuration.hpp).
//
// 1. deformation: F_i = I + sum_j V0_j (u_j - u_i) (x) grad~0 W_ij,  u = x - X,
//    exact for a linear deformation (grad~0 is corrected), then the
//    St Venant-Kirchhoff stress of F. Written with displacements it equals
//    sum_j V0_j (x_j - x_i) (x) grad~0 W_ij, but keeps F = I at rest even
//    where L0 fell back to the identity, and loses no digits to |x| >> |u|.
// 2. accelerations (the one force evaluation), per pair, equal and opposite:
//    m_i a_i = sum_j V0_i V0_j (P_i grad~0 W_ij - P_j grad~0 W_ji)
//            = sum_j V0_i V0_j (P_i L0_i + P_j L0_j) grad0 W_ij
//      (the derivative of the discrete strain energy sum_i V0_i psi(F_i), so
//      elastic forces conserve energy and linear momentum exactly),
//    - sum_j m_i m_j Pi_ij dW/dr(|X_ij|) x_ij / r_ij
//      (Monaghan artificial viscosity, docs/physics.md, "Artificial viscosity", with the kernel
//      of the reference distance along the current direction: central, and
//      dissipative only for approaching pairs),
//    + the hourglass force (hourglass_control.hpp), + m_i g.
#pragma once

#include "sphcore/types.hpp"
#include "tl_particles.hpp"

namespace cosph::solid::tl {

struct ForceParameters {
  double h;
  double A, B;             // Monaghan artificial viscosity
  double hourglass_alpha;  // Ganzenmueller's alpha; 0 turns the control off
  sph::Vec2 gravity;
};

// Reads x, X, neighbours; writes F, J, rho, P_L0, sigma, sigma_zz, strain_energy,
// except for inert particles, whose values stay those of F = I. Both passes
// visit the first in_reach(particles) only (clamp_reach.hpp).
void compute_deformation_and_stress(TLParticles& particles);

// Reads x, v, F, rho, P_L0; writes a (zero for clamped particles; those past
// in_reach keep the zero they start with). The coupler's
// external_a is not included: the kicks add it.
void compute_accelerations(TLParticles& particles, const ForceParameters& parameters);

}  // namespace cosph::solid::tl
