// Reorders struct-of-arrays particle fields into the neighbour grid's order.
#pragma once

#include <tuple>
#include <type_traits>
#include <vector>

#include "sphcore/parallel.hpp"

namespace sph {

// field[k] <- field[order[k]] for every field given, in one pass over order.
// The sorted copies are written into scratch vectors kept from call to call
// (one set per list of field types) whose buffers are then swapped with the
// fields', so that once the sizes have settled a step allocates, zeroes and
// faults in no memory.
template <class... Fields>
void permute(const std::vector<int>& order, Fields&... fields) {
  static thread_local std::tuple<Fields...> scratch;
  std::apply(
      [&order, &fields...](Fields&... sorted) {
        (sorted.resize(fields.size()), ...);
        parallel_for(order.size(), [&](long k) {
          const int from = order[k];
          ((sorted[k] = fields[from]), ...);
        });
        (fields.swap(sorted), ...);
      },
      scratch);
}

// field <- (field[kept[0]], field[kept[1]], ...) for every field given: the
// particles left out of `kept` leave the set. Rare (spray leaving the water),
// so unlike permute it allocates.
template <class... Fields>
void keep_only(const std::vector<int>& kept, Fields&... fields) {
  const auto gather = [&kept](auto& field) {
    std::remove_reference_t<decltype(field)> kept_values(kept.size());
    for (std::size_t k = 0; k < kept.size(); ++k) kept_values[k] = field[kept[k]];
    field.swap(kept_values);
  };
  (gather(fields), ...);
}

}  // namespace sph
