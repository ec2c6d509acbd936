// What the solid models whose particles fill the body (the Jaumann and the
// total-Lagrangian solid) do alike around their own stress: the tip gauge,
// the walls they watch (unmet_walls.hpp), the step limits and the closing
// kick (kick_drift_kick.hpp), the interface the coupler reads, and the
// timeseries columns. Particles carry id, x, v, a, external_a, m, rho, c,
// sigma and clamped; kReference names their initial positions. The solver
// gives gauges() and check_state() (a friend of this base).
#pragma once

#include <utility>
#include <vector>

#include "kick_drift_kick.hpp"
#include "solid_gauges.hpp"
#include "solid_interface.hpp"
#include "solid_parameters.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/interface_particles.hpp"
#include "sphcore/particle_solver.hpp"
#include "sphcore/region.hpp"
#include "sphcore/time_step.hpp"
#include "unmet_walls.hpp"

namespace cosph::solid {

template <class Derived, class Particles, std::vector<Vec2> Particles::*kReference>
class ContinuumSolidSolver : public sph::ParticleSolver<Derived, Particles, SolidParameters> {
  using Base = sph::ParticleSolver<Derived, Particles, SolidParameters>;

 public:
  // The largest step the solid allows now.
  sph::StepLimits step_limits() const {
    return solid_step_limits(this->particles_, this->parameters_);
  }

  // The closing kick with the coupler's accelerations of this step, then the
  // runaway and wall checks.
  void end_step(double dt) {
    closing_kick(this->particles_, dt);
    this->time_ += dt;
    ++this->steps_;
    self().check_state();
    stop_if_in_unmet_wall(this->particles_, this->parameters_.unmet_walls, this->time_,
                          this->steps_);
  }

  // The solid particles inside `region` (clamped ones too: water presses on them).
  void collect_interface(const sph::Region& region, sph::InterfaceParticles& out) {
    interface_.collect(this->particles_, this->parameters_.h, region, out);
  }
  // Accelerations for the particles of the last collect_interface, in its order.
  void set_interface_accelerations(const std::vector<Vec2>& accelerations) {
    interface_.scatter(accelerations, this->particles_.external_a);
  }
  sph::Region interaction_bounds() const { return sph::bounds_of(this->particles_.x); }

  std::vector<sph::Gauge> gauge_values() const {
    const Particles& P = this->particles_;
    std::vector<sph::Gauge> values = named_gauges(self().gauges());
    for (const sph::Gauge& gauge : broken_part_gauges(this->parameters_.broken_part_below_y,
                                                      P.*kReference, P.x, P.m, P.clamped))
      values.push_back(gauge);
    return values;
  }

 protected:
  ContinuumSolidSolver(const SolidParameters& parameters, Particles particles)
      : Base(parameters, std::move(particles)) {
    const Particles& P = this->particles_;
    SolidParameters& par = this->parameters_;
    if (par.tip_gauge) tip_ids_ = tip_gauge_ids(P.id, P.*kReference, *par.tip_gauge, par.dx);
    par.unmet_walls = walls_no_free_particle_is_inside(P.x, P.clamped, par.unmet_walls);
  }

  std::vector<int> tip_ids_;

 private:
  Derived& self() { return static_cast<Derived&>(*this); }
  const Derived& self() const { return static_cast<const Derived&>(*this); }

  SolidInterface interface_;  // the particles of the last collect_interface
};

}  // namespace cosph::solid
