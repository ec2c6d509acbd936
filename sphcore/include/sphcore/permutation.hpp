// Reorders struct-of-arrays particle fields into the neighbour grid's order.
#pragma once

#include <type_traits>
#include <vector>

namespace sph {

// field[k] <- field[order[k]] for every field given.
template <class... Fields>
void permute(const std::vector<int>& order, Fields&... fields) {
  auto apply = [&order](auto& field) {
    std::remove_reference_t<decltype(field)> sorted(field.size());
    for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = field[order[k]];
    field.swap(sorted);
  };
  (apply(fields), ...);
}

}  // namespace sph
