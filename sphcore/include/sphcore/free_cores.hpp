// How much of the machine other processes leave to this one: the CPU time the
// whole machine spent busy (/proc/stat, steal time included, as a virtual
// machine's host takes it) less this process's own (getrusage), per second of
// wall time, between two samples. A solver's loops end at barriers that wait
// for their slowest thread, so a thread whose core another process holds
// stalls every loop: the thread count follows the cores that are free.
#pragma once

#include <chrono>
#include <functional>
#include <istream>

namespace sph {

// Seconds since some fixed point; wall time, and CPU time summed over cores.
struct CpuTimes {
  double wall = 0.0;
  double machine_busy = 0.0;  // every process on every core, this one included
  double own = 0.0;           // this process, all its threads
};

// Now. Without /proc/stat, machine_busy is taken to be this process's own.
CpuTimes cpu_times_now();

// The cores left by other processes between the two samples: `cores` less
// their CPU time per second of wall time, never below 0 nor above `cores`.
double cores_left_by_others(const CpuTimes& earlier, const CpuTimes& later, int cores);

// The threads other processes have running or ready to run at this instant:
// /proc/stat's procs_running (every runnable thread of the machine) less the
// one reading it. Negative when it cannot be read.
double runnable_others(std::istream& proc_stat);

// The least of `readings` of read(), `apart` from each other; negative if one
// is. A thread runnable for an instant (the launcher reading a pipe, a shell
// drawing its prompt) holds no core, yet one reading that caught it would
// keep a run on one thread until its first look again, a second later.
double least_runnable_others(const std::function<double()>& read, int readings,
                             std::chrono::microseconds apart);
inline constexpr int kFirstLookReadings = 5;
inline constexpr std::chrono::microseconds kFirstLookApart{1000};
// /proc/stat's runnable others now, as least_runnable_others takes them.
double runnable_others_now();

// The cores `runnable_others` leave, never below 0 nor above `cores`.
double cores_left_now(double runnable_others, int cores);

// Each call of cores_left(): the cores of the machine that other processes
// left over the time since the call before (the first: since construction).
// /proc/stat counts CPU time in ticks of 10 ms, and two cores give only 20 of
// them in 0.1 s: over a window shorter than kShortestWindow (a solver's first
// look, as it starts) the meter takes the threads runnable at that instant
// instead, and measures its next window from where this one began. Waiting
// the window out would cost every short run 0.1 s.
class FreeCoreMeter {
 public:
  static constexpr double kShortestWindow = 0.1;  // s

  FreeCoreMeter();
  double cores_left();

 private:
  int cores_;
  CpuTimes last_;
};

}  // namespace sph
