// The case's "run" block, validated, with its defaults applied.
#pragma once

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

namespace sph {

// OpenMP threads for a run: `requested` if positive; otherwise one per 4000
// particles, at most `available` (omp_get_max_threads() before the run set
// it, which OMP_NUM_THREADS bounds): below that size a thread costs more in
// synchronisation than it saves.
int choose_threads(int requested, std::size_t particles, int available);

// The threads of a solver's run, set in two steps because choose_threads needs
// the particle count and building the solver already runs its loops: it is
// built on one thread (or on the requested count), then settle() sets the
// run's. Built on the default team instead, a solver that then ran on fewer
// threads kept the extra thread for the whole run, spinning on a core under
// OMP_WAIT_POLICY=active.
class RunThreads {
 public:
  explicit RunThreads(int requested);  // call before building the solver
  int settle(std::size_t particles);   // after; returns the run's thread count

 private:
  int requested_;
  int available_;
};

}  // namespace sph
