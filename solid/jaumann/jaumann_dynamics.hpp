// The neighbour passes of one Jaumann solid step (docs/physics.md, "Jaumann
// solid" and "Momentum").
//
// 1. rates: drho/dt from continuity, and ds/dt from the Jaumann rate of the
//    velocity gradient: renormalised (docs/physics.md, "Jaumann solid"; solid.velocity_gradient
//    "linear", the default), or fitted to be exact for quadratic fields
//    ("quadratic", for small deformations; sphcore/quadratic_gradient.hpp).
// 2. accelerations: dv/dt from the momentum equation with artificial
//    viscosity and (if on) artificial stress, the one force evaluation.
// Between them the solver turns rho and s into the stress (update_stress).
// Both visit the first in_reach(particles) only: the clamped particles
// behind them are out of every free particle's reach (clamp_reach.hpp).
#pragma once

#include "jaumann_particles.hpp"
#include "solid_parameters.hpp"
#include "sphcore/neighbour_list.hpp"

namespace cosph::solid::jaumann {

// Reads x, v, rho, m, s; writes drho, ds (zero for failed particles, whose
// deviator stays zero), the renormalisation matrix L and the neighbour lists
// (each pair once, in the list of its lower index).
// The candidates (a Verlet list) must hold every j within 2h of i.
void compute_rates(JaumannParticles& particles, const sph::CandidateList& candidates,
                   const SolidParameters& parameters);

// Reads the neighbour lists of compute_rates (the positions must not have
// moved since), x, v, rho, m, sigma_L, R, c, external_a; writes a (zero for
// clamped particles).
//
// Within the solid the momentum pair term carries sigma L instead of sigma:
//   dv_i/dt = sum_j m_j ( (sigma_i L_i + sigma_j L_j) / (rho_i rho_j) - Pi_ij I ) . grad_i W_ij
// (Bonet & Lok 1999). The bracket is still symmetric in i, j, so momentum is
// conserved exactly, and the stress divergence stays first-order consistent at
// the free surfaces, where the plain form makes a bending plate too soft (a
// deviation from docs/physics.md, "Momentum", which the coupler's cross-phase
// term does not share).
void compute_accelerations(JaumannParticles& particles, const SolidParameters& parameters);

}  // namespace cosph::solid::jaumann
