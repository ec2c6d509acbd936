// Reorders struct-of-arrays particle fields into the neighbour grid's order,
// or keeps some of the particles only.
#pragma once

#include <tuple>
#include <vector>

#include "sphcore/parallel.hpp"

namespace sph {

// field[k] <- field[order[k]] for every field given, in one pass over order.
// An order that leaves indices out drops those particles (spray leaving the
// water): the fields end with order.size() entries. The sorted copies are
// written into scratch vectors kept from call to call (one set per list of
// field types) whose buffers are then swapped with the fields', so that once
// the sizes have settled a step allocates, zeroes and faults in no memory.
template <class... Fields>
void permute(const std::vector<int>& order, Fields&... fields) {
  static thread_local std::tuple<Fields...> scratch;
  std::apply(
      [&order, &fields...](Fields&... sorted) {
        (sorted.resize(order.size()), ...);
        parallel_for(order.size(), [&](long k) {
          const int from = order[k];
          ((sorted[k] = fields[from]), ...);
        });
        (fields.swap(sorted), ...);
      },
      scratch);
}

}  // namespace sph
