// How long any process of a coupled run waits for a peer (coupling.timeout),
// read in one place for the coupler and the solvers alike.
#pragma once

#include <cmath>

#include "sphcore/case_file.hpp"

namespace cosph::coupling {

// What coupling.timeout = 0 means: long enough for a solver's slowest step on
// a busy machine, short enough that a dead peer is noticed.
inline constexpr double kDefaultTimeoutSeconds = 10.0;
inline constexpr double kMaxTimeoutSeconds = 1e6;

// coupling.timeout in seconds, or the default; refuses a negative or
// non-finite value, naming the file and the field.
inline double coupling_timeout_seconds(const sph::CaseFile& case_file) {
  const double timeout = case_file.config.coupling().timeout();
  sph::require(
      std::isfinite(timeout) && timeout >= 0.0, case_file, "coupling.timeout",
      "must be a finite number of seconds, not negative, got " + sph::format_number(timeout));
  // Waits are counted in milliseconds in a 64-bit integer: far below its limit.
  sph::require(timeout <= kMaxTimeoutSeconds, case_file, "coupling.timeout",
               "must be at most " + sph::format_number(kMaxTimeoutSeconds) +
                   " s (11.6 days), got " + sph::format_number(timeout));
  return timeout > 0.0 ? timeout : kDefaultTimeoutSeconds;
}

}  // namespace cosph::coupling
