// The time loop of a solver that runs alone (no coupler): steps at the solver's
// own stable step until the end time, writes timeseries.csv and the snapshots,
// stops cleanly on Ctrl-C, and, if the state blows up, keeps the last good
// state it measured as NAME_last_good.h5 and says so.
//
// Solver needs: step_limits(), step(dt), time(), steps(), snapshot().
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sphcore/run_control.hpp"
#include "sphcore/run_parameters.hpp"
#include "sphcore/run_threads.hpp"
#include "sphcore/runaway_error.hpp"
#include "sphcore/snapshot_writer.hpp"
#include "sphcore/timeseries_writer.hpp"

namespace sph {

template <class Solver>
class StandaloneRun {
 public:
  // row(solver, dt) gives the values of the columns after "t" and "dt".
  using Row = std::function<std::vector<double>(const Solver&)>;

  StandaloneRun(Solver& solver, const RunParameters& run, const std::string& out_dir,
                const std::string& name, std::vector<Column> columns, Row row)
      : solver_(solver),
        run_(run),
        snapshots_(out_dir, name),
        timeseries_(out_dir + "/timeseries.csv", with_time(std::move(columns))),
        row_(std::move(row)) {}

  // After every step, threads.revise(): the thread count follows the free cores.
  void revise_threads_with(RunThreads& threads) { threads_ = &threads; }

  // Returns 0 when the end time was reached, 130 when stopped by a signal.
  int run() {
    ProgressReporter progress(run_.end_time);
    double next_output = 0.0, next_snapshot = 0.0, dt = 0.0;
    for (;;) {
      const double t = solver_.time();
      // The end time counts as reached within a hundredth of a step.
      const bool finished = t >= run_.end_time - 1e-9 * run_.end_time;
      if (t >= next_output || finished) {
        write_row(dt);
        last_good_ = solver_.snapshot();
        last_good_time_ = t;
        next_output += run_.output_interval;
      }
      if (t >= next_snapshot || finished) {
        snapshots_.write(*last_good_, t);
        next_snapshot += run_.snapshot_interval;
      }
      if (finished) break;
      if (stop_requested()) {
        snapshots_.write(solver_.snapshot(), t);
        return 130;
      }
      dt = std::min(solver_.step_limits().smallest(), run_.end_time - t);
      try {
        solver_.step(dt);
      } catch (const RunawayError& error) {
        const std::string path = snapshots_.write_extra(*last_good_, last_good_time_, "last_good");
        throw RunawayError(std::string(error.what()) + ". Last good state (t = " +
                           std::to_string(last_good_time_) + " s) kept in " + path);
      }
      if (threads_ != nullptr) threads_->revise();
      progress.report(solver_.time(), solver_.steps(), dt);
    }
    progress.report(solver_.time(), solver_.steps(), dt, true);
    return 0;
  }

 private:
  static std::vector<Column> with_time(std::vector<Column> columns) {
    columns.insert(columns.begin(), {{"t", "s"}, {"dt", "s"}});
    return columns;
  }

  void write_row(double dt) {
    std::vector<double> values{solver_.time(), dt};
    const std::vector<double> rest = row_(solver_);
    values.insert(values.end(), rest.begin(), rest.end());
    timeseries_.write_row(values);
  }

  Solver& solver_;
  RunParameters run_;
  SnapshotWriter snapshots_;
  TimeSeriesWriter timeseries_;
  Row row_;
  RunThreads* threads_ = nullptr;
  std::optional<Snapshot> last_good_;
  double last_good_time_ = 0.0;
};

}  // namespace sph
