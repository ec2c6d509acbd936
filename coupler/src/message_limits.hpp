// How large a message the coupler takes from a peer (proto/coupling.proto).
// A Hello is a few numbers and a solver's name. An interface state carries per
// particle an id (a varint, at most 10 bytes) and 14 doubles (position 2,
// velocity 2, stress 4, mass, density, smoothing length, sound speed,
// acceleration 2), with the fields' tags and lengths, its bounds and the
// gauges besides, a few kB for the whole message.
#pragma once

#include <cstddef>
#include <cstdint>

namespace cosph::coupler {

inline constexpr std::size_t kLargestHelloBytes = 64 * 1024;
inline constexpr std::size_t kBytesPerInterfaceParticle = 10 + 14 * 8;
inline constexpr std::size_t kStateOverheadBytes = 64 * 1024;

// The most particles a solver may announce in its Hello: some 200 times the
// largest scene here, and a state of them still fits in half a GB.
inline constexpr std::uint64_t kLargestParticleCount = std::uint64_t{1} << 22;

// The largest state a solver that announced `particle_count` particles can
// send: every one of them at the interface.
inline constexpr std::size_t largest_state_bytes(std::uint64_t particle_count) {
  return kStateOverheadBytes +
         kBytesPerInterfaceParticle * static_cast<std::size_t>(particle_count);
}

// ZeroMQ's own limit (ZMQ_MAXMSGSIZE), fixed when the socket binds, before
// any Hello: it closes the connection of a peer whose message is larger,
// without reading it. The coupler then holds each registered solver to the
// limit of its own particle count, and anyone else to kLargestHelloBytes.
inline constexpr std::size_t kSocketLimitBytes = largest_state_bytes(kLargestParticleCount);

}  // namespace cosph::coupler
