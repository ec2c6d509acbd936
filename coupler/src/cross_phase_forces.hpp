// The cross-phase terms, computed once per fluid-solid pair (r_fs < 2 h_fs,
// h_fs = (h_f + h_s) / 2) and shared equal and opposite, so the exchange
// conserves momentum. W_fs and grad_f W_fs are of the kernel the parameters
// name: the cubic spline, or for a moving wall the water's own
// (fluid.kernel), so that the water sees the solid through the kernel it
// sees its own walls through. Two interface models (case field coupling.interface):
//
// stress_sum, the study's rule (docs/physics.md, "Stress sum"): the
// momentum sum runs over both phases with each particle's own stress,
//   m_f a_f += m_f m_s ( (sigma_f + sigma_s) / (rho_f rho_s) - Pi_fs I ) . grad_f W_fs,
// the same pair term as inside each phase (sphcore/momentum_bracket.hpp, artificial_viscosity.hpp).
//
// moving_wall (docs/physics.md, "Moving wall"): the water sees each solid
// particle as a moving wall particle of the solid's volume V_s = m_s / rho_s,
// as it sees its own walls (Adami, Hu & Adams 2012): pressure P_w
// extrapolated from the water around it with the body force g - a_w, a_w the
// solid particle's acceleration when the solid sends it
// (sphcore/wall_pressure.hpp), and a
// share in the water's continuity,
//   a_f     += V_s ( (sigma_f - P_w I) / rho_f - rho_f Pi_fs I ) . grad_f W_fs
//   drho_f  += rho_f V_s (v_f - v_s) . grad_f W_fs.
// The solid then feels the water's pressure, not its own stress: the bending
// stress along a plate (hundreds of times the water pressure) never enters the
// water's momentum, where its discretisation noise tore the water apart.
// With the water's fluid.dissipation riemann the pairs take the terms the water
// takes against its own walls (sphcore/riemann_dissipation.hpp): Pi_fs is the
// Riemann solver's limited dissipation, and drho_f gains the Riemann density
// term against the wall's side mirroring the water particle,
//   P_s = P_f + rho_f (g - a_w) . (x_s - x_f).
// And with the water's fluid.wall_friction, Pi_fs acts as against its own
// walls (fluid/src/dissipation.hpp, wall_dissipation): on the whole relative
// velocity (dissipation), not at all (none), or on its part along the solid
// particle's normal n_s only (normal), n_s pointing to the water from the
// moment sum P_w is extrapolated with, as the water takes its walls' normals.
#pragma once

#include <vector>

#include "dissipation.hpp"

#include "sphcore/interface_particles.hpp"
#include "sphcore/kernel_shape.hpp"

namespace cosph::coupler {

using sph::Vec2;

enum class InterfaceModel { stress_sum, moving_wall };

struct CrossPhaseParameters {
  InterfaceModel model = InterfaceModel::moving_wall;
  double A = 0.02;                // Monaghan artificial viscosity, linear
  double B = 0.0;                 // and quadratic
  Vec2 gravity = Vec2::Zero();    // moving_wall: g in the body force g - a_w of P_w
  bool wall_acceleration = true;  // moving_wall: a_w taken when the solid sends it
  // moving_wall: the water's Riemann terms in place of Monaghan's viscosity
  // (fluid.dissipation riemann), with the water's reference density rho0 in
  // their 1 / (rho0 c0); c0 is the sound speed the fluid sends.
  bool riemann_dissipation = false;
  double rho0 = 1000.0;
  // moving_wall: the water's fluid.wall_friction.
  fluid::WallFriction wall_friction = fluid::WallFriction::dissipation;
  // The kernel of every pair's W and grad W (fluid.kernel for the moving
  // wall); the pairs are those within its support 2 h_fs, for either shape.
  sph::kernel::Shape kernel = sph::kernel::Shape::cubic_spline;
};

struct CrossPhaseForces {
  std::vector<Vec2> fluid_a;          // per fluid interface particle
  std::vector<Vec2> solid_a;          // per solid interface particle
  std::vector<double> fluid_drho;     // moving_wall only (empty otherwise), kg/m^3/s
  std::vector<double> wall_pressure;  // moving_wall only: P_w per solid interface particle, Pa
  long pairs = 0;
  Vec2 force_on_fluid = Vec2::Zero();  // sum m a, N/m
  Vec2 force_on_solid = Vec2::Zero();
};

CrossPhaseForces compute_cross_phase_forces(const sph::InterfaceParticles& fluid,
                                            const sph::InterfaceParticles& solid,
                                            const CrossPhaseParameters& parameters);

}  // namespace cosph::coupler
