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

#include "continuum_solid_solver.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/checkpoint.hpp"
#include "sphcore/snapshot_writer.hpp"
#include "tl_dynamics.hpp"
#include "tl_particles.hpp"

namespace cosph::solid::tl {

class TLSolver : public ContinuumSolidSolver<TLSolver, TLParticles, &TLParticles::X> {
 public:
  // Throws sph::ConfigError unless the case's solid.model is total_lagrangian.
  TLSolver(const sph::CaseFile& case_file, const SolidParameters& parameters);

  // As JaumannSolver: begin_step kicks, drifts and evaluates the solid's own
  // forces; the coupler's accelerations arrive through
  // set_interface_accelerations; end_step (ContinuumSolidSolver) kicks.
  void begin_step(double dt);

  // For tests: positions and velocities set directly (particles()), then
  // update() to recompute F, the stress and the accelerations.
  void update();
  const ForceParameters& force_parameters() const { return forces_; }
  SolidGauges gauges() const;
  sph::Snapshot snapshot() const;

  // Everything the next step reads, for a checkpoint; restore() takes it back
  // into a solver built from the same case (tl_checkpoint.cpp).
  void save(sph::Checkpoint& checkpoint) const;
  void restore(const sph::Checkpoint& checkpoint);

 private:
  friend ContinuumSolidSolver;
  // Throws sph::RunawayError if a particle's state is not physical.
  void check_state() const;

  ForceParameters forces_;
};

}  // namespace cosph::solid::tl
