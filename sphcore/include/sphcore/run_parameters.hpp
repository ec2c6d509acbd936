// The case's "run" block, validated, with its defaults applied.
#pragma once

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
};

RunParameters read_run_parameters(const CaseFile& case_file);

}  // namespace sph

namespace sph {

// OpenMP threads for a run: `requested` if positive; otherwise one per 4000
// particles, at most omp_get_max_threads() (which OMP_NUM_THREADS bounds):
// below that size a thread costs more in synchronisation than it saves.
int choose_threads(int requested, std::size_t particles);

}  // namespace sph
