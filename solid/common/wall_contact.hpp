// Contact of solid particles with rigid walls (case field solid.walls).
//
// The walls of docs/physics.md, "Walls", are the water's: the coupler's cross-phase sum runs over
// water and solid only, so without this a piece of plate broken off by the
// water (scene 3) falls through the floor under gravity. A wall is an
// axis-aligned box grown by half a solid spacing, the extent of a particle,
// so that a plate whose particles sit half a spacing above the floor rests on
// it. A particle found inside is put back on the nearest face and loses the
// velocity component into the wall: an inelastic, frictionless contact (the
// wall is rigid and takes the momentum; tangential motion is free). It is a
// kinematic constraint, not a force, so it needs no stiffness and limits no
// time step.
#pragma once

#include <algorithm>

#include "sphcore/region.hpp"
#include "sphcore/types.hpp"

namespace cosph::solid {

using sph::Vec2;

// Puts x back on the nearest face of `wall` if it lies strictly inside, and
// removes v's component into the wall. Returns whether it was inside.
inline bool push_out_of_wall(const sph::Region& wall, Vec2& x, Vec2& v) {
  if (!(x.x() > wall.min.x() && x.x() < wall.max.x() && x.y() > wall.min.y() &&
        x.y() < wall.max.y()))
    return false;
  // Depth below each face; the shallowest is the way out.
  const double left = x.x() - wall.min.x(), right = wall.max.x() - x.x();
  const double bottom = x.y() - wall.min.y(), top = wall.max.y() - x.y();
  const double depth = std::min({left, right, bottom, top});
  if (depth == top) {
    x.y() = wall.max.y();
    v.y() = std::max(v.y(), 0.0);
  } else if (depth == bottom) {
    x.y() = wall.min.y();
    v.y() = std::min(v.y(), 0.0);
  } else if (depth == left) {
    x.x() = wall.min.x();
    v.x() = std::min(v.x(), 0.0);
  } else {
    x.x() = wall.max.x();
    v.x() = std::max(v.x(), 0.0);
  }
  return true;
}

}  // namespace cosph::solid
