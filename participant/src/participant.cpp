#include "participant/participant.hpp"

#include <algorithm>
#include <chrono>
#include <zmq.hpp>

#include "participant/protocol.hpp"
#include "sphcore/gauge.hpp"
#include "sphcore/region.hpp"
#include "sphcore/run_control.hpp"

namespace cosph::coupling {

struct Participant::Impl {
  zmq::context_t context{1};
  zmq::socket_t socket{context, zmq::socket_type::dealer};
  std::chrono::milliseconds timeout;
  std::string endpoint;
  std::size_t sent = 0;    // particles in the last state: the answer has one entry for each
  double waited = 0.0;     // s, in await_step, sent with every state
  bool came_last = false;  // in the last step: this solver sets the pace
  bool keyed = false;      // CURVE: a wrong coupler key shows only as silence

  // The solver that sets the pace has its answer within a round trip (about
  // 0.1 ms) and the coupler's pair forces: it polls for this long before its
  // thread sleeps, so that no idle core has to be woken for the answer
  // (README, "Speed"; the commit that added it gives the gain). The other
  // solver waits for it anyway and sleeps at once, leaving the core free.
  static constexpr std::chrono::microseconds kStepSpin{300};

  Envelope await(const char* expected,
                 std::chrono::microseconds spin = std::chrono::microseconds(0)) {
    auto reply = receive(socket, timeout, "the coupler", spin);
    if (!reply && sph::stop_requested())
      throw CouplingError(std::string("interrupted (Ctrl-C or SIGTERM) while waiting for ") +
                          expected);
    if (!reply)
      throw CouplingError(
          "the coupler at " + endpoint + " did not answer within " +
          std::to_string(static_cast<double>(timeout.count()) / 1000.0) + " s (waiting for " +
          expected + ")" +
          (keyed ? "; over tcp the coupler is silent to a solver it does not take: is "
                   "--coupler-key its public key, and was this solver's --keys "
                   "given to it with --allow-key?"
                 : ""));
    if (reply->has_error()) throw CouplingError("coupler: " + reply->error().message());
    return *reply;
  }
};

Participant::Participant(const std::string& endpoint, double timeout_seconds,
                         const CurveKeyFiles& keys)
    : impl_(std::make_unique<Impl>()) {
  check_key_files(endpoint, keys, /*coupler=*/false);
  // The coupler restarts its own timeout when the other solver's message arrives,
  // after this solver has started waiting: a solver that waited only as long would
  // always give up first and blame the coupler for a peer that died. The grace
  // lets the coupler, which knows who is missing, report first.
  const double grace = std::max(1.0, 0.25 * timeout_seconds);
  impl_->timeout = std::chrono::milliseconds(static_cast<long>(1000.0 * (timeout_seconds + grace)));
  impl_->endpoint = endpoint;
  impl_->socket.set(zmq::sockopt::linger, 0);  // never hang on exit over unsent messages
  // The launcher starts the coupler and the solvers together, so a solver often
  // tries before the coupler has bound its socket. ZeroMQ's default first retry
  // after 100 ms was most of a coupled run's start-up; a short first retry that
  // backs off to the same 100 ms keeps a coupler that is truly away unhurried.
  impl_->socket.set(zmq::sockopt::reconnect_ivl, 5);
  impl_->socket.set(zmq::sockopt::reconnect_ivl_max, 100);
  use_client_keys(impl_->socket, keys);
  impl_->keyed = keys.given();
  try {
    impl_->socket.connect(endpoint);
  } catch (const zmq::error_t& error) {
    throw CouplingError("cannot connect to the coupler at " + endpoint + ": " + error.what());
  }
}

Participant::~Participant() = default;

sph::Region Participant::connect(PhaseKind phase, const std::string& solver_name,
                                 std::size_t particle_count, double max_smoothing_length,
                                 const sph::Region& bounds, long resumed_step, bool undamped_modes,
                                 sph::DampedMode fastest_mode) {
  Envelope hello;
  Hello& h = *hello.mutable_hello();
  h.set_protocol_version(kProtocolVersion);
  h.set_phase(phase == PhaseKind::fluid ? FLUID : SOLID);
  h.set_solver(solver_name);
  h.set_particle_count(particle_count);
  h.set_max_smoothing_length(max_smoothing_length);
  *h.mutable_bounds() = to_proto(bounds);
  h.set_resumed(resumed_step >= 0);
  h.set_resumed_step(static_cast<std::uint64_t>(std::max(resumed_step, 0L)));
  h.set_undamped_modes(undamped_modes);
  h.set_fastest_mode_angular_frequency(fastest_mode.angular_frequency);
  h.set_fastest_mode_damping_ratio(fastest_mode.damping_ratio);
  send(impl_->socket, hello);
  const Envelope welcome = impl_->await("its Welcome");
  if (!welcome.has_welcome())
    throw CouplingError("the coupler answered the handshake with the wrong message");
  return from_proto(welcome.welcome().send_region());
}

void Participant::send_state(long step, double time, double proposed_dt, const sph::Region& bounds,
                             double max_smoothing_length, const sph::InterfaceParticles& particles,
                             const std::vector<sph::Gauge>& gauges, bool stop_requested) {
  Envelope message;
  InterfaceState& state = *message.mutable_state();
  state.set_step(static_cast<std::uint64_t>(step));
  state.set_time(time);
  state.set_proposed_dt(proposed_dt);
  *state.mutable_bounds() = to_proto(bounds);
  state.set_max_smoothing_length(max_smoothing_length);
  to_proto(particles, state);
  for (const sph::Gauge& gauge : gauges) {
    Gauge& g = *state.add_gauges();
    g.set_name(gauge.name);
    g.set_unit(gauge.unit);
    g.set_value(gauge.value);
  }
  state.set_waiting(impl_->waited);
  state.set_stop_requested(stop_requested);
  send(impl_->socket, message);
  impl_->sent = particles.size();
}

StepReply Participant::await_step() {
  const std::size_t sent = impl_->sent;
  const auto start = std::chrono::steady_clock::now();
  const Envelope reply = impl_->await(
      "the common step", impl_->came_last ? Impl::kStepSpin : std::chrono::microseconds(0));
  impl_->waited += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!reply.has_step()) throw CouplingError("the coupler answered a step with the wrong message");
  const CouplingStep& s = reply.step();
  impl_->came_last = s.came_last();
  if (!s.stop() && s.acceleration_size() != 2 * static_cast<int>(sent))
    throw CouplingError("the coupler sent " + std::to_string(s.acceleration_size() / 2) +
                        " accelerations for " + std::to_string(sent) + " particles");
  if (!s.stop() && s.density_rate_size() != 0 && s.density_rate_size() != static_cast<int>(sent))
    throw CouplingError("the coupler sent " + std::to_string(s.density_rate_size()) +
                        " density rates for " + std::to_string(sent) + " particles");
  StepReply out{s.dt(), {}, {}, from_proto(s.send_region()), s.stop(), s.whole_step()};
  out.report_gauges = s.report_gauges();
  out.checkpoint = s.checkpoint();
  out.interrupted = s.interrupted();
  out.acceleration.resize(static_cast<std::size_t>(s.acceleration_size() / 2));
  std::copy_n(s.acceleration().data(), 2 * out.acceleration.size(), doubles_of(out.acceleration));
  out.density_rate.assign(s.density_rate().begin(), s.density_rate().end());
  return out;
}

void Participant::report_error(const std::string& message) noexcept {
  try {
    Envelope error;
    error.mutable_error()->set_message(message);
    impl_->socket.send(zmq::buffer(serialise(error)), zmq::send_flags::dontwait);
  } catch (...) {
    // The coupler may be gone already; the launcher reports this solver's exit.
  }
}

}  // namespace cosph::coupling
