// A mode of a solver's own dynamics and the damping ratio its dissipation
// gives it. A solid states its fastest one in a coupled run (Hello fields
// fastest_mode_*, proto/coupling.proto), and the coupler bounds multi-rate
// windows by it (docs/auto_substeps.md). 0, 0: not stated.
#pragma once

namespace sph {

struct DampedMode {
  double angular_frequency = 0.0;  // rad/s
  double damping_ratio = 0.0;
};

}  // namespace sph
