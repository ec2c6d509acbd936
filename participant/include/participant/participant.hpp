// The participant layer: what a solver's main() uses to take part in a coupled
// run. It carries the solver's interface particles out and the cross-phase
// accelerations in; ZeroMQ and the generated protobuf code stay behind it
// (pimpl), so solver code never sees them.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "participant/curve_keys.hpp"
#include "sphcore/damped_mode.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/interface_particles.hpp"
#include "sphcore/region.hpp"

namespace cosph::coupling {

enum class PhaseKind { fluid, solid };

struct StepReply {
  double dt;                            // the common step to take next
  std::vector<sph::Vec2> acceleration;  // per particle sent, in the order sent
  std::vector<double> density_rate;     // the same, or empty: none
  sph::Region send_region;              // where to send particles from next time
  bool stop;                            // the run is over
  bool whole_step;                      // take dt in one step, however long (a stability test)
  bool report_gauges = false;           // send gauges with the next state
  bool checkpoint = false;              // checkpoint at this step (docs/restart.md)
  bool interrupted = false;             // Ctrl-C or SIGTERM: checkpoint, final snapshot, exit
};

class Participant {
 public:
  // Connects to the coupler at `endpoint` (ipc:// or tcp://). Every later
  // receive waits at most timeout_seconds plus a grace (max(1 s, 25 %)) before
  // throwing CouplingError, so that the coupler's own timeout fires first.
  // Over tcp:// the keys are required (sph::ConfigError without them).
  Participant(const std::string& endpoint, double timeout_seconds, const CurveKeyFiles& keys = {});
  ~Participant();
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  // The handshake. Returns the region to send particles from first.
  // resumed_step: the coupling step of the checkpoint the solver resumes
  // from, or -1 for a run from the start. undamped_modes: the solver has
  // modes it does not damp (Hello field undamped_modes, coupling.proto);
  // fastest_mode: its fastest mode's damping, if it states it.
  sph::Region connect(PhaseKind phase, const std::string& solver_name, std::size_t particle_count,
                      double max_smoothing_length, const sph::Region& bounds,
                      long resumed_step = -1, bool undamped_modes = false,
                      sph::DampedMode fastest_mode = {});

  // One step's exchange, in two halves so that a solver can work between
  // them: its interface state out, then the coupler's answer for it in.
  // stop_requested: Ctrl-C or SIGTERM reached this solver, and the coupler is
  // to stop the run at this step (StepReply.interrupted).
  void send_state(long step, double time, double proposed_dt, const sph::Region& bounds,
                  double max_smoothing_length, const sph::InterfaceParticles& particles,
                  const std::vector<sph::Gauge>& gauges, bool stop_requested = false);
  StepReply await_step();

  // Best effort: tells the coupler why this solver stops, so the others stop too.
  void report_error(const std::string& message) noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cosph::coupling
