// The runaway check of a solid step, the same for every model: a screen of
// the particles the step visits (clamp_reach.hpp; the others never change)
// that vectorises (sphcore/runaway_screen.hpp), and only when it fails the
// exact tests, which name the first particle that failed them.
#pragma once

#include <sstream>

#include "clamp_reach.hpp"
#include "sphcore/first_runaway.hpp"
#include "sphcore/parallel.hpp"

namespace cosph::solid {

// Throws sph::RunawayError for the first particle i (in index order) whose
// reason(i) is not null, once some particle fails passes_screen(i). The
// message names the particle, where and when, why, its speed against the
// sound speed, then details(i) (which closes the parenthesis) and advice.
template <class Particles, class Screen, class Reason, class Details>
void stop_if_run_away(const Particles& P, double time, long steps, Screen&& passes_screen,
                      Reason&& reason, Details&& details) {
  const bool may_have_run_away = sph::parallel_any(in_reach(P), sph::kTeamAtAnySize,
                                                   [&](long i) { return !passes_screen(i); });
  if (!may_have_run_away) return;
  sph::stop_at_first_runaway(P, "solid particle", time, steps, reason,
                             [&](std::ostringstream& message, std::size_t i) {
                               message << ", sound speed " << P.c[i] << " m/s";
                               details(message, i);
                             });
}

}  // namespace cosph::solid
