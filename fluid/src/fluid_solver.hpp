// The fluid solver: owns the water and wall particles and advances them by
// kick-drift-kick, one force evaluation per step (docs/physics.md, "Time step").
//
// Step from t to t + dt, with a known at t:
//   v   += dt/2 a                         (kick)
//   x   += dt v,  rho += dt drho/dt(v)    (drift: density moves with positions)
//   a    = a(x, rho)                      (the one force evaluation)
//   v   += dt/2 a                         (kick)
// Density is drifted with the half-step velocity, not kicked alongside it: the
// sound waves of weak compressibility trade energy between rho and v, and
// updating both from the same old state would amplify them every step.
#pragma once

#include "equation_of_state.hpp"
#include "fluid_parameters.hpp"
#include "fluid_particles.hpp"
#include "gauges.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/checkpoint.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/interface_particles.hpp"
#include "sphcore/neighbour_list.hpp"
#include "sphcore/particle_solver.hpp"
#include "sphcore/region.hpp"
#include "sphcore/snapshot_writer.hpp"
#include "sphcore/sorted_verlet_list.hpp"
#include "sphcore/time_step.hpp"

namespace cosph::fluid {

class FluidSolver : public sph::ParticleSolver<FluidSolver, FluidParticles, FluidParameters> {
 public:
  FluidSolver(const sph::CaseFile& case_file, const FluidParameters& parameters);

  // The largest step the fluid allows now.
  sph::StepLimits step_limits() const;
  // The largest water speed step_limits has seen in this process (a restart
  // starts it again), m/s.
  double fastest_water() const { return fastest_water_; }

  // A coupled step is split where the coupler's answer is needed:
  // begin_step kicks, drifts and evaluates the water's own forces at the new
  // positions; then the coupler gets the interface and answers with the
  // cross-phase accelerations (set_interface_accelerations); end_step kicks.
  // begin_step is advance_state (kick, drift, density, pressure: all the
  // interface carries) and then compute_forces, so that a coupled run can
  // send the interface between the two (participant/coupled_run.hpp).
  void begin_step(double dt);
  void advance_state(double dt);
  void compute_forces();  // the wall pressure and the water's own accelerations
  void end_step(double dt);

  // The water particles inside `region`, as the coupler needs them.
  void collect_interface(const sph::Region& region, sph::InterfaceParticles& out);
  // Accelerations for the particles of the last collect_interface, in its
  // order; every other particle gets none.
  void set_interface_accelerations(const std::vector<Vec2>& accelerations);
  // The same for the solid's share in the water's continuity (moving walls).
  void set_interface_density_rates(const std::vector<double>& density_rates);
  // Where water is (the box around every water particle).
  sph::Region interaction_bounds() const;
  std::vector<sph::Gauge> gauge_values() const;

  // How many times the particles were sorted and the Verlet list rebuilt.
  long sorts() const { return sorts_; }
  // Water particles that left as thinned spray (is_thinned_spray).
  long spray_removed() const { return spray_removed_; }
  // The pairs within 2h of the last step, listed at its start.
  const sph::NeighbourList& pairs() const { return pairs_; }
  WaterGauges gauges() const { return measure(particles_, parameters_); }
  // The force of the water on each of fluid.walls, N/m (forces_on_walls), at
  // the last force evaluation.
  std::vector<Vec2> wall_forces() const;
  sph::Snapshot snapshot() const;

  // Everything the next step reads, for a checkpoint; restore() takes it back
  // into a solver built from the same case (fluid_checkpoint.cpp).
  void save(sph::Checkpoint& checkpoint) const;
  void restore(const sph::Checkpoint& checkpoint);

 private:
  // Lists this step's pairs from the Verlet list, first re-sorting the
  // particles and rebuilding that list if it may have missed one.
  void find_neighbours(bool sort);
  void update_pressure();
  // Puts moving wall particle i where its wall is at time t, with its
  // acceleration there, and the wall's velocity at t_velocity (exact, from
  // WallMotion).
  void place_moving_wall(std::size_t i, double t, double t_velocity);
  void check_state() const;
  // False when every particle passes runaway_reason's tests with room to
  // spare (a cheap screen, sph::screen); true when one may fail them.
  bool may_have_run_away() const;
  // Why particle i's state is not physical, or nullptr if it is (or is a wall,
  // or thinned spray).
  const char* runaway_reason(std::size_t i) const;
  // Water with no wall and no solid in reach and too little water around it
  // to renormalise (FluidParticles::spray): spray thrown off the flow, a
  // droplet of a few particles or a sheet one particle thick.
  bool is_spray(std::size_t i) const;
  // Spray thinned below the runaway density bound. Continuity keeps thinning
  // such a particle as its few neighbours fly apart, yet a real droplet keeps
  // the density of water: the value has lost its meaning, so it is no sign of
  // a blow-up. Such a particle leaves the water at the end of its step
  // (DualSPHysics likewise excludes particles whose density leaves a range);
  // the timeseries counts them. More than 1 % of the water in one step is a
  // blow-up.
  // Water in reach of a boundary, a wall or the solid, is never spray: its
  // density must answer when it meets that boundary.
  bool is_thinned_spray(std::size_t i) const;
  void remove_thinned_spray();

  std::vector<long> interface_index_;  // particle indices of the last collect_interface
  TaitEquationOfState eos_;
  sph::SortedVerletList verlet_;
  std::vector<int> walls_in_reach_;  // of the water at the last sort (walls_in_reach)
  long sorts_ = 0;
  bool spray_left_ = false;  // particles left since the last sort
  long spray_removed_ = 0;
  // Taken before a spray removal, while the lists still matched the indices:
  // the wall forces until the next step.
  std::vector<Vec2> wall_forces_before_removal_;
  sph::NeighbourList pairs_;
  // Kept by step_limits, which finds each step's fastest water anyway.
  mutable double fastest_water_ = 0.0;
};

}  // namespace cosph::fluid
