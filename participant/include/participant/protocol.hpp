// Building, checking and parsing the messages of proto/coupling.proto, and
// moving them over ZeroMQ with a timeout on every receive. The conversions are
// pure functions, tested without a network (tests/coupling).
#pragma once

#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>
#include <zmq.hpp>

#include "coupling.pb.h"
#include "participant/coupling_error.hpp"
#include "sphcore/interface_particles.hpp"
#include "sphcore/region.hpp"

namespace cosph::coupling {

inline constexpr unsigned kProtocolVersion = 3;
// Version 3 added InterfaceState.acceleration, which a version-2 peer leaves
// empty: the coupler still takes it, and leaves that term out.
inline constexpr unsigned kOldestProtocolVersion = 2;

const char* phase_name(Phase phase);

Region to_proto(const sph::Region& region);
sph::Region from_proto(const Region& region);

// The messages' packed arrays hold 2-vectors as sph::doubles_of lays them
// out, so that they are copied whole rather than value by value.
using sph::doubles_of;

void to_proto(const sph::InterfaceParticles& particles, InterfaceState& state);
// Throws CouplingError if the arrays do not have one entry per particle
// (acceleration: one per particle, or none).
sph::InterfaceParticles from_proto(const InterfaceState& state);

// Empty if the Hello is acceptable (a protocol version from
// kOldestProtocolVersion to kProtocolVersion) for a peer of the expected
// phase, else the reason, naming what differs.
std::string check_hello(const Hello& hello, Phase expected);

// Every step the coupler builds and frees messages of some 100 kB. Above
// glibc's mmap threshold each one was mapped and unmapped again, and the page
// faults took longer than the pair forces themselves (on the elastic plate the
// coupler's pair forces fell from 0.19 to 0.07 ms per step once freed memory
// stayed in the heap). Call once, at the start of main, before any thread.
void keep_freed_memory();

std::string serialise(const Envelope& envelope);
// Throws CouplingError naming `from` if the bytes are not an Envelope.
Envelope parse(std::string_view bytes, const std::string& from);

// One-frame messages (DEALER side) and routed ones (ROUTER side: identity,
// then the frame). Receives return nothing when the timeout passes; once a
// stop is requested (sph::stop_requested()), they wait at most two seconds
// more: the caller tells which.
void send(zmq::socket_t& socket, const Envelope& envelope);
// dontwait: drop the message rather than wait for a peer that does not read.
void send_to(zmq::socket_t& socket, const std::string& identity, const Envelope& envelope,
             zmq::send_flags flags = zmq::send_flags::none);
// `spin`: how long to poll, yielding the core between polls, before the
// thread sleeps until the message comes (zero: sleep at once). An answer
// expected within a round trip or two is picked up without waking a sleeping
// core, which costs about 0.1 ms on a virtual machine; MPI libraries
// busy-poll for the same reason.
std::optional<Envelope> receive(zmq::socket_t& socket, std::chrono::milliseconds timeout,
                                const std::string& from,
                                std::chrono::microseconds spin = std::chrono::microseconds(0));
struct Routed {
  std::string identity;
  Envelope envelope;
};
// Throws CouplingError for a message that is not one frame holding an Envelope.
std::optional<Routed> receive_routed(zmq::socket_t& socket, std::chrono::milliseconds timeout);

// A routed message as it came, not parsed yet: the coupler checks its size
// and its sender before it parses it. `frames` counts the frames after the
// routing frame (the protocol sends one; the rest are read and dropped).
struct RoutedFrame {
  std::string identity;
  zmq::message_t frame;
  int frames = 0;
};
std::optional<RoutedFrame> receive_routed_frame(zmq::socket_t& socket,
                                                std::chrono::milliseconds timeout);
// What a frame holds, for parse().
std::string_view bytes_of(const zmq::message_t& frame);

}  // namespace cosph::coupling
