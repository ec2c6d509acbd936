// The cubic-spline kernel (docs/physics.md, "Kernel"; Monaghan & Lattanzio 1985), 2-D
// normalisation 10 / (7 pi h^2), support radius 2h. Defined once here: every
// solver, the coupler and the tests use this kernel and its gradient.
#pragma once

#include <numbers>

#include "sphcore/types.hpp"

namespace sph::kernel {

inline constexpr double kSupport = 2.0;  // support radius in units of h

inline constexpr double normalisation(double h) {
  return 10.0 / (7.0 * std::numbers::pi * h * h);
}

// W(r, h).
inline double W(double r, double h) {
  const double s = r / h;
  if (s >= 2.0) return 0.0;
  const double f =
      s < 1.0 ? 1.0 - 1.5 * s * s + 0.75 * s * s * s : 0.25 * (2.0 - s) * (2.0 - s) * (2.0 - s);
  return normalisation(h) * f;
}

// dW/dr(r, h).
inline double dW_dr(double r, double h) {
  const double s = r / h;
  if (s >= 2.0) return 0.0;
  const double df = s < 1.0 ? -3.0 * s + 2.25 * s * s : -0.75 * (2.0 - s) * (2.0 - s);
  return normalisation(h) * df / h;
}

// grad_i W_ij = dW/dr(r_ij) x_ij / r_ij; zero for a particle with itself.
inline Vec2 grad_W(const Vec2& x_ij, double r_ij, double h) {
  if (r_ij <= 0.0) return Vec2::Zero();
  return (dW_dr(r_ij, h) / r_ij) * x_ij;
}

// W(r, h) with the constants of one h taken once: W divides by h twice on
// every call, and in a pair loop those divisions were the critical path.
class Value {
 public:
  explicit Value(double h) : inverse_h_(1.0 / h), normalisation_(normalisation(h)) {}

  double operator()(double r) const {
    const double s = r * inverse_h_;
    const double f =
        s < 1.0 ? 1.0 - 1.5 * s * s + 0.75 * s * s * s : 0.25 * (2.0 - s) * (2.0 - s) * (2.0 - s);
    return s >= 2.0 ? 0.0 : normalisation_ * f;
  }

 private:
  double inverse_h_, normalisation_;
};

// dW/dr(r, h) / r for one fixed h, with the constants worked out once: the
// pair loops call it for every pair, where the three divisions of dW_dr()
// dominated the cost of finding neighbours.
class GradientFactor {
 public:
  explicit GradientFactor(double h) : inverse_h_(1.0 / h), scale_(normalisation(h) / h) {}

  // Zero at r = 0: two particles squeezed onto one point (water pairing near
  // the tip of the elastic plate did that) have no direction between them.
  // Both branches are computed and one selected, so that a loop over pairs
  // vectorises instead of mispredicting s < 1 on every other pair.
  double operator()(double r) const {
    const double s = r * inverse_h_;
    const double inner = -3.0 * s + 2.25 * s * s;
    const double outer = -0.75 * (2.0 - s) * (2.0 - s);
    const double F = scale_ * (s < 1.0 ? inner : outer) / r;
    return s >= 2.0 || r <= 0.0 ? 0.0 : F;
  }

 private:
  double inverse_h_, scale_;
};

}  // namespace sph::kernel
