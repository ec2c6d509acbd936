// The total-Lagrangian SPH solid (cosph-solid-tl; docs/physics.md,
// "Total-Lagrangian solid"): an alternative to the Jaumann solid of
// solid/jaumann that needs no artificial stress. Stress follows from the deformation gradient F
// against the fixed reference configuration (reference_configuration.hpp), through St
// Venant-Kirchhoff elasticity (st_venant_kirchhoff.hpp), with hourglass control
// (hourglass_control.hpp). References: Bonet & Lok 1999 (CMAME 180), Vignjevic, Reveles & Campbell
// 2006 (CMAME 195), Ganzenmueller 2015 (CMAME 286).
//
// Step from t to t + dt, with a known at t (kick-drift-kick, one force
// evaluation per step; the elastic force depends on positions only, so this
// is the symplectic velocity Verlet scheme for the elastic part):
//   v += dt/2 a;  x += dt v;  F, P = P(F);  a = a(x, v, P);  v += dt/2 a
//
// The API is the Jaumann solver's (participant/run_solver.hpp drives either,
// alone or coupled; participant/coupled_solver.hpp states it).
#pragma once

#include <vector>

#include "solid_gauges.hpp"
#include "solid_interface.hpp"
#include "solid_parameters.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/checkpoint.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/interface_particles.hpp"
#include "sphcore/region.hpp"
#include "sphcore/snapshot_writer.hpp"
#include "sphcore/time_step.hpp"
#include "tl_dynamics.hpp"
#include "tl_particles.hpp"

namespace cosph::solid::tl {

class TLSolver {
 public:
  // Throws sph::ConfigError unless the case's solid.model is total_lagrangian.
  TLSolver(const sph::CaseFile& case_file, const SolidParameters& parameters);

  sph::StepLimits step_limits() const;

  // Advances by dt. Throws sph::RunawayError if the new state is not physical.
  void step(double dt) {
    begin_step(dt);
    end_step(dt);
  }
  // As JaumannSolver: begin_step kicks, drifts and evaluates the solid's own
  // forces; the coupler's accelerations arrive through
  // set_interface_accelerations; end_step kicks.
  void begin_step(double dt);
  void end_step(double dt);

  void collect_interface(const sph::Region& region, sph::InterfaceParticles& out);
  void set_interface_accelerations(const std::vector<Vec2>& accelerations);
  sph::Region interaction_bounds() const;
  double max_smoothing_length() const { return parameters_.h; }
  std::vector<sph::Gauge> gauge_values() const;

  double time() const { return time_; }
  long steps() const { return steps_; }
  const TLParticles& particles() const { return particles_; }
  // For tests: positions and velocities set directly, then update() to
  // recompute F, the stress and the accelerations.
  TLParticles& particles() { return particles_; }
  void update();
  const SolidParameters& parameters() const { return parameters_; }
  const ForceParameters& force_parameters() const { return forces_; }
  SolidGauges gauges() const;
  sph::Snapshot snapshot() const;

  // Everything the next step reads, for a checkpoint; restore() takes it back
  // into a solver built from the same case (tl_checkpoint.cpp).
  void save(sph::Checkpoint& checkpoint) const;
  void restore(const sph::Checkpoint& checkpoint);

 private:
  // Throws sph::RunawayError if a particle's state is not physical.
  void check_state() const;

  SolidInterface interface_;  // the particles of the last collect_interface
  SolidParameters parameters_;
  ForceParameters forces_;
  TLParticles particles_;
  std::vector<int> tip_ids_;
  double time_ = 0.0;
  long steps_ = 0;
};

}  // namespace cosph::solid::tl
