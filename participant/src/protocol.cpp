#include "participant/protocol.hpp"

#include "sphcore/run_control.hpp"

#include <malloc.h>
#include <sched.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include "sphcore/region.hpp"

namespace cosph::coupling {

const char* phase_name(Phase phase) {
  switch (phase) {
    case FLUID:
      return "fluid";
    case SOLID:
      return "solid";
    default:
      return "unspecified";
  }
}

Region to_proto(const sph::Region& region) {
  Region out;
  out.set_min_x(region.min.x());
  out.set_min_y(region.min.y());
  out.set_max_x(region.max.x());
  out.set_max_y(region.max.y());
  return out;
}

sph::Region from_proto(const Region& region) {
  return {sph::Vec2(region.min_x(), region.min_y()), sph::Vec2(region.max_x(), region.max_y())};
}

void to_proto(const sph::InterfaceParticles& P, InterfaceState& state) {
  const int n = static_cast<int>(P.size());
  state.mutable_id()->Assign(P.id.begin(), P.id.end());
  state.mutable_position()->Resize(2 * n, 0.0);
  std::copy_n(doubles_of(P.x), 2 * n, state.mutable_position()->mutable_data());
  state.mutable_velocity()->Resize(2 * n, 0.0);
  std::copy_n(doubles_of(P.v), 2 * n, state.mutable_velocity()->mutable_data());
  state.mutable_stress()->Resize(4 * n, 0.0);
  double* stress = state.mutable_stress()->mutable_data();
  for (int i = 0; i < n; ++i) {
    const sph::Mat2& s = P.sigma[i];
    stress[4 * i] = s(0, 0), stress[4 * i + 1] = s(0, 1);
    stress[4 * i + 2] = s(1, 0), stress[4 * i + 3] = s(1, 1);
  }
  state.mutable_mass()->Assign(P.m.begin(), P.m.end());
  state.mutable_density()->Assign(P.rho.begin(), P.rho.end());
  state.mutable_smoothing_length()->Assign(P.h.begin(), P.h.end());
  state.mutable_sound_speed()->Assign(P.c.begin(), P.c.end());
  state.mutable_acceleration()->Resize(2 * static_cast<int>(P.a.size()), 0.0);
  std::copy_n(doubles_of(P.a), 2 * P.a.size(), state.mutable_acceleration()->mutable_data());
}

sph::InterfaceParticles from_proto(const InterfaceState& state) {
  const int n = state.id_size();
  auto expect = [n](int size, int per_particle, const char* field) {
    if (size != per_particle * n)
      throw CouplingError("malformed InterfaceState: " + std::string(field) + " has " +
                          std::to_string(size) + " values for " + std::to_string(n) +
                          " particles (expected " + std::to_string(per_particle * n) + ")");
  };
  expect(state.position_size(), 2, "position");
  expect(state.velocity_size(), 2, "velocity");
  expect(state.stress_size(), 4, "stress");
  expect(state.mass_size(), 1, "mass");
  expect(state.density_size(), 1, "density");
  expect(state.smoothing_length_size(), 1, "smoothing_length");
  expect(state.sound_speed_size(), 1, "sound_speed");
  if (state.acceleration_size() != 0) expect(state.acceleration_size(), 2, "acceleration");
  const auto count = static_cast<std::size_t>(n);
  sph::InterfaceParticles P;
  P.id.assign(state.id().begin(), state.id().end());
  P.x.resize(count), P.v.resize(count), P.sigma.resize(count);
  std::copy_n(state.position().data(), 2 * count, doubles_of(P.x));
  std::copy_n(state.velocity().data(), 2 * count, doubles_of(P.v));
  for (std::size_t i = 0; i < count; ++i) {
    const double* s = state.stress().data() + 4 * i;  // xx, xy, yx, yy
    P.sigma[i] << s[0], s[1], s[2], s[3];
  }
  P.m.assign(state.mass().begin(), state.mass().end());
  P.rho.assign(state.density().begin(), state.density().end());
  P.h.assign(state.smoothing_length().begin(), state.smoothing_length().end());
  P.c.assign(state.sound_speed().begin(), state.sound_speed().end());
  P.a.resize(static_cast<std::size_t>(state.acceleration_size() / 2));
  std::copy_n(state.acceleration().data(), 2 * P.a.size(), doubles_of(P.a));
  for (std::size_t i = 0; i < count; ++i)
    if (!(P.m[i] > 0.0 && P.rho[i] > 0.0 && P.h[i] > 0.0))
      throw CouplingError("malformed InterfaceState: particle " + std::to_string(P.id[i]) +
                          " has a mass, density or smoothing length that is not positive");
  return P;
}

std::string check_hello(const Hello& hello, Phase expected) {
  if (hello.protocol_version() < kOldestProtocolVersion ||
      hello.protocol_version() > kProtocolVersion)
    return "protocol version " + std::to_string(hello.protocol_version()) + " of '" +
           hello.solver() + "' differs from the coupler's version " +
           std::to_string(kProtocolVersion) + " (it takes versions " +
           std::to_string(kOldestProtocolVersion) + " to " + std::to_string(kProtocolVersion) + ")";
  if (hello.phase() != expected)
    return "'" + hello.solver() + "' announced phase " + phase_name(hello.phase()) +
           " where the coupler expects " + phase_name(expected);
  if (!(hello.max_smoothing_length() > 0.0))
    return "'" + hello.solver() + "' announced a smoothing length that is not positive";
  return {};
}

void keep_freed_memory() {
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
}

std::string serialise(const Envelope& envelope) {
  return envelope.SerializeAsString();
}

Envelope parse(std::string_view bytes, const std::string& from) {
  Envelope envelope;
  if (!envelope.ParseFromArray(bytes.data(), static_cast<int>(bytes.size())) ||
      envelope.body_case() == Envelope::BODY_NOT_SET)
    throw CouplingError("garbage from " + from + ": " + std::to_string(bytes.size()) +
                        " bytes that are not a cosph coupling message");
  return envelope;
}

namespace {
// Serialised straight into the frame ZeroMQ sends: an interface of some
// 100 kB is not copied through a string first.
zmq::message_t frame_of(const Envelope& envelope) {
  zmq::message_t frame(envelope.ByteSizeLong());
  envelope.SerializeWithCachedSizesToArray(static_cast<std::uint8_t*>(frame.data()));
  return frame;
}
}  // namespace

std::string_view bytes_of(const zmq::message_t& frame) {
  return {static_cast<const char*>(frame.data()), frame.size()};
}

void send(zmq::socket_t& socket, const Envelope& envelope) {
  socket.send(frame_of(envelope), zmq::send_flags::none);
}

void send_to(zmq::socket_t& socket, const std::string& identity, const Envelope& envelope,
             zmq::send_flags flags) {
  socket.send(zmq::buffer(identity), zmq::send_flags::sndmore | flags);
  socket.send(frame_of(envelope), flags);
}

namespace {
// Whether a message is in within `timeout`; false when a signal interrupts the
// poll (EINTR), which the caller's loop then polls again.
bool poll_readable(zmq::socket_t& socket, std::chrono::milliseconds timeout) {
  zmq::pollitem_t item{socket.handle(), 0, ZMQ_POLLIN, 0};
  try {
    return zmq::poll(&item, 1, timeout) > 0;
  } catch (const zmq::error_t& error) {
    if (error.num() != EINTR) throw;
    return false;
  }
}

// Waits in slices, so that a stop request (SIGINT or SIGTERM: Ctrl-C, or the
// launcher's when another process failed) cuts what is left of the wait to
// kStopGrace. In a sound run the message comes within milliseconds (the other
// solver finishing its window), and the run stops cleanly at the coupler's
// next step, every process writing its checkpoint and final snapshot; a peer
// that died would otherwise hold the wait for the whole timeout, past the
// launcher's grace (5 s after a failure), and get this process killed. Any
// other signal interrupts the poll with EINTR, and the wait goes on.
bool wait_readable(zmq::socket_t& socket, std::chrono::milliseconds timeout,
                   std::chrono::microseconds spin = std::chrono::microseconds(0)) {
  using std::chrono::milliseconds, std::chrono::steady_clock;
  constexpr milliseconds kSlice{100}, kStopGrace{2000};
  const auto start = steady_clock::now();
  auto deadline = start + timeout;
  const auto spin_end = std::min(start + spin, deadline);
  while (steady_clock::now() < spin_end) {
    if (poll_readable(socket, milliseconds(0))) return true;
    sched_yield();  // this process's ZeroMQ I/O thread may need the core
  }
  bool stopping = false;
  for (;;) {
    const auto now = steady_clock::now();
    if (!stopping && sph::stop_requested()) {
      stopping = true;
      deadline = std::min(deadline, now + kStopGrace);
    }
    const auto left = std::chrono::ceil<milliseconds>(deadline - now);
    if (poll_readable(socket, std::clamp(left, milliseconds(0), kSlice))) return true;
    if (steady_clock::now() >= deadline) return false;
  }
}
}  // namespace

std::optional<Envelope> receive(zmq::socket_t& socket, std::chrono::milliseconds timeout,
                                const std::string& from, std::chrono::microseconds spin) {
  if (!wait_readable(socket, timeout, spin)) return std::nullopt;
  zmq::message_t frame;
  (void)socket.recv(frame, zmq::recv_flags::none);
  return parse(bytes_of(frame), from);
}

std::optional<RoutedFrame> receive_routed_frame(zmq::socket_t& socket,
                                                std::chrono::milliseconds timeout) {
  if (!wait_readable(socket, timeout)) return std::nullopt;
  zmq::message_t identity;
  (void)socket.recv(identity, zmq::recv_flags::none);
  RoutedFrame out{identity.to_string(), {}, 0};
  if (!identity.more()) return out;  // a ROUTER always adds the routing frame
  (void)socket.recv(out.frame, zmq::recv_flags::none);
  out.frames = 1;
  for (bool more = out.frame.more(); more; ++out.frames) {
    zmq::message_t extra;
    (void)socket.recv(extra, zmq::recv_flags::none);
    more = extra.more();
  }
  return out;
}

std::optional<Routed> receive_routed(zmq::socket_t& socket, std::chrono::milliseconds timeout) {
  std::optional<RoutedFrame> message = receive_routed_frame(socket, timeout);
  if (!message) return std::nullopt;
  if (message->frames != 1)
    throw CouplingError("garbage: a message of " + std::to_string(message->frames) +
                        " frames, not one");
  return Routed{message->identity, parse(bytes_of(message->frame), "a peer")};
}

}  // namespace cosph::coupling
