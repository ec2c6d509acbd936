// The tests of a runaway check (sph::RunawayError), written for a screen:
// one pass over all particles, on the plain arrays behind Eigen's 2-vectors
// and 2x2 matrices (sph::doubles_of), that the compiler vectorises. Each test
// gives a bool without a branch, to be combined with &, and clears a particle
// only where the exact test clears it too; a solver looks at single particles
// only when its screen fails.
#pragma once

#include "sphcore/types.hpp"

namespace sph::screen {

// A density, or a volume ratio J, outside [kLowest, kHighest] times its rest
// value is far outside weak compressibility or linear elasticity: the run
// has blown up. The exact tests and the screens both use these bounds.
inline constexpr double kLowest = 0.5, kHighest = 2.0;

// x * 0 is 0 for finite x only.
inline bool finite(double value) {
  return value * 0.0 == 0.0;
}

// Both components of 2-vector i finite.
inline bool finite_vector(const double* vectors, long i) {
  return finite(vectors[2 * i]) & finite(vectors[2 * i + 1]);
}

// Every entry of 2x2 matrix i finite: a sum with an infinity or a NaN in it
// is not finite (nor is one that overflows, which only sends the solver to
// the exact test).
inline bool finite_matrix(const double* matrices, long i) {
  const double* m = matrices + 4 * i;
  return finite((m[0] + m[1]) + (m[2] + m[3]));
}

// |v_i| clearly below `limit`: |v_i|^2 <= 0.98 limit^2. Within 1 % of the
// limit, the exact test (on the norm, rounded differently from the square)
// decides. False for a v that is not finite.
inline bool clearly_slower(const double* velocities, long i, double limit) {
  const double v_x = velocities[2 * i], v_y = velocities[2 * i + 1];
  return v_x * v_x + v_y * v_y <= 0.98 * limit * limit;
}

// lowest <= value <= highest; false for NaN.
inline bool within(double value, double lowest, double highest) {
  return (value >= lowest) & (value <= highest);
}

}  // namespace sph::screen
