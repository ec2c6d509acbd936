// How every solver stops a run that has blown up (sph::RunawayError): at the
// first particle, in index order, whose state is not physical, named with
// where and when, why, and how fast it moves. A solver calls this once its
// screen (runaway_screen.hpp) fails, so the exact tests run on few steps.
#pragma once

#include <cstddef>
#include <sstream>

#include "sphcore/parallel.hpp"
#include "sphcore/runaway_error.hpp"

namespace sph {

// Throws sph::RunawayError for the first particle i whose reason(i) is not
// null; returns if there is none. P has id, x and v; `what` names its
// particles ("water particle"); details(message, i) adds the model's own
// numbers after the speed, closes the parenthesis and gives advice.
template <class Particles, class Reason, class Details>
void stop_at_first_runaway(const Particles& P, const char* what, double time, long steps,
                           Reason&& reason, Details&& details) {
  const long first = parallel_find_first(
      P.size(), [&](long i) { return reason(static_cast<std::size_t>(i)) != nullptr; });
  if (first == static_cast<long>(P.size())) return;
  const std::size_t i = static_cast<std::size_t>(first);
  std::ostringstream message;
  message << what << " " << P.id[i] << " at (" << P.x[i].x() << ", " << P.x[i].y()
          << ") m, t = " << time << " s, step " << steps << ": " << reason(i) << " (speed "
          << P.v[i].norm() << " m/s";
  details(message, i);
  throw RunawayError(message.str());
}

}  // namespace sph
