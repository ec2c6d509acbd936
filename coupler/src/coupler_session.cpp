#include "coupler_session.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <set>
#include <sstream>

#include "common_step.hpp"
#include "endpoint_safety.hpp"
#include "message_limits.hpp"
#include "participant/bound_ipc_file.hpp"
#include "participant/protocol.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/region.hpp"
#include "sphcore/run_control.hpp"
#include "sphcore/timeseries_writer.hpp"
#include "substep_choice.hpp"
#include "zap_handler.hpp"

namespace cosph::coupler {

namespace cp = cosph::coupling;
using Clock = std::chrono::steady_clock;

namespace {

constexpr int kFluid = 0, kSolid = 1;
const char* kSideName[2] = {"fluid", "solid"};

struct Peer {
  std::string identity;
  std::string solver;
  std::uint64_t particle_count = 0;  // announced in its Hello: its states' size limit
  double max_h = 0.0;
  sph::Region bounds;
  cp::InterfaceState state;
  sph::InterfaceParticles particles;
  // Of the last state that had them: a solver sends gauges when asked.
  google::protobuf::RepeatedPtrField<cp::Gauge> gauges;
};

class Session {
 public:
  explicit Session(const CouplerSettings& settings)
      : settings_(settings), timeout_(static_cast<long>(1000.0 * settings.timeout_seconds)) {
    // The last messages (the stop, or an error) are queued when run() returns:
    // with no linger, closing the socket dropped whichever the I/O thread had
    // not sent yet, and on a loaded machine the solid waited for its stop until
    // it timed out. They get as long as a peer gets to answer, and no longer,
    // so a peer that is gone cannot hold the coupler's exit.
    socket_.set(zmq::sockopt::linger, static_cast<int>(timeout_.count()));
    socket_.set(zmq::sockopt::router_mandatory, 1);
    socket_.set(zmq::sockopt::maxmsgsize, static_cast<std::int64_t>(kSocketLimitBytes));
    if (settings.keys.given()) {
      cp::use_server_keys(socket_, settings.keys);
      std::set<std::string> allowed;
      for (const std::string& file : settings.keys.allowed)
        allowed.insert(cp::read_public_key(file));
      zap_.emplace(context_, std::move(allowed));
    }
    {
      const PrivateUmask private_socket_file;  // an ipc:// socket only the user can connect to
      bind_endpoint(settings.endpoint);
    }
    ipc_file_.bound(settings.endpoint);
  }

  // ZeroMQ's own error ("Permission denied") names neither the endpoint nor its file.
  void bind_endpoint(const std::string& endpoint) {
    try {
      socket_.bind(endpoint);
    } catch (const zmq::error_t& error) {
      throw cp::CouplingError("cannot bind the coupling endpoint " + endpoint + ": " +
                              error.what());
    }
  }

  int run() {
    const bool resuming = !settings_.checkpoints.resume_from.empty();
    if (resuming) resume();
    handshake();
    for (long step = resuming ? checkpoint_step_ + 1 : 0;; ++step) {
      const int last_in = receive_states(step);
      count_pace_setter_wait(last_in);
      switch (answer(step, last_in)) {
        case Next::step:
          break;
        case Next::end:
          return 0;
        case Next::interrupted:
          std::cerr << "cosph-coupler: interrupted (Ctrl-C or SIGTERM): stopped the run at "
                    << "coupling step " << step << " (t = " << peers_[kFluid].state.time()
                    << " s), every process with its checkpoint of it" << std::endl;
          return 130;
      }
    }
  }

 private:
  // Tells every known peer why the run stops, except one that stopped first
  // (`stopped`: it is gone or going), then throws.
  [[noreturn]] void fail(const std::string& message, int stopped = -1) {
    cp::Envelope error;
    error.mutable_error()->set_message(message);
    // A message queued for a peer that exits holds the coupler's own exit for
    // the whole linger: the launcher, which stops every process 5 s after one
    // fails, then had to kill it. The peers that still run get the error
    // within a second, or are stopped by the launcher anyway.
    socket_.set(zmq::sockopt::linger, static_cast<int>(std::min<long>(timeout_.count(), 1000)));
    for (int side : {kFluid, kSolid}) {
      const Peer& peer = peers_[side];
      if (!peer.identity.empty() && side != stopped) {
        try {
          cp::send_to(socket_, peer.identity, error);
        } catch (const zmq::error_t&) {
          // that peer is gone already
        }
      }
    }
    throw cp::CouplingError(message);
  }

  // The next message of a registered solver, or a Hello from a peer that is
  // not one yet. Anything else from a peer that is not one of the run's
  // solvers is refused and logged, and the wait goes on: only a registered
  // solver's malformed message stops the run.
  cp::Routed await(const std::string& waiting_for) {
    const auto deadline = Clock::now() + timeout_;
    for (;;) {
      const auto start = Clock::now();
      std::optional<cp::RoutedFrame> message = cp::receive_routed_frame(
          socket_,
          std::max(std::chrono::milliseconds(0),
                   std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now())));
      wait_seconds_ += std::chrono::duration<double>(Clock::now() - start).count();
      if (!message && sph::stop_requested())
        fail("the coupler was interrupted (Ctrl-C or SIGTERM): " + waiting_for);
      if (!message)
        fail(waiting_for + ": nothing within " + std::to_string(settings_.timeout_seconds) +
             " s (the solver died, stalled, or never connected)");
      const int side = side_of(message->identity);
      const std::string sender =
          side >= 0 ? "the " + std::string(kSideName[side]) + " ('" + peers_[side].solver + "')"
                    : "a peer";
      std::optional<cp::Envelope> envelope;
      std::string problem = check_frame(*message, side, sender);
      if (problem.empty()) {
        try {
          envelope = cp::parse(cp::bytes_of(message->frame), sender);
        } catch (const cp::CouplingError& error) {
          problem = error.what();
        }
      }
      if (side >= 0) {
        if (!problem.empty()) fail(problem);
        if (envelope->has_error())
          fail(std::string(kSideName[side]) + " stopped: " + envelope->error().message(), side);
        // Moved, not copied: a state is some 100 kB of arrays.
        return cp::Routed{std::move(message->identity), std::move(*envelope)};
      }
      if (problem.empty() && !envelope->has_hello())
        problem = std::string(envelope->has_state() ? "a state" : "a message") +
                  " from a peer that has not said Hello";
      if (!problem.empty()) {
        refuse(message->identity, problem);
        continue;
      }
      return cp::Routed{std::move(message->identity), std::move(*envelope)};
    }
  }

  // Why a message cannot be one of the protocol's, before it is parsed: one
  // frame, no larger than a Hello from a peer that has not said one, or than
  // a state of its particles from a registered solver.
  std::string check_frame(const cp::RoutedFrame& message, int side,
                          const std::string& sender) const {
    if (message.frames != 1)
      return "garbage from " + sender + ": a message of " + std::to_string(message.frames) +
             " frames (the protocol sends one)";
    const std::size_t limit =
        side >= 0 ? largest_state_bytes(peers_[side].particle_count) : kLargestHelloBytes;
    if (message.frame.size() > limit)
      return sender + " sent a message of " + std::to_string(message.frame.size()) +
             " bytes, over the limit of " + std::to_string(limit) + " bytes" +
             (side >= 0 ? " for the " + std::to_string(peers_[side].particle_count) +
                              " particles of its Hello"
                        : " before a Hello is accepted");
    return {};
  }

  // Logs that a peer was refused and tells it why, if it is still there; the
  // run goes on.
  void refuse(const std::string& identity, const std::string& reason) {
    std::cerr << "cosph-coupler: refused a peer that is not one of the run's solvers: " << reason
              << "; the run goes on" << std::endl;
    cp::Envelope error;
    error.mutable_error()->set_message(reason);
    try {
      cp::send_to(socket_, identity, error, zmq::send_flags::dontwait);
    } catch (const zmq::error_t&) {
      // gone already, or not reading: it has been refused all the same
    }
  }

  int side_of(const std::string& identity) const {
    for (int side : {kFluid, kSolid})
      if (peers_[side].identity == identity) return side;
    return -1;
  }

  void handshake() {
    while (peers_[kFluid].identity.empty() || peers_[kSolid].identity.empty()) {
      const cp::Routed message = await("waiting for the solvers to connect");
      const int registered = side_of(message.identity);
      if (registered >= 0)
        fail("the " + std::string(kSideName[registered]) + " ('" + peers_[registered].solver +
             "') sent the wrong message before the run began");
      const cp::Hello& hello = message.envelope.hello();
      const int side = hello.phase() == cp::SOLID ? kSolid : kFluid;
      const std::string problem = check_hello(hello, side);
      if (!problem.empty()) {
        refuse(message.identity, problem);
        continue;
      }
      Peer& peer = peers_[side];
      peer.identity = message.identity;
      peer.solver = hello.solver();
      peer.particle_count = hello.particle_count();
      peer.max_h = hello.max_smoothing_length();
      peer.bounds = cp::from_proto(hello.bounds());
      if (side == kSolid)
        solid_damping_ = {hello.undamped_modes(), hello.fastest_mode_angular_frequency(),
                          hello.fastest_mode_damping_ratio()};
    }
    take_the_solids_damping_into_account();
    for (int side : {kFluid, kSolid}) {
      cp::Envelope welcome;
      welcome.mutable_welcome()->set_protocol_version(cp::kProtocolVersion);
      *welcome.mutable_welcome()->mutable_send_region() = cp::to_proto(send_region(side));
      cp::send_to(socket_, peers_[side].identity, welcome);
    }
    std::cout << "cosph-coupler: coupling '" << peers_[kFluid].solver << "' and '"
              << peers_[kSolid].solver << "' at " << settings_.endpoint << std::endl;
  }

  // The solid's damping can turn an automatic multi-rate choice into
  // synchronised steps or bound its windows (substep_choice.hpp).
  void take_the_solids_damping_into_account() {
    if (settings_.solid_at_fluid_step) return;
    const SubstepChoice choice =
        account_for_the_solids_damping(settings_.stepping, solid_damping_, peers_[kSolid].solver);
    const bool unchanged = choice.max_substeps == settings_.stepping.max_substeps &&
                           choice.max_window == settings_.stepping.max_window;
    if (unchanged) return;
    settings_.stepping = choice;
    std::cout << "cosph-coupler: sub-stepping: " << choice.reason << std::endl;
  }

  // Empty if the Hello may join the run as `side`, else the reason.
  std::string check_hello(const cp::Hello& hello, int side) const {
    std::string problem = cp::check_hello(hello, side == kSolid ? cp::SOLID : cp::FLUID);
    if (problem.empty() && !peers_[side].identity.empty())
      problem = "a second " + std::string(kSideName[side]) + " solver, '" + hello.solver() +
                "' (the run's is '" + peers_[side].solver + "')";
    if (problem.empty() && hello.particle_count() > kLargestParticleCount)
      problem = "'" + hello.solver() + "' announced " + std::to_string(hello.particle_count()) +
                " particles, more than the coupler takes (" +
                std::to_string(kLargestParticleCount) + ")";
    if (problem.empty()) problem = check_resumed_step(hello, side);
    return problem;
  }

  // The three parts of a checkpoint are taken at one coupling step.
  std::string check_resumed_step(const cp::Hello& hello, int side) const {
    const bool resuming = !settings_.checkpoints.resume_from.empty();
    const std::string solver = kSideName[side];
    if (!resuming && hello.resumed())
      return "the " + solver + " resumes from its checkpoint at coupling step " +
             std::to_string(hello.resumed_step()) + ", the coupler starts the run afresh";
    if (resuming && !hello.resumed())
      return "the " + solver + " starts afresh, the coupler resumes from its checkpoint at step " +
             std::to_string(checkpoint_step_) + " (" + settings_.checkpoints.resume_from + ")";
    if (resuming && static_cast<long>(hello.resumed_step()) != checkpoint_step_)
      return "the checkpoint's parts do not match: the " + solver + " resumes from coupling step " +
             std::to_string(hello.resumed_step()) + ", the coupler from step " +
             std::to_string(checkpoint_step_) + " (" + settings_.checkpoints.resume_from + ")";
    return {};
  }

  // Particles of `side` that the other phase can reach within the next step:
  // the other side's bounds, grown by the largest pair reach plus a margin
  // for one step's motion (less than h at any stable CFL number).
  sph::Region send_region(int side) const {
    const Peer& other = peers_[1 - side];
    const double reach = peers_[kFluid].max_h + peers_[kSolid].max_h;
    return other.bounds.grown(reach + std::max(peers_[kFluid].max_h, peers_[kSolid].max_h));
  }

  // Returns the side whose state came last.
  int receive_states(long step) {
    bool got[2] = {false, false};
    int last_in = kFluid;
    while (!got[kFluid] || !got[kSolid]) {
      const std::string missing = !got[kFluid] && !got[kSolid] ? "fluid and solid"
                                  : !got[kFluid]               ? "fluid"
                                                               : "solid";
      cp::Routed message = await("step " + std::to_string(step) + ", waiting for the " + missing);
      const int side = side_of(message.identity);
      if (side < 0) {  // a Hello, once both solvers are in
        const cp::Hello& hello = message.envelope.hello();
        refuse(message.identity, check_hello(hello, hello.phase() == cp::SOLID ? kSolid : kFluid));
        continue;
      }
      if (!message.envelope.has_state())
        fail(std::string(kSideName[side]) + " sent the wrong message at step " +
             std::to_string(step));
      Peer& peer = peers_[side];
      const auto parse_start = Clock::now();
      peer.state = std::move(*message.envelope.mutable_state());
      try {
        peer.particles = cp::from_proto(peer.state);
      } catch (const cp::CouplingError& error) {
        fail(std::string(kSideName[side]) + ": " + error.what());
      }
      messaging_seconds_ += std::chrono::duration<double>(Clock::now() - parse_start).count();
      if (side == kSolid) warn_if_no_acceleration(peer);
      peer.bounds = cp::from_proto(peer.state.bounds());
      peer.max_h = peer.state.max_smoothing_length();
      if (!peer.state.gauges().empty()) {
        if (!peer.gauges.empty() && peer.state.gauges_size() != peer.gauges.size())
          fail(std::string(kSideName[side]) + " changed the set of gauges it sends during the run");
        peer.gauges.Swap(peer.state.mutable_gauges());
      }
      got[side] = true;
      last_in = side;
    }
    const double t_fluid = peers_[kFluid].state.time(), t_solid = peers_[kSolid].state.time();
    if (std::abs(t_fluid - t_solid) > 1e-9 * std::max(1.0, settings_.run.end_time))
      fail("the solvers are out of step: fluid at t = " + std::to_string(t_fluid) +
           " s, solid at t = " + std::to_string(t_solid) + " s");
    return last_in;
  }

  // The moving wall's pressure takes the solid's acceleration (docs/physics.md,
  // "Moving wall"); a solid that does not send it still couples, the term left
  // out, and the user hears of it once.
  void warn_if_no_acceleration(const Peer& solid) {
    if (warned_no_acceleration_ || solid.particles.size() == 0 ||
        solid.particles.has_acceleration() ||
        settings_.cross_phase.model != InterfaceModel::moving_wall ||
        !settings_.cross_phase.wall_acceleration)
      return;
    warned_no_acceleration_ = true;
    std::cerr << "cosph-coupler: warning: '" << solid.solver
              << "' sends no acceleration with its interface state (protocol version 2?): the "
                 "moving wall's pressure leaves out the term of the wall's acceleration, "
                 "rho (g - a_w) . r, and takes g alone"
              << std::endl;
  }

  // Each state carries its solver's waits for the answers so far, the last
  // one being that for the previous step's answer. The solver whose state
  // came last in that step waited for the coupling alone: the messages and
  // the pair forces. The other also waited for it to catch up, which is the
  // two solvers' imbalance, not the coupling's cost.
  void count_pace_setter_wait(int last_in) {
    if (pace_setter_ >= 0)
      pace_setter_waiting_ += peers_[pace_setter_].state.waiting() - pace_setter_waited_before_;
    pace_setter_ = last_in;
    pace_setter_waited_before_ = peers_[last_in].state.waiting();
  }

  enum class Next { step, end, interrupted };

  // Returns what comes after this answer. Ctrl-C or SIGTERM, to the coupler
  // or to a solver (its state says so), stops the run at this step: the
  // answer asks every process for its checkpoint of it, then to stop.
  Next answer(long step, int last_in) {
    const auto pair_start = Clock::now();
    const CrossPhaseForces forces = compute_cross_phase_forces(
        peers_[kFluid].particles, peers_[kSolid].particles, settings_.cross_phase);
    pair_seconds_ += std::chrono::duration<double>(Clock::now() - pair_start).count();

    const double t = peers_[kFluid].state.time();
    const double end = settings_.run.end_time;
    const bool stop = t >= end - 1e-9 * end;
    double dt =
        settings_.solid_at_fluid_step
            ? peers_[kFluid].state.proposed_dt()
            : common_step(peers_[kFluid].state.proposed_dt(), peers_[kSolid].state.proposed_dt(),
                          settings_.stepping.max_substeps, settings_.stepping.max_window);
    if (!(dt > 0.0) || !std::isfinite(dt))
      fail("a solver proposed a step that is not positive at t = " + std::to_string(t) + " s");
    dt = std::min(dt, end - t);
    record(step, t, dt, forces, stop);
    // Asked for ahead: the solvers then pay for gauges on these states only.
    row_due_ = !stop && (t + dt >= next_output_ || t + dt >= end - 1e-9 * end);
    const bool interrupted =
        !stop && (sph::stop_requested() || peers_[kFluid].state.stop_requested() ||
                  peers_[kSolid].state.stop_requested());
    const bool due = !stop && t >= next_checkpoint_;
    const bool checkpoint = due || interrupted;

    const auto send_start = Clock::now();
    // The solver whose state came last sets the pace; the other has been
    // waiting for the answer anyway: answer the last one first.
    for (int side : {last_in, 1 - last_in}) {
      cp::Envelope reply;
      cp::CouplingStep& s = *reply.mutable_step();
      s.set_step(static_cast<std::uint64_t>(step));
      s.set_dt(dt);
      s.set_stop(stop);
      s.set_whole_step(settings_.solid_at_fluid_step);
      s.set_came_last(side == last_in);
      s.set_report_gauges(row_due_);
      s.set_checkpoint(checkpoint);
      s.set_interrupted(interrupted);
      const auto& a = side == kFluid ? forces.fluid_a : forces.solid_a;
      s.mutable_acceleration()->Resize(2 * static_cast<int>(a.size()), 0.0);
      std::copy_n(cp::doubles_of(a), 2 * a.size(), s.mutable_acceleration()->mutable_data());
      if (side == kFluid)
        s.mutable_density_rate()->Add(forces.fluid_drho.begin(), forces.fluid_drho.end());
      *s.mutable_send_region() = cp::to_proto(send_region(side));
      try {
        cp::send_to(socket_, peers_[side].identity, reply);
      } catch (const zmq::error_t& error) {
        fail(std::string("cannot reach the ") + kSideName[side] + " solver: " + error.what());
      }
    }
    messaging_seconds_ += std::chrono::duration<double>(Clock::now() - send_start).count();
    // An interruption's checkpoint is one more: the periodic ones keep their times.
    if (due) next_checkpoint_ += settings_.run.checkpoint_interval;
    if (checkpoint) write_checkpoint(step);
    // The last report is forced, so the launcher's summary names the end time.
    progress_.report(t, step, dt, stop || interrupted);
    return stop ? Next::end : interrupted ? Next::interrupted : Next::step;
  }

  // What decides the coupler's next answers and rows, taken after its answer
  // at `step`: the solvers take theirs after the window that answer closes.
  void write_checkpoint(long step) const {
    sph::Checkpoint checkpoint;
    checkpoint.put_value("next_output", next_output_);
    checkpoint.put_value("next_checkpoint", next_checkpoint_);
    checkpoint.put_flag("row_due", row_due_);
    checkpoint.put_count("level", level_);
    std::string columns;
    for (const sph::Column& column : columns_) columns += column.name + "\n" + column.unit + "\n";
    checkpoint.put_text("timeseries_columns", columns);
    checkpoint.put_count("timeseries_rows", static_cast<long>(timeseries_->rows()));
    checkpoint.put_count("coupling_rows", static_cast<long>(coupling_->rows()));
    checkpoint.put("seconds",
                   std::vector<double>{wait_seconds_, messaging_seconds_, pair_seconds_,
                                       pace_setter_waiting_, pace_setter_waited_before_});
    checkpoint.put_count("pace_setter", pace_setter_);
    sph::put_intervals(checkpoint, settings_.run);
    checkpoint.write(settings_.out_dir, "coupler", step, settings_.checkpoints.identity);
  }

  void resume() {
    const sph::Checkpoint checkpoint =
        sph::Checkpoint::read(settings_.checkpoints.resume_from, settings_.checkpoints.identity);
    checkpoint_step_ = checkpoint.sequence();
    next_output_ = checkpoint.value("next_output");
    next_checkpoint_ = checkpoint.value("next_checkpoint");
    row_due_ = checkpoint.flag("row_due");
    level_ = static_cast<int>(checkpoint.count("level"));
    std::istringstream columns(checkpoint.text("timeseries_columns"));
    sph::Column column;
    while (std::getline(columns, column.name) && std::getline(columns, column.unit))
      columns_.push_back(column);
    std::vector<double> seconds;
    checkpoint.get("seconds", seconds);
    wait_seconds_ = seconds.at(0);
    messaging_seconds_ = seconds.at(1);
    pair_seconds_ = seconds.at(2);
    pace_setter_waiting_ = seconds.at(3);
    pace_setter_waited_before_ = seconds.at(4);
    pace_setter_ = static_cast<int>(checkpoint.count("pace_setter"));
    sph::take_intervals(checkpoint, settings_.run);
    timeseries_.emplace(settings_.out_dir + "/timeseries.csv", columns_,
                        sph::TimeSeriesWriter::ContinueAfter{
                            static_cast<std::size_t>(checkpoint.count("timeseries_rows"))});
    coupling_.emplace(settings_.out_dir + "/coupling.csv", coupling_columns(),
                      sph::TimeSeriesWriter::ContinueAfter{
                          static_cast<std::size_t>(checkpoint.count("coupling_rows"))});
  }

  void record(long step, double t, double dt, const CrossPhaseForces& forces, bool stop) {
    if (!timeseries_) open_outputs();
    if (!row_due_ && !stop) return;
    next_output_ += settings_.run.output_interval;
    std::vector<double> row{t, dt};
    for (int side : {kFluid, kSolid})
      for (const auto& gauge : peers_[side].gauges) row.push_back(gauge.value());
    row.push_back(level_ < 0 ? 0.0 : peers_[kFluid].gauges[level_].value());
    row.push_back(forces.force_on_solid.x());
    row.push_back(forces.force_on_solid.y());
    timeseries_->write_row(row);
    const std::array<double, 16> coupling{t,
                                          forces.force_on_fluid.x(),
                                          forces.force_on_fluid.y(),
                                          forces.force_on_solid.x(),
                                          forces.force_on_solid.y(),
                                          static_cast<double>(peers_[kFluid].particles.size()),
                                          static_cast<double>(peers_[kSolid].particles.size()),
                                          static_cast<double>(forces.pairs),
                                          static_cast<double>(step),
                                          wait_seconds_,
                                          messaging_seconds_,
                                          pair_seconds_,
                                          dt,
                                          peers_[kFluid].state.waiting(),
                                          peers_[kSolid].state.waiting(),
                                          pace_setter_waiting_};
    coupling_->write_row(coupling);
  }

  void open_outputs() {
    std::vector<sph::Column> columns{{"t", "s"}, {"dt", "s"}};
    // A name both sides measure (kinetic_energy, max_speed) gets the side as prefix.
    auto measured_by = [this](int side, const std::string& name) {
      for (const auto& gauge : peers_[side].gauges)
        if (gauge.name() == name) return true;
      return false;
    };
    for (int side : {kFluid, kSolid}) {
      const auto& gauges = peers_[side].gauges;
      for (int g = 0; g < gauges.size(); ++g) {
        const bool shared = measured_by(1 - side, gauges[g].name());
        columns.push_back(
            {(shared ? std::string(kSideName[side]) + "_" : std::string()) + gauges[g].name(),
             gauges[g].unit()});
        if (side == kFluid && gauges[g].name() == "height") level_ = g;
      }
    }
    // The water level at the left wall, the scene's name for the fluid's "height".
    columns.push_back({"level", "m"});
    // The net force of the water on the solid (the plate of every scene here),
    // of the states of the row: the load an engineer reads.
    columns.push_back({"plate_force_x", "N/m"});
    columns.push_back({"plate_force_y", "N/m"});
    columns_ = columns;
    timeseries_.emplace(settings_.out_dir + "/timeseries.csv", columns);
    coupling_.emplace(settings_.out_dir + "/coupling.csv", coupling_columns());
  }

  static std::vector<sph::Column> coupling_columns() {
    return std::vector<sph::Column>{{"t", "s"},
                                    {"force_on_fluid_x", "N/m"},
                                    {"force_on_fluid_y", "N/m"},
                                    {"force_on_solid_x", "N/m"},
                                    {"force_on_solid_y", "N/m"},
                                    {"fluid_interface_particles", "1"},
                                    {"solid_interface_particles", "1"},
                                    {"pairs", "1"},
                                    {"step", "1"},
                                    {"waiting", "s"},
                                    {"messaging", "s"},
                                    {"pair_forces", "s"},
                                    {"dt", "s"},
                                    {"fluid_waiting", "s"},
                                    {"solid_waiting", "s"},
                                    {"pace_setter_waiting", "s"}};
  }

  CouplerSettings settings_;
  SolidDamping solid_damping_;  // from the solid's Hello: see account_for_the_solids_damping
  std::chrono::milliseconds timeout_;
  cp::BoundIpcFile ipc_file_;  // before the context: destroyed after it
  zmq::context_t context_{1};
  std::optional<ZapHandler> zap_;  // before the socket: it answers for it until it is closed
  zmq::socket_t socket_{context_, zmq::socket_type::router};
  std::array<Peer, 2> peers_;
  std::optional<sph::TimeSeriesWriter> timeseries_, coupling_;
  std::vector<sph::Column> columns_;  // of timeseries.csv
  double next_checkpoint_ = settings_.run.checkpoint_interval;
  long checkpoint_step_ = -1;  // of the checkpoint resumed from
  int level_ = -1;
  bool warned_no_acceleration_ = false;
  double next_output_ = 0.0;
  // The states in hand go into timeseries.csv: asked for with the last
  // answer (CouplingStep.report_gauges), and the first.
  bool row_due_ = true;
  double wait_seconds_ = 0.0, messaging_seconds_ = 0.0, pair_seconds_ = 0.0;
  // count_pace_setter_wait: the waits of the solver that came last, summed
  // step by step; the side that came last in the step before (none before
  // the first), and its waits up to that step.
  double pace_setter_waiting_ = 0.0;
  int pace_setter_ = -1;
  double pace_setter_waited_before_ = 0.0;
  sph::ProgressReporter progress_{settings_.run.end_time};
};

}  // namespace

int run_coupler(const CouplerSettings& settings) {
  Session session(settings);
  return session.run();
}

}  // namespace cosph::coupler
