// The neighbour passes of one fluid step (docs/physics.md, "Continuity and
// delta-SPH" to "Walls").
//
// 1. continuity_and_gradients: drho/dt from continuity with delta-SPH
//    diffusion, and, for the next passes, the renormalised density and velocity
//    gradients and the viscous stress.
// 2. wall_pressure: the walls' pressure extrapolated from the water (Adami et
//    al. 2012), once the water's new pressure is known.
// 3. accelerations: dv/dt from the momentum equation, the one force evaluation.
// And, for the timeseries, the force of the water on each wall (forces_on_walls).
#pragma once

#include <vector>

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

// The wall particles with water closer than `reach`, in index order. With
// reach = 2h + skin at a sort, no other wall has water within 2h until the
// next sort (no particle moves skin / 2 in between): their pressure is zero.
std::vector<int> walls_in_reach(const FluidParticles& particles, const sph::CellGrid& grid,
                                double reach);

// delta-plus-SPH's particle shifts (particle_shifting.hpp) at the positions of
// this step's pairs, into `shift`, for the next drift; the volumes of
// compute_continuity_and_gradients; dt the step's.
void compute_particle_shifts(FluidParticles& particles, const sph::NeighbourList& pairs,
                             const FluidParameters& parameters, double dt);

// The other walls (walls_in_reach in index order) as they are with no water
// in reach: p = 0, rho0, tau = 0. Those in reach keep their values, which the
// continuity pass reads before the new wall pressure is known.
void rest_walls_out_of_reach(FluidParticles& particles, const std::vector<int>& walls_in_reach,
                             const TaitEquationOfState& eos);

// The pressure (and density) of `walls`; the other walls are left as they are.
void compute_wall_pressure(FluidParticles& particles, const sph::CellGrid& grid,
                           const std::vector<int>& walls, const FluidParameters& parameters,
                           const TaitEquationOfState& eos);

// The water's own forces and gravity; the coupling's share is added by the
// integrator, since it arrives after this evaluation.
void compute_accelerations(FluidParticles& particles, const sph::NeighbourList& pairs,
                           const FluidParameters& parameters);

// The force of the water on each of fluid.walls, per unit depth (N/m): minus
// the momentum terms its wall particles j give the water,
//   F_k = - sum_{j in wall k} sum_{water i} m_i m_j ( (sigma_i + sigma_j) / (rho_i rho_j)
//                                                   - Pi_ij I ) . grad_i W_ij,
// with the stresses of the last compute_accelerations and the velocities of
// now (in the artificial viscosity; the same until the step's last kick). Pairs
// are equal and opposite, so the walls' forces add up to sum_i m_i (g - a_i)
// over the water (less the coupling's share): what holds the water up.
std::vector<Vec2> forces_on_walls(const FluidParticles& particles, const sph::NeighbourList& pairs,
                                  const FluidParameters& parameters);

}  // namespace cosph::fluid
