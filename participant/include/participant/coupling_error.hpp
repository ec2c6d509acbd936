// The error of the coupling layer, apart from the protocol (protocol.hpp) so
// that a solver's time loop can tell it from its own errors without seeing
// ZeroMQ or the generated messages.
#pragma once

#include <stdexcept>

namespace cosph::coupling {

// A peer misbehaved, vanished or refused us: the message is ready for a user.
class CouplingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace cosph::coupling
