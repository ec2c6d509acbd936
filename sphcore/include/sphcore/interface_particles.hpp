// What a solver shows the other phase: its particles near the interface, with
// everything the cross-phase momentum term needs (docs/physics.md,
// "Coupling"). Plain data, so that solver cores know nothing of the
// transport that carries it.
#pragma once

#include <algorithm>
#include <vector>

#include "sphcore/types.hpp"

namespace sph {

struct InterfaceParticles {
  std::vector<long> id;
  std::vector<Vec2> x, v;
  std::vector<Mat2> sigma;  // full stress tensor, tension positive
  std::vector<double> m, rho, h, c;
  // A solid's total acceleration at each particle, from its last closing kick
  // (the moving wall's a_w); empty from a solver that does not send it.
  std::vector<Vec2> a;

  std::size_t size() const { return x.size(); }
  void reserve(std::size_t n) {
    id.reserve(n), x.reserve(n), v.reserve(n), sigma.reserve(n);
    m.reserve(n), rho.reserve(n), h.reserve(n), c.reserve(n);
  }
  bool has_acceleration() const { return !x.empty() && a.size() == x.size(); }
  void clear() {
    id.clear(), x.clear(), v.clear(), sigma.clear();
    m.clear(), rho.clear(), h.clear(), c.clear(), a.clear();
  }
  void add(long particle_id, const Vec2& position, const Vec2& velocity, const Mat2& stress,
           double mass, double density, double smoothing_length, double sound_speed) {
    id.push_back(particle_id);
    x.push_back(position);
    v.push_back(velocity);
    sigma.push_back(stress);
    m.push_back(mass);
    rho.push_back(density);
    h.push_back(smoothing_length);
    c.push_back(sound_speed);
  }
  // As add, for a solver that sends its acceleration: every particle or none.
  void add(long particle_id, const Vec2& position, const Vec2& velocity, const Vec2& acceleration,
           const Mat2& stress, double mass, double density, double smoothing_length,
           double sound_speed) {
    add(particle_id, position, velocity, stress, mass, density, smoothing_length, sound_speed);
    a.push_back(acceleration);
  }
};

// Hands the coupler's per-particle values (accelerations, density rates),
// given in the order of the particles a solver sent (their indices in `sent`),
// to the solver's own array; the rest get `none`.
template <class T>
void scatter_interface_values(const std::vector<long>& sent, const std::vector<T>& values,
                              const T& none, std::vector<T>& external) {
  std::fill(external.begin(), external.end(), none);
  for (std::size_t k = 0; k < sent.size() && k < values.size(); ++k) external[sent[k]] = values[k];
}

inline void scatter_interface_accelerations(const std::vector<long>& sent,
                                            const std::vector<Vec2>& accelerations,
                                            std::vector<Vec2>& external_a) {
  scatter_interface_values(sent, accelerations, Vec2::Zero().eval(), external_a);
}

}  // namespace sph
