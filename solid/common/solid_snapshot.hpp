// The snapshot fields every solid model writes (docs/physics.md, "Stress
// sum"): identity, velocity, density, pressure, the in-plane stress and its
// von Mises value, and the flags. A model adds its own fields between the
// stress and the flags (the total-Lagrangian solid's J).
#pragma once

#include <cstdint>
#include <vector>

#include "sphcore/snapshot_writer.hpp"
#include "sphcore/types.hpp"
#include "sphcore/von_mises.hpp"

namespace cosph::solid {

// The particles' id, velocity, density and stress, with `pressure` the mean
// normal stress the model defines.
template <class Particles>
sph::Snapshot stress_snapshot(const Particles& P, const std::vector<double>& pressure) {
  const std::size_t n = P.size();
  std::vector<double> xx(n), xy(n), yy(n), vm(n);
  for (std::size_t i = 0; i < n; ++i) {
    xx[i] = P.sigma[i](0, 0);
    xy[i] = P.sigma[i](0, 1);
    yy[i] = P.sigma[i](1, 1);
    vm[i] = sph::von_mises(P.sigma[i]);
  }
  sph::Snapshot snapshot(P.x);
  snapshot.add_scalar("id", P.id);
  snapshot.add_vector("velocity", P.v);
  snapshot.add_scalar("density", P.rho);
  snapshot.add_scalar("pressure", pressure);
  snapshot.add_scalar("stress_xx", xx);
  snapshot.add_scalar("stress_xy", xy);
  snapshot.add_scalar("stress_yy", yy);
  snapshot.add_scalar("von_mises", vm);
  return snapshot;
}

// The failed and clamped flags, 0 or 1 per particle.
inline void add_flags(sph::Snapshot& snapshot, const std::vector<std::uint8_t>& failed,
                      const std::vector<std::uint8_t>& clamped) {
  snapshot.add_scalar("failed", std::vector<int>(failed.begin(), failed.end()));
  snapshot.add_scalar("clamped", std::vector<int>(clamped.begin(), clamped.end()));
}

}  // namespace cosph::solid
