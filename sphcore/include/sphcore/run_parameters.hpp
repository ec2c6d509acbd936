// The case's "run" block, validated, with its defaults applied.
#pragma once

#include <cmath>
#include <string>

#include "sphcore/case_file.hpp"
#include "sphcore/types.hpp"

namespace sph {

struct RunParameters {
  double end_time;
  double output_interval;
  double snapshot_interval;
  double cfl;
  Vec2 gravity;
  int threads;  // 0: all cores
  // Simulated time between checkpoints (docs/restart.md); infinite: none.
  double checkpoint_interval = INFINITY;
};

RunParameters read_run_parameters(const CaseFile& case_file);

// A phase's particle spacing dx and smoothing length h = h_factor dx, from its
// block's `spacing` and `h_factor` (1.3 when unset), validated; `block`
// ("fluid", "solid") names the fields in errors.
struct Resolution {
  double dx;
  double h;
};
Resolution read_resolution(const CaseFile& case_file, const std::string& block, double spacing,
                           double h_factor);

}  // namespace sph
