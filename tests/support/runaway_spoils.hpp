// The test of a solver's runaway check: spoil one particle's state at a time
// and see whether the next end_step stops with sph::RunawayError. The check
// screens all particles in one vectorised pass before it looks at any one of
// them (sph::screen), so each spoil is tried on particles in the pass's first
// lane, its middle and its remainder.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "sphcore/runaway_error.hpp"

namespace cosph::testing {

template <class Particles>
struct Spoil {
  const char* what;
  std::function<void(Particles&, std::size_t)> apply;
  bool stops;  // whether the check must stop the run
};

// make_solver() builds a fresh solver; end_step(0.0) moves nothing and runs
// the check.
template <class MakeSolver, class Particles>
void expect_exactly_the_runaways_stop(const MakeSolver& make_solver,
                                      const std::vector<Spoil<Particles>>& spoils,
                                      const std::vector<std::size_t>& particles) {
  for (const std::size_t i : particles)
    for (const Spoil<Particles>& spoil : spoils) {
      auto solver = make_solver();
      spoil.apply(solver.particles(), i);
      if (spoil.stops)
        EXPECT_THROW(solver.end_step(0.0), sph::RunawayError) << spoil.what << ", particle " << i;
      else
        EXPECT_NO_THROW(solver.end_step(0.0)) << spoil.what << ", particle " << i;
    }
}

}  // namespace cosph::testing
