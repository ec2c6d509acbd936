// The water's walls that the solid does not meet.
//
// The solid meets only the walls its case lists under solid.walls
// (wall_contact.hpp); the coupler's cross-phase sum runs over water and solid,
// not over the water's walls. A case that lists none lets a body that reaches
// the tank's floor (a block dropped into the water, a piece broken off) fall
// through it and go on as if nothing were there. So when solid.walls is empty,
// the solid watches the water's walls (fluid.walls) and stops the run, saying
// what to add, once a free particle lies wholly inside one of them: its
// centre at least half a spacing inside the wall.
//
// A wall some free particle starts inside is left out: the case put the body
// there, and a check that failed at once would only get in the way.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "clamp_reach.hpp"
#include "sphcore/parallel.hpp"
#include "sphcore/region.hpp"
#include "sphcore/runaway_error.hpp"
#include "sphcore/shape.hpp"
#include "sphcore/types.hpp"

namespace cosph::solid {

struct UnmetWall {
  int index;  // in fluid.walls
  // The wall's bounds shrunk by half a solid spacing: for a box, the points
  // at least that deep inside it; for any other region, a screen around them.
  sph::Region inside;
  std::optional<sph::Shape> shape;  // absent for a box without holes
  double depth = 0.0;               // half a solid spacing

  UnmetWall(int index_in_walls, const sph::Shape& wall, double half_spacing)
      : index(index_in_walls), depth(half_spacing) {
    const sph::Bounds b = wall.bounds();
    inside = sph::Region{b.min, b.max}.grown(-half_spacing);
    if (wall.kind() != sph::Shape::Kind::box || !wall.holes().empty()) shape = wall;
  }
  bool contains(const sph::Vec2& x) const {
    return inside.contains(x) && (!shape || shape->depth(x) >= depth);
  }
};

struct WallCrossing {
  std::size_t particle;
  int wall_index;  // in fluid.walls
};

// The first free particle (clamped[i] false) lying inside one of `walls`.
template <class Positions, class Clamped>
std::optional<WallCrossing> find_wall_crossing(const Positions& x, const Clamped& clamped,
                                               const std::vector<UnmetWall>& walls) {
  for (const UnmetWall& wall : walls)
    for (std::size_t i = 0; i < x.size(); ++i)
      if (!clamped[i] && wall.contains(x[i])) return WallCrossing{i, wall.index};
  return std::nullopt;
}

// `walls` without those some free particle lies inside now.
template <class Positions, class Clamped>
std::vector<UnmetWall> walls_no_free_particle_is_inside(const Positions& x, const Clamped& clamped,
                                                        std::vector<UnmetWall> walls) {
  std::erase_if(walls, [&](const UnmetWall& wall) {
    return find_wall_crossing(x, clamped, std::vector<UnmetWall>{wall}).has_value();
  });
  return walls;
}

// Throws sph::RunawayError, naming the particle, the wall and what to add to
// the case, if a free particle of P lies inside one of `walls`. The speed is
// in the message because a body flung through a wall by a blow-up (the
// stability map's light coupled plates) is caught here too.
template <class Particles>
void stop_if_in_unmet_wall(const Particles& P, const std::vector<UnmetWall>& walls, double time,
                           long steps) {
  // A screen of all particles, which vectorises, before the search that
  // stops at the first: it runs every step, and a crossing ends the run.
  if (std::none_of(walls.begin(), walls.end(), [&P](const UnmetWall& wall) {
        // Free particles are all in reach (clamp_reach.hpp).
        return sph::parallel_any(in_reach(P), sph::kTeamAtAnySize, [&](long i) {
          return !P.clamped[i] & wall.inside.contains(P.x[i]);
        });
      }))
    return;
  const auto crossing = find_wall_crossing(P.x, P.clamped, walls);
  if (!crossing) return;
  const sph::Vec2 x = P.x[crossing->particle], v = P.v[crossing->particle];
  std::ostringstream message;
  message << "solid particle " << P.id[crossing->particle] << " at (" << x.x() << ", " << x.y()
          << ") m, t = " << time << " s, step " << steps
          << ": it has gone into the water's wall fluid.walls[" << crossing->wall_index
          << "] (speed " << v.norm()
          << " m/s). The solid meets only the walls listed under solid.walls, and the case "
             "lists none: if the body is to rest on or strike this wall, list the walls there "
             "(usually the fluid's); if it got there at a speed no flow could give it, the run "
             "has blown up";
  throw sph::RunawayError(message.str());
}

}  // namespace cosph::solid
