#include "sphcore/lattice.hpp"

#include <cmath>

namespace sph {

std::vector<Vec2> fill_box(const cosph::config::Box& box, double spacing) {
  // Round, not floor: a box meant to hold 18 columns must not get 17 from 17.9999.
  const long nx = std::lround((box.max().x() - box.min().x()) / spacing);
  const long ny = std::lround((box.max().y() - box.min().y()) / spacing);
  std::vector<Vec2> points;
  points.reserve(static_cast<std::size_t>(std::max(nx, 0L) * std::max(ny, 0L)));
  for (long j = 0; j < ny; ++j)
    for (long i = 0; i < nx; ++i)
      points.emplace_back(box.min().x() + (static_cast<double>(i) + 0.5) * spacing,
                          box.min().y() + (static_cast<double>(j) + 0.5) * spacing);
  return points;
}

bool contains(const cosph::config::Box& box, const Vec2& p) {
  return p.x() >= box.min().x() && p.x() <= box.max().x() && p.y() >= box.min().y() &&
         p.y() <= box.max().y();
}

}  // namespace sph
