// The solid solver: owns the solid particles and advances them by
// kick-drift-kick, one force evaluation per step (SPEC.md "Time integration").
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

#include "solid_gauges.hpp"
#include "solid_parameters.hpp"
#include "solid_particles.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/cell_grid.hpp"
#include "sphcore/snapshot_writer.hpp"
#include "sphcore/time_step.hpp"

namespace cosph::solid {

class SolidSolver {
 public:
  SolidSolver(const sph::CaseFile& case_file, const SolidParameters& parameters);

  // The largest step the solid allows now.
  sph::StepLimits step_limits() const;

  // Advances by dt. Throws sph::RunawayError if the new state is not physical;
  // the particles then hold that bad state.
  void step(double dt);

  double time() const { return time_; }
  long steps() const { return steps_; }
  const SolidParticles& particles() const { return particles_; }
  // The coupler's way in: it sets external_a (same order as particles()).
  SolidParticles& mutable_particles() { return particles_; }
  const SolidParameters& parameters() const { return parameters_; }
  SolidGauges gauges() const { return measure(particles_, tip_ids_); }
  sph::Snapshot snapshot() const;

 private:
  void sort_and_find_neighbours();
  void update_stress();
  void check_state() const;

  SolidParameters parameters_;
  SolidParticles particles_;
  std::vector<int> tip_ids_;
  sph::CellGrid grid_;
  double time_ = 0.0;
  long steps_ = 0;
};

}  // namespace cosph::solid
