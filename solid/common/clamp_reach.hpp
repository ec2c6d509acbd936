// Clamped particles that no free particle can feel. A free particle's
// acceleration reads its neighbours within 2h; what it reads of a clamped
// neighbour (stress, density, its kernel correction) is itself a sum over that
// neighbour's own neighbours. Each model states how deep that chain goes
// (jaumann_solver.cpp, reference_configuration.cpp) and so how far from every
// free particle a clamped one must lie before nothing it computes reaches a
// free particle. Clamped particles never move, so the set is fixed at the
// start. They are no particle's neighbour candidates, and the passes stop at
// in_reach(P), one past the last particle in reach: in the cell order the
// particles are kept in, a clamp at the end of that order (a plate clamped at
// its top) is not visited at all, and those out of reach before that point
// are skipped as inert. They stay in the arrays, and so in the snapshots
// and in the interface the coupler reads (the water presses on the clamp),
// in the order they had: moved behind the others, they changed the order in
// which the coupler sums the water's pairs with the plate, and the flow grew
// that round-off into millimetres at the plate's tip by t = 0.33 s.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "sphcore/types.hpp"

namespace cosph::solid {

// 1 for each clamped particle with no free particle closer than `reach`, else
// 0 (positions x; clamped 1 or 0).
std::vector<std::uint8_t> clamped_beyond(const std::vector<sph::Vec2>& x,
                                         const std::vector<std::uint8_t>& clamped, double reach);

// One past the last particle not `out` of reach (0 if none is).
std::size_t reach_end(const std::vector<std::uint8_t>& out);

// How many particles, from the first, the step's passes visit: up to the
// store's reach_end (all particles until it is set).
template <class Particles>
std::size_t in_reach(const Particles& P) {
  return std::min(P.size(), P.reach_end);
}

}  // namespace cosph::solid
