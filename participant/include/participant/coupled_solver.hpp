// What a solver must offer for CoupledRun to drive it: the contract of a
// phase in a coupled run, checked where the template is used, so that a
// solver missing a member fails to compile with a message naming it.
#pragma once

#include <concepts>
#include <vector>

#include "participant/participant.hpp"
#include "sphcore/damped_mode.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/interface_particles.hpp"
#include "sphcore/region.hpp"
#include "sphcore/snapshot_writer.hpp"
#include "sphcore/time_step.hpp"
#include "sphcore/types.hpp"

namespace cosph::coupling {

template <class Solver>
concept CoupledSolver = requires(Solver& solver, const Solver& done, double dt,
                                 const sph::Region& region, sph::InterfaceParticles& out,
                                 const std::vector<sph::Vec2>& accelerations) {
  // A step split where the coupler's cross-phase accelerations are needed:
  // begin_step kicks, drifts and evaluates the solver's own forces, end_step
  // kicks with the accelerations set in between.
  solver.begin_step(dt);
  solver.end_step(dt);
  { done.step_limits() } -> std::convertible_to<sph::StepLimits>;
  // The particles inside `region` out, and the coupler's accelerations for
  // them back, in the same order.
  solver.collect_interface(region, out);
  solver.set_interface_accelerations(accelerations);
  { done.interaction_bounds() } -> std::convertible_to<sph::Region>;
  { done.max_smoothing_length() } -> std::convertible_to<double>;
  // What the coupler writes to timeseries.csv, and the solver to its snapshots.
  { done.gauge_values() } -> std::convertible_to<std::vector<sph::Gauge>>;
  { done.snapshot() } -> std::convertible_to<sph::Snapshot>;
  { done.time() } -> std::convertible_to<double>;
  { done.steps() } -> std::convertible_to<long>;
  { done.particles().size() } -> std::convertible_to<std::size_t>;
};

// Optional: a solver whose step splits where its interface state is complete
// (advance_state: kick, drift, density, stress), and its own forces begin
// (compute_forces), so that the coupler computes the cross-phase terms while
// the solver computes its own.
template <class Solver>
concept SplitsItsStep = requires(Solver& solver, double dt) {
  solver.advance_state(dt);
  solver.compute_forces();
};

// Optional: a solver that presents more interface particles than it has
// particles (the shell: several layers across each mid-line particle) gives
// the most it can send; the Hello announces it, and the coupler sizes the
// states it accepts by it. Without the member: particles().size().
template <class Solver>
concept CountsInterfaceParticles = requires(const Solver& solver) {
  { solver.interface_particle_count() } -> std::convertible_to<std::size_t>;
};

template <class Solver>
std::size_t announced_particle_count(const Solver& solver) {
  if constexpr (CountsInterfaceParticles<Solver>)
    return solver.interface_particle_count();
  else
    return solver.particles().size();
}

// Optional: a solver that may carry no dissipation for its fastest modes
// says so (Hello field undamped_modes); one without the member damps them.
template <class Solver>
concept ReportsUndampedModes = requires(const Solver& solver) {
  { solver.undamped_modes() } -> std::convertible_to<bool>;
};

template <class Solver>
bool has_undamped_modes(const Solver& solver) {
  if constexpr (ReportsUndampedModes<Solver>)
    return solver.undamped_modes();
  else
    return false;
}

// Optional: a solid that damps its modes may state its fastest mode's
// angular frequency and the damping ratio it gives it (Hello fields
// fastest_mode_*), from which the coupler bounds automatic multi-rate
// windows; one without the member states nothing.
template <class Solver>
concept ReportsFastestMode = requires(const Solver& solver) {
  { solver.fastest_mode() } -> std::convertible_to<sph::DampedMode>;
};

template <class Solver>
sph::DampedMode fastest_mode_of(const Solver& solver) {
  if constexpr (ReportsFastestMode<Solver>) {
    return solver.fastest_mode();
  } else {
    return {};
  }
}

}  // namespace cosph::coupling
