// The parts of a kick-drift-kick step that both solid models take alike, on
// any particle store with x, v, a, external_a (the coupler's share), c,
// clamped and reach_end: what the step may be, the kicks and the drift. A
// clamped particle never moves, and those past in_reach (clamp_reach.hpp)
// are not visited.
#pragma once

#include <array>
#include <cmath>

#include "clamp_reach.hpp"
#include "solid_parameters.hpp"
#include "sphcore/parallel.hpp"
#include "sphcore/region.hpp"
#include "sphcore/time_step.hpp"
#include "wall_contact.hpp"

namespace cosph::solid {

// The largest step the solid allows now (sph::step_limits).
template <class Particles>
sph::StepLimits solid_step_limits(const Particles& P, const SolidParameters& parameters) {
  const auto [v_max2, a_max2, c_max] =
      sph::parallel_max(in_reach(P), std::array{0.0, 0.0, 0.0}, sph::kTeamAtAnySize, [&](long i) {
        return std::array{P.v[i].squaredNorm(), P.a[i].squaredNorm(), P.c[i]};
      });
  return sph::step_limits(parameters.run.cfl, parameters.h, c_max, std::sqrt(v_max2),
                          std::sqrt(a_max2), 0.0);
}

// The opening kick and the drift of particle i, which solid.walls stop.
template <class Particles>
void kick_and_drift(Particles& P, long i, double dt, const SolidParameters& parameters) {
  P.v[i] += (0.5 * dt) * (P.a[i] + P.external_a[i]);
  P.x[i] += dt * P.v[i];
  for (const SolidWall& wall : parameters.walls) push_out_of_wall(wall, P.x[i], P.v[i]);
}

// The closing kick, with the accelerations of the new state, which it keeps
// in kick_a: the acceleration the coupler's moving wall takes at the next
// exchange (docs/physics.md, "Moving wall").
template <class Particles>
void closing_kick(Particles& P, double dt) {
  const double half = 0.5 * dt;
  sph::parallel_for(in_reach(P), sph::kTeamAtAnySize, [&](long i) {
    P.kick_a[i] = P.clamped[i] ? Vec2::Zero() : Vec2(P.a[i] + P.external_a[i]);
    P.v[i] += half * P.kick_a[i];
  });
}

}  // namespace cosph::solid
