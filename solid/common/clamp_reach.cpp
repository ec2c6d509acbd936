#include "clamp_reach.hpp"

#include <cmath>

#include "sphcore/cell_grid.hpp"

namespace cosph::solid {

std::vector<std::uint8_t> clamped_beyond(const std::vector<sph::Vec2>& x,
                                         const std::vector<std::uint8_t>& clamped, double reach) {
  std::vector<sph::Vec2> free;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!clamped[i]) free.push_back(x[i]);
  std::vector<std::uint8_t> beyond(x.size(), 0);
  sph::CellGrid grid;
  grid.build(free, reach);
  const std::vector<int>& order = grid.order();  // candidate ranges are of this order
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!clamped[i]) continue;
    bool near = false;
    grid.for_each_candidate_range(x[i], [&](int begin, int end) {
      for (int k = begin; k < end && !near; ++k)
        near = (free[order[k]] - x[i]).squaredNorm() < reach * reach;
    });
    beyond[i] = !near;
  }
  return beyond;
}

std::size_t reach_end(const std::vector<std::uint8_t>& out) {
  std::size_t end = out.size();
  while (end > 0 && out[end - 1]) --end;
  return end;
}

}  // namespace cosph::solid
