#include "solid_gauges.hpp"

#include <algorithm>
#include <limits>

namespace cosph::solid {

std::vector<int> tip_gauge_ids(const std::vector<int>& id, const std::vector<Vec2>& x0,
                               const sph::Vec2& p, double dx) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const Vec2& x : x0) nearest = std::min(nearest, (x - p).norm());
  std::vector<int> ids;
  for (std::size_t i = 0; i < x0.size(); ++i)
    if ((x0[i] - p).norm() <= nearest + 1e-6 * dx) ids.push_back(id[i]);
  std::sort(ids.begin(), ids.end());
  return ids;
}

Vec2 mean_displacement(const std::vector<int>& id, const std::vector<Vec2>& x,
                       const std::vector<Vec2>& x0, const std::vector<int>& tip_ids) {
  Vec2 sum = Vec2::Zero();
  for (std::size_t i = 0; i < x.size(); ++i)
    if (std::binary_search(tip_ids.begin(), tip_ids.end(), id[i])) sum += x[i] - x0[i];
  return tip_ids.empty() ? sum : Vec2(sum / static_cast<double>(tip_ids.size()));
}

Vec2 broken_part_centre(const std::vector<Vec2>& x0, const std::vector<Vec2>& x,
                        const std::vector<double>& m, const std::vector<std::uint8_t>& clamped,
                        double below_y) {
  Vec2 moment = Vec2::Zero();
  double mass = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (clamped[i] || x0[i].y() >= below_y) continue;
    moment += m[i] * x[i];
    mass += m[i];
  }
  return mass > 0.0 ? Vec2(moment / mass) : Vec2::Zero();
}

}  // namespace cosph::solid
