// Hourglass control for total-Lagrangian SPH (Ganzenmueller 2015, CMAME 286,
// "An hourglass control algorithm for Lagrangian Smooth Particle
// Hydrodynamics"). F_i is a weighted average over the neighbours, blind to
// displacement patterns that average out (a zig-zag between neighbouring
// particles leaves F unchanged and costs no energy). Each particle predicts
// where a neighbour should be, F_i X_ji, and the pair is pushed towards the
// mean of the two predictions:
//   eps^i_ij = F_i X_ji - x_ji,  delta^i_ij = eps^i_ij . x_ji / r_ji  (X_ji = X_j - X_i)
//   f_i = -alpha/2 V0_i V0_j W0_ij / |X_ji|^2 (E_i delta^i_ij + E_j delta^j_ij) x_ji / r_ji
// delta^j_ij uses F_j X_ji (its prediction of the same pair seen from j), so
// f_j = -f_i exactly and the force is central. A linear or quadratic
// displacement field (uniform stretch, pure bending) has zero error, so the
// term leaves them alone and only resists the modes F cannot see; near the
// free surfaces, where F of a quadratic field is only first-order accurate,
// it stiffens bending a little.
//
// alpha is solid.hourglass_control, default 5 (kDefaultHourglassControl in
// solid_parameters.hpp): the value of the author's own implementation, LAMMPS
// smd/tlsph, whose examples all use hg = 10 with a force half as large per unit
// coefficient (delta = 0.5 gamma . n there), i.e. alpha = 5 in the form above.
// The kernels differ (LAMMPS: spiky kernel, support 2.01 dx; here the cubic
// spline, support 2.6 dx), so the match is of the coefficient, not of every
// pair force. 0 turns the control off. Without it the oscillating plate is too
// soft, converging towards theory only as the resolution grows: bending mixes
// with the patterns F cannot see; the period falls as alpha grows
// (docs/results/oscillating_plate_tl.md; docs/physics.md, "Hourglass control").
#pragma once

#include <cmath>

#include "sphcore/types.hpp"

namespace cosph::solid::tl {

using sph::Mat2;
using sph::Vec2;

// Force on i from its pair with j (divide by m_i for the acceleration).
// X_ji = X_j - X_i, x_ji = x_j - x_i and r = |x_ji|, which the caller has.
inline Vec2 hourglass_force(double alpha, const Mat2& F_i, const Mat2& F_j, double E_i, double E_j,
                            double V0_i, double V0_j, double W0_ij, const Vec2& X_ji,
                            const Vec2& x_ji, double r) {
  if (r <= 0.0) return Vec2::Zero();
  const Vec2 n = x_ji / r;
  const double delta_i = (F_i * X_ji - x_ji).dot(n);
  const double delta_j = (F_j * X_ji - x_ji).dot(n);
  const double scale = -0.5 * alpha * (V0_i * V0_j) * W0_ij / X_ji.squaredNorm();
  return (scale * (E_i * delta_i + E_j * delta_j)) * n;
}

}  // namespace cosph::solid::tl
