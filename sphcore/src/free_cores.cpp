#include "sphcore/free_cores.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <thread>

namespace sph {
namespace {

double seconds_of(const timeval& t) {
  return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
}

double own_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return seconds_of(usage.ru_utime) + seconds_of(usage.ru_stime);
}

// The first line of /proc/stat: "cpu user nice system idle iowait irq softirq
// steal guest guest_nice" in clock ticks; guest time is counted in user
// already. Negative when it cannot be read.
double machine_busy_seconds() {
  std::ifstream stat("/proc/stat");
  std::string label;
  double user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0, steal = 0;
  if (!(stat >> label >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal) ||
      label != "cpu")
    return -1.0;
  return (user + nice + system + irq + softirq + steal) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

}  // namespace

CpuTimes cpu_times_now() {
  CpuTimes now;
  now.wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  now.own = own_cpu_seconds();
  const double busy = machine_busy_seconds();
  now.machine_busy = busy < 0.0 ? now.own : busy;
  return now;
}

double cores_left_by_others(const CpuTimes& earlier, const CpuTimes& later, int cores) {
  const double wall = later.wall - earlier.wall;
  if (wall <= 0.0) return cores;
  const double others =
      ((later.machine_busy - earlier.machine_busy) - (later.own - earlier.own)) / wall;
  return std::clamp(cores - others, 0.0, static_cast<double>(cores));
}

FreeCoreMeter::FreeCoreMeter()
    : cores_(static_cast<int>(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)))),
      last_(cpu_times_now()) {}

double runnable_others(std::istream& proc_stat) {
  std::string label;
  double count = 0.0;
  while (proc_stat >> label) {
    if (label == "procs_running") return proc_stat >> count ? std::max(0.0, count - 1.0) : -1.0;
    proc_stat.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  return -1.0;
}

double least_runnable_others(const std::function<double()>& read, int readings,
                             std::chrono::microseconds apart) {
  double least = -1.0;
  for (int k = 0; k < readings; ++k) {
    if (k > 0) std::this_thread::sleep_for(apart);
    const double now = read();
    if (now < 0.0) return now;
    least = k == 0 ? now : std::min(least, now);
  }
  return least;
}

double runnable_others_now() {
  return least_runnable_others(
      [] {
        std::ifstream stat("/proc/stat");
        return runnable_others(stat);
      },
      kFirstLookReadings, kFirstLookApart);
}

double cores_left_now(double runnable_others, int cores) {
  if (runnable_others < 0.0) return cores;
  return std::clamp(cores - runnable_others, 0.0, static_cast<double>(cores));
}

double FreeCoreMeter::cores_left() {
  const CpuTimes now = cpu_times_now();
  if (now.wall - last_.wall < kShortestWindow) return cores_left_now(runnable_others_now(), cores_);
  const double left = cores_left_by_others(last_, now, cores_);
  last_ = now;
  return left;
}

}  // namespace sph
