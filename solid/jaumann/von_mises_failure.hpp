// Von Mises failure (docs/physics.md, "Von Mises failure"): a solid particle whose equivalent
// stress sigma_VM reaches the yield stress sigma_y fails, for good. A failed
// particle is crushed material: it still resists compression (its pressure
// P >= 0), but carries no tension and no shear, so it is free to separate
// from the body. Its density does not fall below rho0 (jaumann_solver.cpp):
// separating is not stretching.
#pragma once

#include <algorithm>

#include "sphcore/types.hpp"
#include "sphcore/von_mises.hpp"

namespace cosph::solid::jaumann {

using sph::Mat2;

inline bool yields(const Mat2& sigma, double yield_stress) {
  return sph::von_mises(sigma) >= yield_stress;
}

// The stress a failed particle carries at pressure P.
inline Mat2 failed_stress(double P) {
  return -std::max(P, 0.0) * Mat2::Identity();
}

}  // namespace cosph::solid::jaumann
