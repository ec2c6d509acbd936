// Thrown when a solver's state stops being physical (not finite, faster than
// sound, crushed or torn density): the run stops instead of writing garbage.
#pragma once

#include <stdexcept>

namespace sph {

class RunawayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sph
