// The Wendland C2 kernel (docs/physics.md, "Kernel"; Wendland 1995, Adv.
// Comput. Math. 4:389; in SPH: Dehnen & Aly 2012, MNRAS 425:1068), 2-D
// normalisation 7 / (4 pi h^2), support radius 2h like the cubic spline's.
// With q = r / h:
//   W(r, h) = 7 / (4 pi h^2) (1 - q/2)^4 (2q + 1),   dW/dr = 7 / (4 pi h^3) (-5 q) (1 - q/2)^3.
// Its Fourier transform is positive, so unlike the cubic spline it has no
// pairing instability however many neighbours it holds: particles stay
// ordered, and the pressure noise of disordered particles is smaller.
#pragma once

#include <numbers>

#include "sphcore/kernel.hpp"
#include "sphcore/types.hpp"

namespace sph::kernel::wendland_c2 {

inline constexpr double normalisation(double h) {
  return 7.0 / (4.0 * std::numbers::pi * h * h);
}

// W(r, h).
inline double W(double r, double h) {
  const double q = r / h;
  if (q >= kSupport) return 0.0;
  const double u = 1.0 - 0.5 * q;
  return normalisation(h) * u * u * u * u * (2.0 * q + 1.0);
}

// dW/dr(r, h).
inline double dW_dr(double r, double h) {
  const double q = r / h;
  if (q >= kSupport) return 0.0;
  const double u = 1.0 - 0.5 * q;
  return normalisation(h) * (-5.0 * q * u * u * u) / h;
}

// W(r) for one fixed h, the constants taken once (as kernel::Value).
class Value {
 public:
  explicit Value(double h) : inverse_h_(1.0 / h), normalisation_(normalisation(h)) {}

  double operator()(double r) const {
    const double q = r * inverse_h_;
    const double u = 1.0 - 0.5 * q;
    return q >= kSupport ? 0.0 : normalisation_ * u * u * u * u * (2.0 * q + 1.0);
  }

 private:
  double inverse_h_, normalisation_;
};

// dW/dr(r) / r for one fixed h (as kernel::GradientFactor): -5 q (1 - q/2)^3 / r
// = -5 (1 - q/2)^3 / h, no division by r and finite (not zero) at r = 0 where
// x_ij = 0 makes the gradient vanish anyway.
class GradientFactor {
 public:
  explicit GradientFactor(double h)
      : inverse_h_(1.0 / h), scale_(-5.0 * normalisation(h) / (h * h)) {}

  double operator()(double r) const {
    const double q = r * inverse_h_;
    const double u = 1.0 - 0.5 * q;
    return q >= kSupport ? 0.0 : scale_ * u * u * u;
  }

 private:
  double inverse_h_, scale_;
};

}  // namespace sph::kernel::wendland_c2
