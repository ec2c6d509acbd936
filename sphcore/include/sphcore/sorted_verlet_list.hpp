// The Verlet re-sort every solver with a neighbour search takes alike: the
// particles are sorted by cell and the Verlet list (neighbour_list.hpp) built
// within 2h + skin; the owner rebuilds both once some particle may have moved
// half the skin since (verlet_rebuild_distance). The owner keeps the particle
// arrays, so it applies the grid's order to them itself.
#pragma once

#include <utility>
#include <vector>

#include "sphcore/cell_grid.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/neighbour_list.hpp"
#include "sphcore/permutation.hpp"
#include "sphcore/types.hpp"

namespace sph {

class SortedVerletList {
 public:
  // For smoothing length h, on a grid of cells of (2h + skin) / subdivisions
  // (CellGrid::build).
  explicit SortedVerletList(double h, int subdivisions = 1)
      : reach_(kernel::kSupport * h + kSkinOverH * h),
        rebuild_at_(verlet_rebuild_distance(h)),
        subdivisions_(subdivisions) {}

  // Bins the positions x, lets permute(order) put every particle array, x
  // included, into the grid's order, and lists the candidates of the sorted
  // particles (`filters`: CandidateList::build's wanted and kept).
  template <class Permute, class... Filters>
  void sort(const std::vector<Vec2>& x, Permute&& permute, Filters&&... filters) {
    grid_.build(x, reach_, subdivisions_);
    std::forward<Permute>(permute)(grid_.order());
    x_at_sort_ = x;
    candidates_.build(grid_, x, reach_, std::forward<Filters>(filters)...);
  }

  // Takes back the state of a sort from a checkpoint: x_at_sort, the
  // positions at that sort, already in cell order. The grid and the list are
  // rebuilt from them, the same bits as at the sort itself (the list of the
  // sort was built from the same positions). Returns false if x_at_sort is not
  // in the grid's order, which a checkpoint of this build cannot give.
  template <class... Filters>
  bool restore(std::vector<Vec2> x_at_sort, Filters&&... filters) {
    grid_.build(x_at_sort, reach_, subdivisions_);
    const std::vector<int>& order = grid_.order();
    for (std::size_t i = 0; i < order.size(); ++i)
      if (order[i] != static_cast<int>(i)) return false;
    x_at_sort_ = std::move(x_at_sort);
    candidates_.build(grid_, x_at_sort_, reach_, std::forward<Filters>(filters)...);
    return true;
  }

  // The positions at the last sort, for a checkpoint.
  const std::vector<Vec2>& x_at_sort() const { return x_at_sort_; }

  // The squared distance particle i, now at x_i, has moved since the last sort.
  double moved2(const Vec2& x_i, long i) const { return moved2(x_i, x_at_sort_[i]); }
  // The same, from its place at the sort (x_at_sort()[i]): for a loop that
  // holds that array in a local.
  static double moved2(const Vec2& x_i, const Vec2& x_at_sort_i) {
    return (x_i - x_at_sort_i).squaredNorm();
  }
  // True when a particle that moved sqrt(largest_moved2) may have a neighbour
  // the list misses: then sort.
  bool stale(double largest_moved2) const { return largest_moved2 > rebuild_at_ * rebuild_at_; }

  // Particles left between sorts: only kept[0], kept[1], ... remain, in that
  // order. The grid and the list still hold the old indices until the next sort.
  void keep_only(const std::vector<int>& kept) { permute(kept, x_at_sort_); }

  double reach() const { return reach_; }         // 2h + skin
  const CellGrid& grid() const { return grid_; }  // built at the last sort
  const CandidateList& candidates() const { return candidates_; }

 private:
  double reach_;
  double rebuild_at_;
  int subdivisions_;
  CellGrid grid_;
  CandidateList candidates_;
  std::vector<Vec2> x_at_sort_;  // positions at the last sort
};

}  // namespace sph
