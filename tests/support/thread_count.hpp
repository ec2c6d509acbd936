// A solver's particles after some steps on a given number of OpenMP threads,
// and their comparison: the fluid's and the solid's tests that the thread
// count changes nothing.
#pragma once

#include <gtest/gtest.h>
#include <omp.h>

#include "sphcore/case_file.hpp"
#include "sphcore/parallel.hpp"

namespace cosph::testing {

// The particles of a Solver built from the case after `steps` steps on
// `threads` threads, having checked that its loops do take them. OpenMP's
// thread count is left as it was found.
template <class Solver, class Parameters>
auto particles_after_steps(const sph::CaseFile& case_file, const Parameters& parameters,
                           int threads, int steps) {
  const int threads_before = omp_get_max_threads();
  omp_set_num_threads(threads);
  Solver solver(case_file, parameters);
  EXPECT_EQ(sph::threaded(solver.particles().size()), threads > 1);
  for (int step = 0; step < steps; ++step) solver.step(solver.step_limits().smallest());
  omp_set_num_threads(threads_before);
  return solver.particles();
}

// Asserts that two runs' particles agree to the last bit in every one of
// `fields` (pointers to the particle set's per-particle vectors), naming the
// first particle and field (counted from 1) that differ.
template <class Particles, class... Fields>
void expect_same_particles(const Particles& one, const Particles& two, Fields... fields) {
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    int field = 0;  // the fold stops at the first field that differs
    const bool same = (... && (++field, (one.*fields)[i] == (two.*fields)[i]));
    ASSERT_TRUE(same) << "particle " << one.id[i] << ", field " << field;
  }
}

}  // namespace cosph::testing
