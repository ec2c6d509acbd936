// The time loop of a solver that runs alone (no coupler): steps at the solver's
// own stable step until the end time, writes timeseries.csv and the snapshots,
// stops cleanly on Ctrl-C, and, if the state blows up, keeps the last good
// state it measured as NAME_last_good.h5 and says so. A Checkpointable solver
// also writes a checkpoint every run.checkpoint_interval and on Ctrl-C, and
// resumes from one (docs/restart.md).
//
// Solver needs: step_limits(), step(dt), time(), steps(), snapshot().
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sphcore/checkpoint.hpp"
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
        out_dir_(out_dir),
        name_(name),
        snapshots_(out_dir, name),
        columns_(with_time(std::move(columns))),
        row_(std::move(row)) {}

  // Checkpoints as `settings` says (a solver that is not Checkpointable writes none).
  void checkpoint_with(CheckpointSettings settings) { checkpoints_ = std::move(settings); }

  // After every step, threads.revise(): the thread count follows the free cores.
  void revise_threads_with(RunThreads& threads) { threads_ = &threads; }

  // Returns 0 when the end time was reached, 130 when stopped by a signal.
  int run() {
    ProgressReporter progress(run_.end_time);
    if (checkpoints_.resume_from.empty())
      timeseries_.emplace(out_dir_ + "/timeseries.csv", columns_);
    else
      resume();
    double dt = 0.0;
    // A resumed run's first state is its checkpoint's, whose outputs were
    // written before it was taken.
    bool outputs_done = !checkpoints_.resume_from.empty();
    for (;;) {
      const double t = solver_.time();
      // The end time counts as reached within a hundredth of a step.
      const bool finished = t >= run_.end_time - 1e-9 * run_.end_time;
      if (outputs_done && !finished) {
        outputs_done = false;
      } else {
        write_outputs(t, dt, finished);
        if (finished) break;
        if (t >= next_checkpoint_) {
          write_checkpoint();
          next_checkpoint_ += run_.checkpoint_interval;
        }
      }
      if (stop_requested()) {
        write_checkpoint();
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
  void write_outputs(double t, double dt, bool finished) {
    if (t >= next_output_ || finished) {
      write_row(dt);
      last_good_ = solver_.snapshot();
      last_good_time_ = t;
      next_output_ += run_.output_interval;
    }
    if (t >= next_snapshot_ || finished) {
      snapshots_.write(*last_good_, t);
      next_snapshot_ += run_.snapshot_interval;
    }
  }

  static std::vector<Column> with_time(std::vector<Column> columns) {
    columns.insert(columns.begin(), {{"t", "s"}, {"dt", "s"}});
    return columns;
  }

  void write_row(double dt) {
    std::vector<double> values{solver_.time(), dt};
    const std::vector<double> rest = row_(solver_);
    values.insert(values.end(), rest.begin(), rest.end());
    timeseries_->write_row(values);
  }

  // After the outputs due at the solver's time: a resumed run starts with the
  // step that follows.
  void write_checkpoint() {
    if constexpr (Checkpointable<Solver>) {
      if (solver_.steps() == last_checkpoint_steps_) return;  // taken at this state already
      last_checkpoint_steps_ = solver_.steps();
      Checkpoint checkpoint;
      solver_.save(checkpoint);
      snapshots_.save(checkpoint);
      checkpoint.put_count("timeseries_rows", static_cast<long>(timeseries_->rows()));
      checkpoint.put_value("next_output", next_output_);
      checkpoint.put_value("next_snapshot", next_snapshot_);
      checkpoint.put_value("next_checkpoint", next_checkpoint_);
      put_intervals(checkpoint, run_);
      checkpoint.write(out_dir_, name_, solver_.steps(), checkpoints_.identity);
    }
  }

  void resume() {
    if constexpr (Checkpointable<Solver>) {
      const Checkpoint checkpoint =
          Checkpoint::read(checkpoints_.resume_from, checkpoints_.identity);
      solver_.restore(checkpoint);
      snapshots_.restore(checkpoint);
      timeseries_.emplace(out_dir_ + "/timeseries.csv", columns_,
                          TimeSeriesWriter::ContinueAfter{
                              static_cast<std::size_t>(checkpoint.count("timeseries_rows"))});
      next_output_ = checkpoint.value("next_output");
      next_snapshot_ = checkpoint.value("next_snapshot");
      next_checkpoint_ = checkpoint.value("next_checkpoint");
      take_intervals(checkpoint, run_);
      last_good_ = solver_.snapshot();
      last_good_time_ = solver_.time();
    } else {
      throw ConfigError(checkpoints_.resume_from + ": this solver cannot resume from a checkpoint");
    }
  }

  Solver& solver_;
  RunParameters run_;
  std::string out_dir_, name_;
  SnapshotWriter snapshots_;
  std::vector<Column> columns_;
  std::optional<TimeSeriesWriter> timeseries_;
  Row row_;
  CheckpointSettings checkpoints_;
  double next_output_ = 0.0, next_snapshot_ = 0.0;
  double next_checkpoint_ = run_.checkpoint_interval;
  long last_checkpoint_steps_ = -1;
  RunThreads* threads_ = nullptr;
  std::optional<Snapshot> last_good_;
  double last_good_time_ = 0.0;
};

}  // namespace sph
