// The OpenMP threads of a solver's run. Every loop of the solvers ends at a
// barrier that waits for its slowest thread; a thread whose core another
// process holds gets a scheduler time slice now and then, and each loop then
// waits for one: with one outside busy loop on two cores, the dam break at
// 22 000 particles ran 63 times slower on two threads than on a quiet
// machine. So a run takes no more threads than the cores other processes
// leave free, and looks again every second while it runs. Results are the
// same bits on any thread count, so a change of count changes speed only.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>

namespace sph {

// A core counts as free while other processes use less than this share of it.
inline constexpr double kBusyCoreShare = 0.25;

// OpenMP threads for a run: `requested` if positive; otherwise one per 4000
// particles (below that a thread costs more in synchronisation than it
// saves), at most `available` (omp_get_max_threads() before the run set it,
// which OMP_NUM_THREADS and the process's cores bound) and at most the free
// cores in `cores_left` (the cores other processes left), at least one.
int choose_threads(int requested, std::size_t particles, int available, double cores_left);

// Set in two steps because choose_threads needs the particle count and
// building the solver already runs its loops: it is built on one thread (or
// on the requested count), then settle() sets the run's; revise(), called
// after every step, chooses again once a second. Built on the default team
// instead, a solver that then ran on fewer threads kept the extra thread for
// the whole run, spinning on a core under OMP_WAIT_POLICY=active.
class RunThreads {
 public:
  // cores_left(): the cores other processes left since its last call
  // (sph::FreeCoreMeter by default).
  using CoresLeft = std::function<double()>;
  static constexpr std::chrono::seconds kRevisionPeriod{1};

  explicit RunThreads(int requested);  // call before building the solver
  RunThreads(int requested, CoresLeft cores_left);
  int settle(std::size_t particles);  // after; returns the run's thread count
  int revise();                       // cheap unless a second has passed
  int revise_now();                   // chooses again at once; returns the count

 private:
  int requested_;
  int available_;
  CoresLeft cores_left_;
  std::size_t particles_ = 0;
  int threads_ = 1;
  std::chrono::steady_clock::time_point next_revision_{};
};

}  // namespace sph
