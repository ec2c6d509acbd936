#include "prescribed_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cosph::fluid {
namespace {

// dq/dt at sample k of the parabola through it and its two nearest
// neighbours: exact for a quadratic q(t), on uneven times too.
double three_point_slope(const std::vector<double>& t, const std::vector<double>& q,
                         std::size_t k) {
  const std::size_t n = t.size();
  if (n == 2) return (q[1] - q[0]) / (t[1] - t[0]);
  const std::size_t a = k == 0 ? 0 : (k == n - 1 ? n - 3 : k - 1);
  const double t0 = t[a], t1 = t[a + 1], t2 = t[a + 2], s = t[k];
  // The derivative of the Lagrange parabola through (t0, q0), (t1, q1), (t2, q2) at s.
  return q[a] * ((s - t1) + (s - t2)) / ((t0 - t1) * (t0 - t2)) +
         q[a + 1] * ((s - t0) + (s - t2)) / ((t1 - t0) * (t1 - t2)) +
         q[a + 2] * ((s - t0) + (s - t1)) / ((t2 - t0) * (t2 - t1));
}

}  // namespace

PrescribedMotion PrescribedMotion::sinusoid(double amplitude, double period, double ramp_time) {
  PrescribedMotion motion;
  motion.amplitude_ = amplitude;
  motion.omega_ = 2.0 * std::numbers::pi / period;
  motion.ramp_time_ = ramp_time;
  return motion;
}

PrescribedMotion PrescribedMotion::samples(std::vector<double> times, std::vector<double> values) {
  PrescribedMotion motion;
  motion.sampled_ = true;
  motion.times_ = std::move(times);
  motion.values_ = std::move(values);
  for (std::size_t k = 0; k < motion.times_.size(); ++k)
    motion.slopes_.push_back(three_point_slope(motion.times_, motion.values_, k));
  return motion;
}

MotionState PrescribedMotion::at(double t) const {
  return sampled_ ? samples_at(t) : sinusoid_at(t);
}

MotionState PrescribedMotion::sinusoid_at(double t) const {
  // s(t) = A sin(w t) and the ramp r(t), multiplied: (s r)'' = s'' r + 2 s' r' + s r''.
  const double w = omega_;
  const double s = amplitude_ * std::sin(w * t), ds = amplitude_ * w * std::cos(w * t),
               d2s = -w * w * s;
  double r = 1.0, dr = 0.0, d2r = 0.0;
  if (t < ramp_time_) {
    const double k = std::numbers::pi / ramp_time_;
    r = 0.5 * (1.0 - std::cos(k * t));
    dr = 0.5 * k * std::sin(k * t);
    d2r = 0.5 * k * k * std::cos(k * t);
  }
  return {s * r, ds * r + s * dr, d2s * r + 2.0 * ds * dr + s * d2r};
}

MotionState PrescribedMotion::samples_at(double t) const {
  if (t <= times_.front()) return {values_.front(), 0.0, 0.0};
  if (t >= times_.back()) return {values_.back(), 0.0, 0.0};
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin()) -
      1;
  const double dt = times_[k + 1] - times_[k], u = (t - times_[k]) / dt;
  const double q0 = values_[k], q1 = values_[k + 1];
  const double m0 = slopes_[k] * dt, m1 = slopes_[k + 1] * dt;  // slopes per unit u
  // The cubic Hermite basis h00 = 2u^3 - 3u^2 + 1, h10 = u^3 - 2u^2 + u,
  // h01 = -2u^3 + 3u^2, h11 = u^3 - u^2, and its derivatives in u.
  const double u2 = u * u, u3 = u2 * u;
  const double value = (2 * u3 - 3 * u2 + 1) * q0 + (u3 - 2 * u2 + u) * m0 +
                       (-2 * u3 + 3 * u2) * q1 + (u3 - u2) * m1;
  const double rate = (6 * u2 - 6 * u) * q0 + (3 * u2 - 4 * u + 1) * m0 + (-6 * u2 + 6 * u) * q1 +
                      (3 * u2 - 2 * u) * m1;
  const double acceleration =
      (12 * u - 6) * q0 + (6 * u - 4) * m0 + (-12 * u + 6) * q1 + (6 * u - 2) * m1;
  return {value, rate / dt, acceleration / (dt * dt)};
}

}  // namespace cosph::fluid
