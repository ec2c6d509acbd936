// The cross-phase terms of the momentum equation (SPEC.md "Momentum: the
// coupling rule"), computed once per fluid-solid pair:
//   m_f a_f += m_f m_s ( (sigma_f + sigma_s) / (rho_f rho_s) - Pi_fs I ) . grad_f W_fs
//   m_s a_s -= the same
// over pairs with r_fs < 2 h_fs, h_fs = (h_f + h_s) / 2. The same pair terms as
// inside each phase (sphcore/pair_terms.hpp), so a fluid-solid pair is no
// different from any other, and the exchange conserves momentum.
#pragma once

#include <vector>

#include "sphcore/interface_particles.hpp"

namespace cosph::coupler {

using sph::Vec2;

struct CrossPhaseParameters {
  double A;  // Monaghan artificial viscosity, linear
  double B;  // and quadratic
};

struct CrossPhaseForces {
  std::vector<Vec2> fluid_a;  // per fluid interface particle
  std::vector<Vec2> solid_a;  // per solid interface particle
  long pairs = 0;
  Vec2 force_on_fluid = Vec2::Zero();  // sum m a, N/m
  Vec2 force_on_solid = Vec2::Zero();
};

CrossPhaseForces compute_cross_phase_forces(const sph::InterfaceParticles& fluid,
                                            const sph::InterfaceParticles& solid,
                                            const CrossPhaseParameters& parameters);

}  // namespace cosph::coupler
