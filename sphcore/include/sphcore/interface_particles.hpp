// What a solver shows the other phase: its particles near the interface, with
// everything the cross-phase momentum term needs (docs/physics.md,
// "Coupling"). Plain data, so that solver cores know nothing of the
// transport that carries it.
#pragma once

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "sphcore/types.hpp"

namespace sph {

struct Region {
  Vec2 min = Vec2::Constant(std::numeric_limits<double>::infinity());
  Vec2 max = Vec2::Constant(-std::numeric_limits<double>::infinity());

  static Region everything() {
    const double inf = std::numeric_limits<double>::infinity();
    return {Vec2(-inf, -inf), Vec2(inf, inf)};
  }
  bool empty() const { return !(min.x() <= max.x() && min.y() <= max.y()); }
  // Without a branch (& of the four tests, not &&), so that a screen over
  // all particles (sph::parallel_any) vectorises.
  bool contains(const Vec2& p) const {
    return (p.x() >= min.x()) & (p.x() <= max.x()) & (p.y() >= min.y()) & (p.y() <= max.y());
  }
  void include(const Vec2& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  Region grown(double margin) const {
    if (empty()) return *this;
    return {min - Vec2::Constant(margin), max + Vec2::Constant(margin)};
  }
};

// The box around the positions i with included(i): a solver's interaction
// bounds, which it sends every coupled step. One pass over the plain
// coordinates, which vectorises (a loop of Region::include does not); a
// position left out counts as +-infinity.
template <class Included>
Region bounds_of(const std::vector<Vec2>& positions, Included&& included) {
  const double inf = std::numeric_limits<double>::infinity();
  const double* const x = doubles_of(positions);
  const long n = static_cast<long>(positions.size());
  double min_x = inf, min_y = inf, max_x = -inf, max_y = -inf;
#pragma omp simd reduction(min : min_x, min_y) reduction(max : max_x, max_y)
  for (long i = 0; i < n; ++i) {
    const bool in = included(i);
    min_x = std::min(min_x, in ? x[2 * i] : inf);
    min_y = std::min(min_y, in ? x[2 * i + 1] : inf);
    max_x = std::max(max_x, in ? x[2 * i] : -inf);
    max_y = std::max(max_y, in ? x[2 * i + 1] : -inf);
  }
  return {Vec2(min_x, min_y), Vec2(max_x, max_y)};
}

// The box around every position.
inline Region bounds_of(const std::vector<Vec2>& positions) {
  return bounds_of(positions, [](long) { return true; });
}

struct InterfaceParticles {
  std::vector<long> id;
  std::vector<Vec2> x, v;
  std::vector<Mat2> sigma;  // full stress tensor, tension positive
  std::vector<double> m, rho, h, c;

  std::size_t size() const { return x.size(); }
  void reserve(std::size_t n) {
    id.reserve(n), x.reserve(n), v.reserve(n), sigma.reserve(n);
    m.reserve(n), rho.reserve(n), h.reserve(n), c.reserve(n);
  }
  void clear() {
    id.clear(), x.clear(), v.clear(), sigma.clear();
    m.clear(), rho.clear(), h.clear(), c.clear();
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

// One measurement of a solver, a column of timeseries.csv.
struct Gauge {
  std::string name;
  std::string unit;
  double value;
};

}  // namespace sph
