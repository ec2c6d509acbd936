// Cell-linked-list neighbour search, O(N) per build.
//
// Particles are binned into square cells no smaller than the largest support
// radius, then counting-sorted by cell. A solver permutes its particle arrays
// into that order (permutation.hpp), so the candidates of a particle are three
// contiguous index ranges, one per row of the 3x3 block of cells: the loops
// stream memory instead of chasing pointers.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "sphcore/types.hpp"

namespace sph {

class CellGrid {
 public:
  // Bins the positions for neighbours within `range` (the largest
  // interaction range), in cells of range / subdivisions: two subdivisions
  // scan a 5x5 block of half-size cells, a third fewer candidates than 3x3.
  // Throws std::runtime_error if the particles spread over so many cells that
  // the grid would not fit in memory (a run that has blown up).
  void build(std::span<const Vec2> x, double range, int subdivisions = 1);

  // Particle indices sorted by cell: new index k holds old particle order()[k].
  const std::vector<int>& order() const { return order_; }

  // Calls visit(begin, end) for the index ranges, in sorted order, of the
  // particles in the cells within `range` of point p's cell, one range per row
  // of cells. Valid for a point anywhere, inside the grid or not.
  template <class Visit>
  void for_each_candidate_range(const Vec2& p, Visit&& visit) const {
    const long cx = cell_coordinate(p.x(), origin_.x());
    const long cy = cell_coordinate(p.y(), origin_.y());
    const long x_lo = std::max(cx - reach_, 0L), x_hi = std::min(cx + reach_, nx_ - 1);
    if (x_lo > x_hi) return;
    for (long row = std::max(cy - reach_, 0L); row <= std::min(cy + reach_, ny_ - 1); ++row) {
      const int begin = cell_begin_[row * nx_ + x_lo];
      const int end = cell_begin_[row * nx_ + x_hi + 1];
      if (begin < end) visit(begin, end);
    }
  }

  double cell_size() const { return cell_size_; }

 private:
  long cell_coordinate(double coordinate, double origin) const {
    // floor() by truncation: without SSE4.1 std::floor is a call into libm,
    // and this runs for every particle of every grid build and query.
    const double cell = (coordinate - origin) * inverse_cell_size_;
    const long truncated = static_cast<long>(cell);
    return truncated - static_cast<long>(cell < static_cast<double>(truncated));
  }

  double cell_size_ = 0.0, inverse_cell_size_ = 0.0;
  Vec2 origin_ = Vec2::Zero();
  long nx_ = 0, ny_ = 0;
  long reach_ = 1;               // cells scanned on each side
  std::vector<int> cell_begin_;  // nx*ny + 1 prefix sums
  std::vector<int> order_;
  std::vector<long> cell_of_;
  std::vector<int> fill_;  // next free slot per cell while sorting; kept to reuse its memory
};

}  // namespace sph
