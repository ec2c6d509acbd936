#include "sphcore/run_control.hpp"

#include <atomic>
#include <csignal>
#include <cstdio>

namespace sph {
namespace {
std::atomic<bool> stop_flag{false};
extern "C" void on_stop_signal(int) {
  stop_flag.store(true);
}
}  // namespace

void install_stop_handlers() {
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
}

bool stop_requested() {
  return stop_flag.load();
}

void ProgressReporter::report(double t, long step, double dt, bool force) {
  const auto now = std::chrono::steady_clock::now();
  if (!force && now - last_ < std::chrono::milliseconds(500)) return;
  last_ = now;
  std::printf("progress t=%.6g end=%.6g step=%ld dt=%.3g\n", t, end_time_, step, dt);
  std::fflush(stdout);
}

}  // namespace sph
