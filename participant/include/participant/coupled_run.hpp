// The time loop of a solver in a coupled run: the counterpart of
// sph::StandaloneRun, with the coupler choosing every step.
//
// Per step: begin_step(dt) (kick, drift, own forces), one exchange with the
// coupler (interface out; cross-phase accelerations and density rates, the
// next dt and the stop flag in), end_step(dt) (kick). A solver that splits
// begin_step where its state is complete (advance_state: kick, drift,
// density, stress) and its own forces begin (compute_forces) sends its
// interface between the two halves, and computes its forces while the coupler
// computes the cross-phase terms: the messages and the coupler's work then
// cost a synchronised step almost nothing. In a multi-rate run the
// coupler's step is a window that the solver covers in as many sub-steps as
// its own stability needs, the cross-phase terms held over it, and exchanges
// once, at the window's end. The coupler writes timeseries.csv from the
// gauges each solver sends with the states it asks them for (those due in it);
// each solver writes its own snapshots.
//
// A Checkpointable solver writes a checkpoint when the coupler's answer asks
// for one, after the window that answer closes, and resumes from one
// (docs/restart.md): its state, the answer in hand, and the counters.
//
// Ctrl-C or SIGTERM does not stop the solver where it is: it finishes its
// window and says so with its state; the coupler, which may have been
// signalled itself, answers that step with `interrupted` (and `checkpoint`),
// and every process writes its checkpoint of that step, a final snapshot, and
// exits with 130. If the coupler does not answer within a grace (it or the
// other solver is gone), the solver writes its final snapshot and stops alone.
//
// What the solver must offer is the concept CoupledSolver
// (coupled_solver.hpp); optionally set_interface_density_rates, and
// advance_state with compute_forces (SplitsItsStep).
#pragma once

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "participant/coupled_solver.hpp"
#include "participant/coupling_error.hpp"
#include "participant/participant.hpp"
#include "sphcore/checkpoint.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/region.hpp"
#include "sphcore/run_control.hpp"
#include "sphcore/run_parameters.hpp"
#include "sphcore/run_threads.hpp"
#include "sphcore/runaway_error.hpp"
#include "sphcore/snapshot_writer.hpp"

namespace cosph::coupling {

struct CoupledRunSettings {
  std::string out_dir;
  std::string name;  // "fluid", "solid": snapshot file names
  PhaseKind phase;
  std::string solver_description;
  std::string endpoint;
  double timeout_seconds;
  CurveKeyFiles keys = {};  // over tcp://
};

// The sub-steps a solver takes to cover the coupler's window with steps no
// larger than the one it proposed (1 when the window is that step or smaller).
inline int substeps_for(double window, double proposed_dt) {
  const double ratio = window / proposed_dt;
  return ratio <= 1.0 ? 1 : static_cast<int>(std::ceil(ratio * (1.0 - 1e-12)));
}

template <CoupledSolver Solver>
class CoupledRun {
 public:
  CoupledRun(Solver& solver, const sph::RunParameters& run, CoupledRunSettings settings)
      : solver_(solver),
        run_(run),
        settings_(std::move(settings)),
        snapshots_(settings_.out_dir, settings_.name),
        participant_(settings_.endpoint, settings_.timeout_seconds, settings_.keys) {}

  // After every step, threads.revise(): the thread count follows the free cores.
  void revise_threads_with(sph::RunThreads& threads) { threads_ = &threads; }

  // Checkpoints as `settings` says (a solver that is not Checkpointable writes none).
  void checkpoint_with(sph::CheckpointSettings settings) { checkpoints_ = std::move(settings); }

  // Returns 0 when the coupler stopped the run at its end, 130 on Ctrl-C.
  int run() {
    try {
      return loop();
    } catch (const CouplingError& error) {
      // The coupler or the other solver stopped first (Ctrl-C or SIGTERM
      // reached it before this process, or it failed) while this solver
      // waited for it: the state in hand is still written. Not before the
      // coupler welcomed it: a solver it refused is not part of the run, and
      // must not add to the indexes of the folder it may share with one.
      const std::string kept = connected_ ? final_snapshot() : "";
      if (sph::stop_requested()) {
        std::cerr << settings_.name << ": interrupted (Ctrl-C or SIGTERM)" << kept << std::endl;
        return 130;
      }
      participant_.report_error(settings_.name + ": " + error.what());
      throw CouplingError(error.what() + kept);
    } catch (const sph::RunawayError& error) {
      const std::string message = std::string(error.what()) + overstep_note() +
                                  ". Last good snapshot: " + last_snapshot_ +
                                  " (t = " + std::to_string(last_time_) + " s)";
      participant_.report_error(settings_.name + ": " + message);
      throw sph::RunawayError(message);
    } catch (const std::exception& error) {
      participant_.report_error(settings_.name + ": " + error.what());
      throw;
    }
  }

 private:
  int loop() {
    const bool resuming = !checkpoints_.resume_from.empty();
    StepReply reply{};
    if (resuming) reply = resume();
    sph::Region region = participant_.connect(
        settings_.phase, settings_.solver_description, announced_particle_count(solver_),
        solver_.max_smoothing_length(), solver_.interaction_bounds(), resuming ? windows_ : -1,
        has_undamped_modes(solver_), fastest_mode_of(solver_));
    connected_ = true;
    sph::ProgressReporter progress(run_.end_time);
    if (!resuming) reply = exchange(region, solver_.time(), windows_);
    // A resumed run's first state is its checkpoint's, whose snapshot and
    // checkpoint were written before.
    bool outputs_done = resuming;
    for (;;) {
      bool snapshot_now = false;
      if (outputs_done) {
        outputs_done = false;
      } else {
        if (solver_.time() >= next_snapshot_ || reply.stop) {
          write_snapshot();
          next_snapshot_ += run_.snapshot_interval;
          snapshot_now = true;
        }
        if (reply.stop) break;
        if (reply.checkpoint) write_checkpoint(reply);
        if (reply.interrupted) return stop_interrupted(snapshot_now);
      }
      if (stop_sent_) {
        // A coupler that does not know the request (another build) went on:
        // this solver stops alone, as it did before the coupler stopped runs.
        write_snapshot();
        participant_.report_error(settings_.name + " was interrupted (Ctrl-C or SIGTERM)");
        return 130;
      }
      if (reply.whole_step) note_overstep(reply.dt);
      const int substeps = reply.whole_step ? 1 : substeps_for(reply.dt, proposed_dt_);
      const double dt = reply.dt / substeps;
      for (int k = 1; k <= substeps; ++k) {
        if (k < substeps)
          solver_.begin_step(dt);
        else
          reply = begin_step_with_exchange(dt, reply.send_region);
        solver_.end_step(dt);
      }
      if (threads_ != nullptr) threads_->revise();
      progress.report(solver_.time(), solver_.steps(), dt);
    }
    progress.report(solver_.time(), solver_.steps(), 0.0, true);
    return 0;
  }

  // The window's last step, with its exchange. The interface has moved to
  // t + dt: it is labelled so (end_step advances time() only later). A state
  // due in timeseries.csv waits for the forces: its gauges may read them.
  StepReply begin_step_with_exchange(double dt, const sph::Region& region) {
    if constexpr (SplitsItsStep<Solver>) {
      if (report_gauges_) {
        solver_.begin_step(dt);
        send_state(region, solver_.time() + dt, ++windows_);
        return await_step();
      }
      solver_.advance_state(dt);
      // The step proposed bounds the force term with the accelerations of the
      // solver's previous force pass: this one's are not known yet. The
      // sound-speed term, which sets the step in the scenes here, is exact.
      send_state(region, solver_.time() + dt, ++windows_);
      solver_.compute_forces();
    } else {
      solver_.begin_step(dt);
      send_state(region, solver_.time() + dt, ++windows_);
    }
    return await_step();
  }

  StepReply exchange(const sph::Region& region, double time, long step) {
    send_state(region, time, step);
    return await_step();
  }

  void send_state(const sph::Region& region, double time, long step) {
    solver_.collect_interface(region, interface_);
    proposed_dt_ = solver_.step_limits().smallest();
    stop_sent_ = sph::stop_requested();
    participant_.send_state(step, time, proposed_dt_, solver_.interaction_bounds(),
                            solver_.max_smoothing_length(), interface_,
                            report_gauges_ ? solver_.gauge_values() : std::vector<sph::Gauge>{},
                            stop_sent_);
  }

  // The coupler stopped the run at this step for Ctrl-C or SIGTERM; the
  // checkpoint it asked for is written. The final snapshot, unless one was
  // due at this time anyway, is not in the checkpoint's list: a resume
  // writes that snapshot number again.
  int stop_interrupted(bool snapshot_now) {
    if (!snapshot_now) write_snapshot();
    std::cerr << settings_.name << ": interrupted (Ctrl-C or SIGTERM): stopped at coupling step "
              << windows_ << " (t = " << solver_.time() << " s)"
              << (sph::Checkpointable<Solver> ? ", with its checkpoint" : "") << "; final snapshot "
              << last_snapshot_ << std::endl;
    return 130;
  }

  StepReply await_step() {
    StepReply reply = participant_.await_step();
    report_gauges_ = reply.report_gauges;
    solver_.set_interface_accelerations(reply.acceleration);
    // Only a solver with a use for the other phase's share in its continuity
    // (the fluid) takes it; a solid model need not know of it.
    if constexpr (requires { solver_.set_interface_density_rates(reply.density_rate); })
      solver_.set_interface_density_rates(reply.density_rate);
    return reply;
  }

  // A whole step longer than the solver's own stable one (coupling.solid_step
  // = "fluid") is the coupler's order, but the user hears of it at once.
  void note_overstep(double dt) {
    const double ratio = dt / proposed_dt_;
    if (ratio > 1.0 + 1e-9 && largest_overstep_ <= 1.0)
      std::cerr << settings_.name << ": warning: taking the coupler's step " << dt << " s whole, "
                << ratio << " times this solver's stable step " << proposed_dt_
                << " s (coupling.solid_step = \"fluid\", a stability test)" << std::endl;
    largest_overstep_ = std::max(largest_overstep_, ratio);
  }

  std::string overstep_note() const {
    if (largest_overstep_ <= 1.0 + 1e-9) return "";
    std::ostringstream note;
    note << "; its steps were up to " << largest_overstep_
         << " times its stable step, as coupling.solid_step = \"fluid\" asks";
    return note.str();
  }

  void write_checkpoint(const StepReply& reply) {
    if constexpr (sph::Checkpointable<Solver>) {
      sph::Checkpoint checkpoint;
      solver_.save(checkpoint);
      snapshots_.save(checkpoint);
      checkpoint.put_value("window", reply.dt);
      const sph::Region& r = reply.send_region;
      checkpoint.put("send_region",
                     std::vector<double>{r.min.x(), r.min.y(), r.max.x(), r.max.y()});
      checkpoint.put_flag("whole_step", reply.whole_step);
      checkpoint.put_flag("report_gauges", report_gauges_);
      checkpoint.put_value("proposed_dt", proposed_dt_);
      checkpoint.put_value("next_snapshot", next_snapshot_);
      checkpoint.put_value("largest_overstep", largest_overstep_);
      sph::put_intervals(checkpoint, run_);
      checkpoint.write(settings_.out_dir, settings_.name, windows_, checkpoints_.identity);
    }
  }

  // The solver's state and the coupler's answer in hand at the checkpoint.
  StepReply resume() {
    if constexpr (sph::Checkpointable<Solver>) {
      const sph::Checkpoint checkpoint =
          sph::Checkpoint::read(checkpoints_.resume_from, checkpoints_.identity);
      solver_.restore(checkpoint);
      snapshots_.restore(checkpoint);
      StepReply reply{};
      reply.dt = checkpoint.value("window");
      std::vector<double> r;
      checkpoint.get("send_region", r);
      reply.send_region = sph::Region{sph::Vec2(r.at(0), r.at(1)), sph::Vec2(r.at(2), r.at(3))};
      reply.whole_step = checkpoint.flag("whole_step");
      report_gauges_ = checkpoint.flag("report_gauges");
      reply.report_gauges = report_gauges_;
      proposed_dt_ = checkpoint.value("proposed_dt");
      next_snapshot_ = checkpoint.value("next_snapshot");
      largest_overstep_ = checkpoint.value("largest_overstep");
      sph::take_intervals(checkpoint, run_);
      windows_ = checkpoint.sequence();
      last_snapshot_ = "(none since the resume)";
      last_time_ = solver_.time();
      return reply;
    } else {
      throw sph::ConfigError(checkpoints_.resume_from +
                             ": this solver cannot resume from a checkpoint");
    }
  }

  void write_snapshot() {
    last_snapshot_ = snapshots_.write(solver_.snapshot(), solver_.time());
    last_time_ = solver_.time();
  }

  // After a coupling failure: the state as the failure found it, perhaps in
  // the middle of a step (its positions then up to one step ahead of the time
  // it is labelled with). Returns what to add to the message.
  std::string final_snapshot() noexcept {
    try {
      write_snapshot();
      return "; final snapshot " + last_snapshot_ + " (t = " + std::to_string(last_time_) + " s)";
    } catch (const std::exception& error) {
      return std::string("; no final snapshot: ") + error.what();
    }
  }

  Solver& solver_;
  sph::RunThreads* threads_ = nullptr;
  sph::RunParameters run_;
  CoupledRunSettings settings_;
  sph::SnapshotWriter snapshots_;
  Participant participant_;
  sph::InterfaceParticles interface_;
  double proposed_dt_ = 0.0;       // at the last exchange: sub-steps are no larger
  long windows_ = 0;               // exchanges so far after the first: the coupler's step count
  bool report_gauges_ = true;      // the next state goes into timeseries.csv (the first does)
  double largest_overstep_ = 0.0;  // largest step taken whole over the proposed one
  double next_snapshot_ = 0.0;
  sph::CheckpointSettings checkpoints_;
  bool connected_ = false;  // the coupler welcomed this solver
  bool stop_sent_ = false;  // the last state asked the coupler to stop the run
  std::string last_snapshot_ = "(none yet)";
  double last_time_ = 0.0;
};

}  // namespace cosph::coupling
