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

#include <cmath>
#include <span>
#include <vector>

#include "sphcore/cell_grid.hpp"
#include "sphcore/kernel.hpp"

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
#pragma omp parallel
    {
      Store& store = stores_[static_cast<std::size_t>(omp_get_thread_num())];
      store.j.clear();
      store.F.clear();
      // About 21 neighbours at h = 1.3 dx: room for 32 avoids regrowth.
      const std::size_t owned = x.size() / stores_.size() + 1;
      store.j.reserve(32 * owned);
      store.F.reserve(32 * owned);
#pragma omp for schedule(static)
      for (long i = 0; i < n; ++i) {
        const std::size_t begin = store.j.size();
        if (wanted(i)) {
          const Vec2 x_i = x[i];
          grid.for_each_candidate_range(x_i, [&](int range_begin, int range_end) {
            for (int j = range_begin; j < range_end; ++j) {
              const double r2 = (x_i - x[j]).squaredNorm();
              if (r2 >= support2 || j == i) continue;
              const double r = std::sqrt(r2);
              store.j.push_back(j);
              store.F.push_back(gradient_factor(r));
            }
          });
        }
        first_[i] = begin;
        count_[i] = static_cast<int>(store.j.size() - begin);
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
  struct Store {
    std::vector<int> j;
    std::vector<double> F;
  };
  std::vector<Store> stores_;
  std::vector<std::size_t> first_;
  std::vector<int> count_;
  std::vector<int> owner_;
};

}  // namespace sph
