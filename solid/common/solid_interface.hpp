// The solid particles a coupled run shares with the water, and the coupler's
// accelerations back onto them: the same for every solid model whose
// particles carry id, x, v, kick_a, sigma, m, rho and c (cosph-solid,
// cosph-solid-tl).
#pragma once

#include <cstddef>
#include <vector>

#include "sphcore/interface_particles.hpp"
#include "sphcore/region.hpp"
#include "sphcore/types.hpp"

namespace cosph::solid {

class SolidInterface {
 public:
  // The particles inside `region`, clamped ones too: water presses on them.
  template <class Particles>
  void collect(const Particles& P, double h, const sph::Region& region,
               sph::InterfaceParticles& out) {
    out.clear();
    sent_.clear();
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (!region.contains(P.x[i])) continue;
      sent_.push_back(static_cast<long>(i));
      out.add(P.id[i], P.x[i], P.v[i], P.kick_a[i], P.sigma[i], P.m[i], P.rho[i], h, P.c[i]);
    }
  }

  // The coupler's accelerations, in the order of the last collect, into
  // external_a; the particles not sent get none.
  void scatter(const std::vector<sph::Vec2>& accelerations,
               std::vector<sph::Vec2>& external_a) const {
    sph::scatter_interface_accelerations(sent_, accelerations, external_a);
  }

 private:
  std::vector<long> sent_;  // particle indices of the last collect
};

}  // namespace cosph::solid
