// A prescribed scalar motion q(t) with its rate and acceleration: a piston's
// displacement or a rotation's angle (docs/physics.md, "Moving walls").
// Either a ramped sinusoid, differentiated analytically, or samples from a
// file, joined by a cubic Hermite curve with three-point slopes: exact for a
// motion quadratic in time (a uniformly accelerated tank), continuous in q and
// dq/dt, and with d2q/dt2 linear within each interval.
#pragma once

#include <vector>

namespace cosph::fluid {

struct MotionState {
  double value = 0.0;         // q
  double rate = 0.0;          // dq/dt
  double acceleration = 0.0;  // d2q/dt2
};

class PrescribedMotion {
 public:
  PrescribedMotion() = default;  // q = 0 always
  // q(t) = amplitude sin(2 pi t / period) r(t), r(t) = (1 - cos(pi t / ramp)) / 2
  // for t < ramp, else 1; ramp_time 0: no ramp.
  static PrescribedMotion sinusoid(double amplitude, double period, double ramp_time);
  // The samples (t_k, q_k), at least two, t_k increasing. Before t_0 and after
  // the last time, q holds its end value at rest.
  static PrescribedMotion samples(std::vector<double> times, std::vector<double> values);

  MotionState at(double t) const;

 private:
  MotionState sinusoid_at(double t) const;
  MotionState samples_at(double t) const;

  bool sampled_ = false;
  double amplitude_ = 0.0, omega_ = 0.0, ramp_time_ = 0.0;
  std::vector<double> times_, values_, slopes_;  // slopes: dq/dt at the samples
};

}  // namespace cosph::fluid
