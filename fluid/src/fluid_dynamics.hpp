// The neighbour passes of one fluid step (SPEC.md "Fluid").
//
// 1. continuity_and_gradients: drho/dt from continuity with delta-SPH
//    diffusion, and, for the next passes, the renormalised density and velocity
//    gradients and the viscous stress.
// 2. wall_pressure: the walls' pressure extrapolated from the water (Adami et
//    al. 2012), once the water's new pressure is known.
// 3. accelerations: dv/dt from the momentum equation, the one force evaluation.
#pragma once

#include "equation_of_state.hpp"
#include "fluid_parameters.hpp"
#include "fluid_particles.hpp"
#include "sphcore/cell_grid.hpp"
#include "sphcore/neighbour_list.hpp"

namespace cosph::fluid {

// Reads grad_rho (of the previous step: the diffusion's correction term lags
// one step, which keeps this to one pass) and writes drho, tau and the new
// grad_rho.
void compute_continuity_and_gradients(FluidParticles& particles, const sph::NeighbourList& pairs,
                                      const FluidParameters& parameters);

void compute_wall_pressure(FluidParticles& particles, const sph::CellGrid& grid,
                           const FluidParameters& parameters, const TaitEquationOfState& eos);

// The water's own forces and gravity; the coupling's share is added by the
// integrator, since it arrives after this evaluation.
void compute_accelerations(FluidParticles& particles, const sph::NeighbourList& pairs,
                           const FluidParameters& parameters);

}  // namespace cosph::fluid
