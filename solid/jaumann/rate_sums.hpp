// What the solid's rates pass sums over a particle's neighbours (docs/physics.md,
// "Jaumann solid"): sum_j V_j v_ij . grad_i W_ij (continuity over rho_i), the
// renormalisation matrix M_i and the raw velocity gradient.
#pragma once

#include "sphcore/renormalisation.hpp"
#include "sphcore/types.hpp"

namespace cosph::solid::jaumann {

using sph::Vec2;

// A pair adds the same terms to i and to j, weighted by V_j and by V_i, since
// x_ij, v_ij and grad_i W_ij all change sign from j's side: the pass works
// each pair out once.
struct RateSums {
  double volume_divergence = 0.0;
  sph::GradientSums gradients;

  void add(double V, const Vec2& grad_W_ij, const Vec2& x_ij, const Vec2& v_ij) {
    const Vec2 Vg = V * grad_W_ij;
    volume_divergence += v_ij.dot(Vg);
    gradients.add(Vg, x_ij, v_ij);
  }
  RateSums& operator+=(const RateSums& other) {
    volume_divergence += other.volume_divergence;
    gradients += other.gradients;
    return *this;
  }
};

}  // namespace cosph::solid::jaumann
