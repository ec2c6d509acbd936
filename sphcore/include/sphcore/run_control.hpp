// What a running solver shares with the outside: Ctrl-C / SIGTERM ask it to
// stop after the current step (writing a final snapshot), and a progress line
// on stdout that the launcher turns into a status display.
#pragma once

#include <chrono>

namespace sph {

// Installs SIGINT and SIGTERM handlers that set a flag; stop_requested() reads it.
void install_stop_handlers();
bool stop_requested();

// Prints "progress t=... end=... step=... dt=..." at most twice a second.
class ProgressReporter {
 public:
  explicit ProgressReporter(double end_time) : end_time_(end_time) {}
  void report(double t, long step, double dt, bool force = false);

 private:
  double end_time_;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace sph
