// When a particle loop is worth running on several threads (OpenMP's if
// clause). Every loop of the solvers gives the same result on any number of
// threads, so this decides speed only.
#pragma once

#include <cstddef>

namespace sph {

// Below a few thousand particles a parallel loop costs more in starting
// threads and waiting at its barrier than it saves: on the dam break at 1 182
// particles, two threads took longer per step than one.
inline bool worth_threads(std::size_t particles) {
  return particles >= 4096;
}

}  // namespace sph
