#include "sphcore/cell_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sphcore/parallel.hpp"

namespace sph {

void CellGrid::build(std::span<const Vec2> x, double range, int subdivisions) {
  const std::size_t n = x.size();
  reach_ = std::max(subdivisions, 1);
  const double cell_size = range / static_cast<double>(reach_);
  cell_size_ = cell_size;
  inverse_cell_size_ = 1.0 / cell_size;
  Vec2 lo = Vec2::Constant(0.0), hi = Vec2::Constant(0.0);
  if (n > 0) {
    // The box as the largest of -x, -y, x and y; the last quantity is 1 for a
    // position that is not finite, checked per particle: max passes a NaN by
    // (NaN < a is false).
    const auto box_of = [&](long i) {
      return std::array{-x[i].x(), -x[i].y(), x[i].x(), x[i].y(), x[i].allFinite() ? 0.0 : 1.0};
    };
    const auto [minus_lo_x, minus_lo_y, hi_x, hi_y, not_finite] =
        parallel_max(n, box_of(0), worth_threads(n), box_of);
    if (not_finite != 0.0)
      throw std::runtime_error("neighbour search: a particle position is not finite");
    lo = Vec2(-minus_lo_x, -minus_lo_y);
    hi = Vec2(hi_x, hi_y);
  }
  origin_ = lo;
  nx_ = cell_coordinate(hi.x(), lo.x()) + 1;
  ny_ = cell_coordinate(hi.y(), lo.y()) + 1;
  // A grid far larger than the particle count means particles flew apart.
  const double cells = static_cast<double>(nx_) * static_cast<double>(ny_);
  if (cells > 64.0 * static_cast<double>(n) + 4.0e6)
    throw std::runtime_error("neighbour search: particles spread over " + std::to_string(cells) +
                             " cells (domain " + std::to_string(hi.x() - lo.x()) + " x " +
                             std::to_string(hi.y() - lo.y()) + " m): the run has blown up");

  const std::size_t cell_count = static_cast<std::size_t>(nx_ * ny_);
  cell_begin_.assign(cell_count + 1, 0);
  cell_of_.resize(n);
  parallel_for(n, [&](long i) {
    const long cx = std::clamp(cell_coordinate(x[i].x(), lo.x()), 0L, nx_ - 1);
    const long cy = std::clamp(cell_coordinate(x[i].y(), lo.y()), 0L, ny_ - 1);
    cell_of_[i] = cy * nx_ + cx;
  });
  for (std::size_t i = 0; i < n; ++i) ++cell_begin_[cell_of_[i] + 1];
  for (std::size_t c = 0; c < cell_count; ++c) cell_begin_[c + 1] += cell_begin_[c];
  order_.resize(n);
  fill_.assign(cell_begin_.begin(), cell_begin_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) order_[fill_[cell_of_[i]]++] = static_cast<int>(i);
}

}  // namespace sph
