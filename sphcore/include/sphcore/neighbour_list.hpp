// The pairs within the kernel support, found once per step and read by every
// neighbour pass of that step.
//
// For each listed particle i it stores its neighbours j (r_ij < 2h, j != i)
// and F_ij = (dW/dr)(r_ij) / r_ij, so that grad_i W_ij = F_ij x_ij: the passes
// then do no distance tests and no kernel evaluations of their own. Each
// thread keeps the pairs of the particles it owns under a static schedule,
// which the passes use too, so building needs no merge.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "sphcore/cell_grid.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/parallel.hpp"

namespace sph {

class NeighbourList {
 public:
  // Lists the neighbours of every particle i with wanted(i); others get none.
  template <class Wanted>
  void build(const CellGrid& grid, std::span<const Vec2> x, double h, Wanted&& wanted) {
    const long n = static_cast<long>(x.size());
    const double support2 = (kernel::kSupport * h) * (kernel::kSupport * h);
    const kernel::GradientFactor gradient_factor(h);
    first_.resize(x.size());
    count_.resize(x.size());
    owner_.resize(x.size());
    stores_.resize(static_cast<std::size_t>(omp_get_max_threads()));
#pragma omp parallel if (worth_threads(x.size()))
    {
      Store& store = stores_[static_cast<std::size_t>(omp_get_thread_num())];
      // About 21 neighbours at h = 1.3 dx: room for 32 avoids regrowth.
      store.reserve(32 * (x.size() / stores_.size() + 1));
      store.size = 0;
#pragma omp for schedule(static)
      for (long i = 0; i < n; ++i) {
        const std::size_t begin = store.size;
        if (wanted(i)) list_neighbours(grid, x, i, support2, gradient_factor, store);
        first_[i] = begin;
        count_[i] = static_cast<int>(store.size - begin);
        owner_[i] = omp_get_thread_num();
      }
    }
  }

  std::span<const int> neighbours(long i) const {
    return {stores_[owner_[i]].j.data() + first_[i], static_cast<std::size_t>(count_[i])};
  }
  // F_ij in the order of neighbours(i).
  std::span<const double> gradient_factors(long i) const {
    return {stores_[owner_[i]].F.data() + first_[i], static_cast<std::size_t>(count_[i])};
  }

 private:
  // One thread's pairs: the first `size` entries of j and F are in use.
  struct Store {
    std::vector<int> j;
    std::vector<double> F;
    std::size_t size = 0;

    void reserve(std::size_t entries) {
      if (entries <= j.size()) return;
      const std::size_t grown = std::max(entries, 2 * j.size());
      j.resize(grown);
      F.resize(grown);
    }
  };
  // Appends the neighbours of i to the store. Every candidate is written, and
  // the end moves past it only if it is a neighbour: no branch to mispredict on
  // half the candidates. F holds r^2 until the second loop, which vectorises.
  static void list_neighbours(const CellGrid& grid, std::span<const Vec2> x, long i,
                              double support2, kernel::GradientFactor gradient_factor,
                              Store& store) {
    std::size_t candidates = 0;
    grid.for_each_candidate_range(x[i], [&](int begin, int end) { candidates += end - begin; });
    const std::size_t begin = store.size;
    store.reserve(begin + candidates);
    int* const j_out = store.j.data();
    double* const F_out = store.F.data();
    const Vec2 x_i = x[i];
    std::size_t end = begin;
    auto scan = [&, support2](int range_begin, int range_end) {
      for (int j = range_begin; j < range_end; ++j) {
        const double r2 = (x_i - x[j]).squaredNorm();
        j_out[end] = j;
        F_out[end] = r2;
        end += static_cast<std::size_t>(r2 < support2);
      }
    };
    // i lies in one of the ranges (its own cell's row): that range is scanned
    // in two parts around it rather than testing j != i for every candidate.
    const int self = static_cast<int>(i);
    grid.for_each_candidate_range(x_i, [&](int range_begin, int range_end) {
      if (self < range_begin || self >= range_end) return scan(range_begin, range_end);
      scan(range_begin, self);
      scan(self + 1, range_end);
    });
    for (std::size_t k = begin; k < end; ++k) F_out[k] = gradient_factor(std::sqrt(F_out[k]));
    store.size = end;
  }

  std::vector<Store> stores_;
  std::vector<std::size_t> first_;
  std::vector<int> count_;
  std::vector<int> owner_;
};

}  // namespace sph
