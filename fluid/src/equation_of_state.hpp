// Tait equation of state for weakly compressible water (docs/physics.md,
// "Equation of state"):
//   P = P0 [ (rho/rho0)^gamma - 1 ],  gamma = 7,  P0 = rho0 c0^2 / gamma.
#pragma once

#include <cmath>

namespace cosph::fluid {

class TaitEquationOfState {
 public:
  static constexpr double kGamma = 7.0;

  TaitEquationOfState(double rho0, double c0) : rho0_(rho0), P0_(rho0 * c0 * c0 / kGamma) {}

  double pressure(double rho) const {
    const double ratio = rho / rho0_;
    const double ratio2 = ratio * ratio;
    return P0_ * (ratio2 * ratio2 * ratio2 * ratio - 1.0);  // gamma = 7 without pow()
  }

  // The density at which the water has pressure P (walls, hydrostatic start).
  double density(double P) const { return rho0_ * std::pow(1.0 + P / P0_, 1.0 / kGamma); }

  double rho0() const { return rho0_; }
  double P0() const { return P0_; }

 private:
  double rho0_, P0_;
};

}  // namespace cosph::fluid
