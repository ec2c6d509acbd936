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

#include "jaumann_particles.hpp"
#include "solid_gauges.hpp"
#include "solid_interface.hpp"
#include "solid_parameters.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/cell_grid.hpp"
#include "sphcore/checkpoint.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/interface_particles.hpp"
#include "sphcore/neighbour_list.hpp"
#include "sphcore/region.hpp"
#include "sphcore/snapshot_writer.hpp"
#include "sphcore/time_step.hpp"

namespace cosph::solid::jaumann {

class JaumannSolver {
 public:
  JaumannSolver(const sph::CaseFile& case_file, const SolidParameters& parameters);

  // The largest step the solid allows now.
  sph::StepLimits step_limits() const;

  // Advances by dt. Throws sph::RunawayError if the new state is not physical;
  // the particles then hold that bad state.
  void step(double dt) {
    begin_step(dt);
    end_step(dt);
  }

  // A coupled step is split where the coupler's answer is needed (as in
  // FluidSolver): begin_step kicks, drifts and evaluates the solid's own
  // forces; the coupler's cross-phase accelerations arrive through
  // set_interface_accelerations; end_step kicks. begin_step is advance_state
  // (kick, drift, density, stress: all the interface carries) and then
  // compute_forces, so that a coupled run can send the interface between them.
  void begin_step(double dt);
  void advance_state(double dt);
  void compute_forces();  // the solid's own accelerations
  void end_step(double dt);

  // The solid particles inside `region` (clamped ones too: water presses on them).
  void collect_interface(const sph::Region& region, sph::InterfaceParticles& out);
  // Accelerations for the particles of the last collect_interface, in its order.
  void set_interface_accelerations(const std::vector<Vec2>& accelerations);
  sph::Region interaction_bounds() const;
  double max_smoothing_length() const { return parameters_.h; }
  std::vector<sph::Gauge> gauge_values() const;

  double time() const { return time_; }
  long steps() const { return steps_; }
  const JaumannParticles& particles() const { return particles_; }
  // For tests that set up a state the case cannot describe (a velocity field);
  // the next step recomputes everything derived from it.
  JaumannParticles& particles() { return particles_; }
  const SolidParameters& parameters() const { return parameters_; }
  SolidGauges gauges() const;
  sph::Snapshot snapshot() const;

  // Everything the next step reads, for a checkpoint; restore() takes it back
  // into a solver built from the same case (jaumann_checkpoint.cpp).
  void save(sph::Checkpoint& checkpoint) const;
  void restore(const sph::Checkpoint& checkpoint);

 private:
  void sort();  // by cell, and the Verlet list rebuilt
  // The Verlet list from the grid and the positions of the last sort.
  void list_candidates(double reach);
  void mark_inert_clamp();
  enum class Including { inert, active_only };
  void update_stress(Including including);
  // Throws sph::RunawayError if a particle's state is not physical.
  void check_state() const;

  SolidInterface interface_;  // the particles of the last collect_interface
  SolidParameters parameters_;
  JaumannParticles particles_;
  std::vector<int> tip_ids_;
  double skin_;                    // of the Verlet list (sph::kSkinOverH)
  sph::CellGrid grid_;             // built for 2h + skin at the last sort
  sph::CandidateList candidates_;  // the Verlet list of the last sort
  std::vector<Vec2> x_at_sort_;    // positions at the last sort
  double time_ = 0.0;
  long steps_ = 0;
};

}  // namespace cosph::solid::jaumann
