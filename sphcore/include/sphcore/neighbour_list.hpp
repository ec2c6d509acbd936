// The pairs within the kernel support, found once per step and read by every
// neighbour pass of that step, and the Verlet list they are found in.
//
// NeighbourList stores, for each listed particle i, its neighbours j
// (r_ij < 2h, j != i), F_ij = (dW/dr)(r_ij) / r_ij, so that
// grad_i W_ij = F_ij x_ij, and r_ij itself: the passes then do no distance
// tests, no kernel evaluations and no square roots of their own. It is
// built from a CandidateList each step. Both list a particle's neighbours in
// index order (the grid's candidate ranges come row by row, each in order),
// so a pass that works each pair out once finds i's later neighbours at the
// end of its list (ordered_shares.hpp).
//
// CandidateList is a Verlet list (Verlet 1967): the particles within
// range = 2h + skin, found on the cell grid. While no particle has moved more
// than skin / 2 since it was built, every pair now within 2h was within
// 2h + skin then, so filtering its candidates finds exactly the neighbours a
// grid search would, in fewer tests and without re-sorting the particles. The
// owner of the list decides when to rebuild it; the skin decides speed only.
//
// Each share of the particles (a thread's under OpenMP's static schedule, which
// the passes use too; a chunk on TBB) keeps its particles' lists in a store of
// its own, so building needs no merge.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "sphcore/cell_grid.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/kernel_shape.hpp"
#include "sphcore/parallel.hpp"

namespace sph {

namespace detail {

// One share's lists: the first `size` entries of j (and of value, for a list
// that keeps one per pair) are in use. A cache line of its own: each thread
// moves its store's `size` on every particle, and two stores sharing a line made the
// line bounce between the cores (false sharing).
template <bool kWithValue>
struct alignas(64) PairStore {
  std::vector<int> j;
  std::vector<double> value, distance;
  std::size_t size = 0;

  void reserve(std::size_t entries) {
    if (entries <= j.size()) return;
    const std::size_t grown = std::max(entries, 2 * j.size());
    j.resize(grown);
    if constexpr (kWithValue) {
      value.resize(grown);
      distance.resize(grown);
    }
  }
};

// Where each particle's list lies: in which chunk's store, from where, how long.
template <bool kWithValue>
class PerThreadLists {
 public:
  // Runs append(i, store) for every i in [0, n), the store being that of i's
  // chunk (for_each_chunk: a particle's candidates, and so its cost, vary);
  // append adds i's entries at its end.
  template <class Append>
  void fill(std::size_t n, std::size_t entries_per_particle, Append&& append) {
    first_.resize(n);
    count_.resize(n);
    owner_.resize(n);
    const bool use_team = worth_threads(n);
    stores_.resize(static_cast<std::size_t>(sph::chunk_count(n, use_team)));
    sph::for_each_chunk(n, use_team, [&](long chunk_begin, long chunk_end, long chunk) {
      const int owner = static_cast<int>(chunk);
      Store& store = stores_[static_cast<std::size_t>(owner)];
      store.reserve(entries_per_particle * (n / stores_.size() + 1));
      store.size = 0;
      for (long i = chunk_begin; i < chunk_end; ++i) {
        const std::size_t begin = store.size;
        append(i, store);
        first_[i] = begin;
        count_[i] = static_cast<int>(store.size - begin);
        owner_[i] = owner;
      }
    });
  }

  std::span<const int> j(long i) const {
    return {stores_[owner_[i]].j.data() + first_[i], static_cast<std::size_t>(count_[i])};
  }
  std::span<const double> value(long i) const {
    return {stores_[owner_[i]].value.data() + first_[i], static_cast<std::size_t>(count_[i])};
  }
  std::span<const double> distance(long i) const {
    return {stores_[owner_[i]].distance.data() + first_[i], static_cast<std::size_t>(count_[i])};
  }

  using Store = PairStore<kWithValue>;

 private:
  std::vector<Store> stores_;
  std::vector<std::size_t> first_;
  std::vector<int> count_;
  std::vector<int> owner_;
};

// Calls scan(begin, end) for the grid's candidate ranges of particle i, i
// itself left out: its own cell's row is split in two around it rather than
// testing j != i for every candidate. Returns nothing; counts nothing.
template <class Scan>
void for_each_grid_candidate_range(const CellGrid& grid, std::span<const Vec2> x, long i,
                                   Scan&& scan) {
  const int self = static_cast<int>(i);
  grid.for_each_candidate_range(x[i], [&](int range_begin, int range_end) {
    if (self < range_begin || self >= range_end) return scan(range_begin, range_end);
    scan(range_begin, self);
    scan(self + 1, range_end);
  });
}

inline std::size_t grid_candidate_count(const CellGrid& grid, const Vec2& x_i) {
  std::size_t candidates = 0;
  grid.for_each_candidate_range(x_i, [&](int begin, int end) { candidates += end - begin; });
  return candidates;
}

}  // namespace detail

// The Verlet list's skin, one rule for every solver: pairs are listed within
// 2h + kSkinOverH h. It sets speed only (0.15, 0.25 and 0.4 h ran within
// 0.5 % of each other on the flowing dam break).
inline constexpr double kSkinOverH = 0.25;

// The list must be rebuilt once a particle has moved this far since it was
// built: while none has moved skin / 2, a pair now within 2h was within
// 2h + skin then. A hair less than half keeps round-off from mattering.
inline double verlet_rebuild_distance(double h) {
  return 0.499 * kSkinOverH * h;
}

// The Verlet list: for each particle i with wanted(i), the j != i within
// `range`, in the grid's (sorted) order.
class CandidateList {
 public:
  // The grid must have been built for at least `range` on these positions.
  // Lists are built for the particles i that are `wanted`, and hold the
  // candidates j that `kept(i, j)`: a pass that works each pair out once
  // needs only the later half.
  template <class Wanted>
  void build(const CellGrid& grid, std::span<const Vec2> x, double range, Wanted&& wanted) {
    build(grid, x, range, std::forward<Wanted>(wanted), [](long, int) { return true; });
  }
  template <class Wanted, class Kept>
  void build(const CellGrid& grid, std::span<const Vec2> x, double range, Wanted&& wanted,
             Kept&& kept) {
    const double range2 = range * range;
    // About 27 candidates at h = 1.3 dx and a skin of h / 4: room for 40.
    lists_.fill(x.size(), 40, [&](long i, Store& store) {
      if (!wanted(i)) return;
      store.reserve(store.size + detail::grid_candidate_count(grid, x[i]));
      int* const j_out = store.j.data();
      const Vec2 x_i = x[i];
      std::size_t end = store.size;
      // Every candidate is written, and the end moves past it only if it is
      // within range: no branch to mispredict on half the candidates.
      detail::for_each_grid_candidate_range(grid, x, i, [&](int begin, int stop) {
        for (int j = begin; j < stop; ++j) {
          j_out[end] = j;
          end += static_cast<std::size_t>((x_i - x[j]).squaredNorm() < range2) & kept(i, j);
        }
      });
      store.size = end;
    });
  }

  std::span<const int> candidates(long i) const { return lists_.j(i); }

 private:
  using Store = detail::PairStore<false>;
  detail::PerThreadLists<false> lists_;
};

// Writes to j_out and r2_out, in the candidates' order, those of a particle at
// x_i that lie closer than sqrt(range2), with their r^2, and returns how many.
// Every candidate is written, and the end moves past it only if it is in
// range: no branch to mispredict on a fifth of the candidates. The outputs
// need room for all the candidates.
inline std::size_t filter_within(std::span<const int> candidates, std::span<const Vec2> x,
                                 const Vec2& x_i, double range2, int* j_out, double* r2_out) {
  std::size_t count = 0;
  for (const int j : candidates) {
    const double r2 = (x_i - x[j]).squaredNorm();
    j_out[count] = j;
    r2_out[count] = r2;
    count += static_cast<std::size_t>(r2 < range2);
  }
  return count;
}

class NeighbourList {
 public:
  // The pairs of this step from a Verlet list: its candidates within 2h of i,
  // in its order. Exactly the neighbours a grid search finds while no particle
  // has moved more than half the list's skin since it was built.
  // F_ij is of the kernel `shape` (kernel_shape.hpp).
  void build(const CandidateList& candidates, std::span<const Vec2> x, double h,
             kernel::Shape shape = kernel::Shape::cubic_spline) {
    const double support2 = (kernel::kSupport * h) * (kernel::kSupport * h);
    kernel::with_gradient_factor(shape, h, [&](const auto gradient_factor) {
      // About 21 neighbours at h = 1.3 dx: room for 32 avoids regrowth.
      lists_.fill(x.size(), 32, [&](long i, Store& store) {
        const auto c = candidates.candidates(i);
        if (c.empty()) return;
        store.reserve(store.size + c.size());
        // r holds r^2 until the second loop, which vectorises.
        double* const F = store.value.data() + store.size;
        double* const r = store.distance.data() + store.size;
        const std::size_t count =
            filter_within(c, x, x[i], support2, store.j.data() + store.size, r);
        for (std::size_t k = 0; k < count; ++k) {
          r[k] = std::sqrt(r[k]);
          F[k] = gradient_factor(r[k]);
        }
        store.size += count;
      });
    });
  }

  std::span<const int> neighbours(long i) const { return lists_.j(i); }
  // F_ij in the order of neighbours(i).
  std::span<const double> gradient_factors(long i) const { return lists_.value(i); }
  // r_ij = |x_i - x_j| in the order of neighbours(i), as the list found it:
  // the bits a pass gets from x_ij.norm() of the same positions.
  std::span<const double> distances(long i) const { return lists_.distance(i); }

 private:
  using Store = detail::PairStore<true>;
  detail::PerThreadLists<true> lists_;
};

}  // namespace sph
