// The water's total stress (docs/physics.md, "Momentum" and "Physical
// viscosity"): sigma = -p I + tau, kept by its three components (tau is
// symmetric) for the momentum pass's bracket (sphcore/momentum_bracket.hpp).
#pragma once

#include "sphcore/momentum_bracket.hpp"
#include "sphcore/types.hpp"

namespace cosph::fluid {

using sph::Mat2;
using sph::SymmetricStress;

// sigma = -p I + tau; tau is symmetric by construction (viscous_stress.hpp).
inline SymmetricStress total_stress(double p, const Mat2& tau) {
  return {-p + tau(0, 0), tau(0, 1), -p + tau(1, 1)};
}

}  // namespace cosph::fluid
