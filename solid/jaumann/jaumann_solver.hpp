// The Jaumann solid solver: owns its particles and advances them by
// kick-drift-kick, one force evaluation per step (docs/physics.md, "Time step").
//
// Step from t to t + dt, with a known at t:
//   v    += dt/2 a                                   (kick)
//   x    += dt v                                     (drift)
//   rho  += dt drho/dt(v),  s += dt ds/dt(v)         (with the half-step velocity)
//   sigma = -P(rho) I + s,  failure, artificial stress
//   a     = a(x, sigma)                              (the one force evaluation)
//   v    += dt/2 a                                   (kick)
// Density and stress are drifted with the half-step velocity, not kicked
// alongside it: elastic waves trade energy between (rho, s) and v, and
// updating both from the same old state would amplify them every step.
//
// The API is the fluid solver's, so that a coupler can drive either, sub-step
// the solid, and set external_a on the particles it shares with the fluid.
#pragma once

#include <vector>

#include "continuum_solid_solver.hpp"
#include "jaumann_particles.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/checkpoint.hpp"
#include "sphcore/snapshot_writer.hpp"
#include "sphcore/sorted_verlet_list.hpp"

namespace cosph::solid::jaumann {

class JaumannSolver
    : public ContinuumSolidSolver<JaumannSolver, JaumannParticles, &JaumannParticles::x0> {
 public:
  JaumannSolver(const sph::CaseFile& case_file, const SolidParameters& parameters);

  // A coupled step is split where the coupler's answer is needed (as in
  // FluidSolver): begin_step kicks, drifts and evaluates the solid's own
  // forces; the coupler's cross-phase accelerations arrive through
  // set_interface_accelerations; end_step kicks. begin_step is advance_state
  // (kick, drift, density, stress: all the interface carries) and then
  // compute_forces, so that a coupled run can send the interface between them.
  void begin_step(double dt);
  void advance_state(double dt);
  void compute_forces();  // the solid's own accelerations

  SolidGauges gauges() const;
  sph::Snapshot snapshot() const;

  // Everything the next step reads, for a checkpoint; restore() takes it back
  // into a solver built from the same case (jaumann_checkpoint.cpp).
  void save(sph::Checkpoint& checkpoint) const;
  void restore(const sph::Checkpoint& checkpoint);

 private:
  friend ContinuumSolidSolver;
  void sort();  // by cell, and the Verlet list rebuilt
  // Which j the Verlet list keeps as candidates of i (sort and restore alike).
  auto candidate_filter() const {
    const JaumannParticles& P = particles_;
    const bool whole = parameters_.velocity_gradient == VelocityGradient::quadratic;
    return
        [&P, whole](long i, int j) { return (whole || j > i || P.inert[j]) && !P.out_of_reach[j]; };
  }
  // Which clamped particles are inert and which out of reach (clamp_reach.hpp).
  void set_clamp_reach();
  enum class Including { inert, active_only };
  void update_stress(Including including);
  // Throws sph::RunawayError if a particle's state is not physical.
  void check_state() const;

  sph::SortedVerletList verlet_;
};

}  // namespace cosph::solid::jaumann
