// An axis-aligned box of the plane: what a solver tells the coupler it may
// interact within, a wall, a clamp, a gauge's area.
#pragma once

#include <algorithm>
#include <limits>
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

}  // namespace sph
