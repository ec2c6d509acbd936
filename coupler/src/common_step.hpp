// The coupler's choice of the common step (the coupling window) from the two
// solvers' proposals. Synchronised (max_substeps 1): the smaller proposal, so
// that both take the same steps. Multi-rate: the larger proposal, but no more
// than max_substeps times the smaller, and each solver covers the window in as
// many sub-steps as its own stability needs (participant/coupled_run.hpp).
// max_window, the bound the solid's damping sets (substep_choice.hpp), caps a
// multi-rate window but never below the smaller proposal: at that length the
// window is synchronised.
#pragma once

#include <algorithm>
#include <limits>

namespace cosph::coupler {

inline double common_step(double proposed_a, double proposed_b, int max_substeps,
                          double max_window = std::numeric_limits<double>::infinity()) {
  const double smaller = std::min(proposed_a, proposed_b);
  const double larger = std::max(proposed_a, proposed_b);
  if (max_substeps <= 1) return smaller;
  return std::min({larger, max_substeps * smaller, std::max(max_window, smaller)});
}

}  // namespace cosph::coupler
