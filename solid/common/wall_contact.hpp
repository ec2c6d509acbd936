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
#include <optional>

#include "sphcore/region.hpp"
#include "sphcore/shape.hpp"
#include "sphcore/types.hpp"

namespace cosph::solid {

using sph::Vec2;

// One of solid.walls, grown by `margin`.
struct SolidWall {
  // A box wall: the grown box, the whole of it. Any other: the box around the
  // grown region, which a particle outside cannot touch.
  sph::Region box;
  std::optional<sph::Shape> shape;  // absent for a box without holes
  double margin = 0.0;

  SolidWall(const sph::Shape& region, double grown_by) : margin(grown_by) {
    const sph::Bounds b = region.bounds();
    box = sph::Region{b.min, b.max}.grown(grown_by);
    if (region.kind() != sph::Shape::Kind::box || !region.holes().empty()) shape = region;
  }

  // Whether x lies inside the grown wall deeper than `tolerance`.
  bool holds(const Vec2& x, double tolerance) const {
    if (!shape) return box.grown(-tolerance).contains(x);
    if (!box.contains(x)) return false;
    return shape->contains(x) || shape->nearest_surface(x).distance < margin - tolerance;
  }
};

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

// The same for a wall of any shape: x goes to the nearest point of the grown
// surface, half a spacing out along the region's outward normal.
inline bool push_out_of_wall(const SolidWall& wall, Vec2& x, Vec2& v) {
  if (!wall.shape) return push_out_of_wall(wall.box, x, v);
  if (!wall.box.contains(x)) return false;
  const sph::SurfacePoint surface = wall.shape->nearest_surface(x);
  if (!wall.shape->contains(x) && surface.distance >= wall.margin) return false;
  x = surface.point + wall.margin * surface.outward;
  v -= std::min(v.dot(surface.outward), 0.0) * surface.outward;
  return true;
}

}  // namespace cosph::solid
