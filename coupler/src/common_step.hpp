// The coupler's choice of the common step (the coupling window) from the two
// solvers' proposals. Synchronised (max_substeps 1): the smaller proposal, so
// that both take the same steps. Multi-rate: the larger proposal, but no more
// than max_substeps times the smaller, and each solver covers the window in as
// many sub-steps as its own stability needs (participant/coupled_run.hpp).
#pragma once

#include <algorithm>

namespace cosph::coupler {

inline double common_step(double proposed_a, double proposed_b, int max_substeps) {
  const double smaller = std::min(proposed_a, proposed_b);
  const double larger = std::max(proposed_a, proposed_b);
  return max_substeps <= 1 ? smaller : std::min(larger, max_substeps * smaller);
}

}  // namespace cosph::coupler
