// The runaway check of a solid step, the same for every model: a screen of
// all particles that vectorises (sphcore/runaway_screen.hpp), and only when
// it fails the exact tests, which name the first particle that failed them.
#pragma once

#include <sstream>
#include <string>

#include "sphcore/parallel.hpp"
#include "sphcore/runaway_error.hpp"

namespace cosph::solid {

// Throws sph::RunawayError for the first particle i (in index order) whose
// reason(i) is not null, once some particle fails passes_screen(i). The
// message names the particle, where and when, why, its speed against the
// sound speed, then details(i) (which closes the parenthesis) and advice.
template <class Particles, class Screen, class Reason, class Details>
void stop_if_run_away(const Particles& P, double time, long steps, Screen&& passes_screen,
                      Reason&& reason, Details&& details) {
  const bool may_have_run_away =
      sph::parallel_any(P.size(), sph::kTeamAtAnySize, [&](long i) { return !passes_screen(i); });
  if (!may_have_run_away) return;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const char* why = reason(i);
    if (why == nullptr) continue;
    std::ostringstream message;
    message << "solid particle " << P.id[i] << " at (" << P.x[i].x() << ", " << P.x[i].y()
            << ") m, t = " << time << " s, step " << steps << ": " << why << " (speed "
            << P.v[i].norm() << " m/s, sound speed " << P.c[i] << " m/s";
    details(message, i);
    throw sph::RunawayError(message.str());
  }
}

}  // namespace cosph::solid
