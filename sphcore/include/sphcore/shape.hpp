// Regions of a scene: a box, a polygon or a circle, less any number of other
// regions. The solvers ask a region four things: does it hold a point, how
// deep inside is a point (walls keep only the particles within 2h of their
// surface), where is the nearest point of its surface (solid contact), and
// does a segment touch it (can water pass between two sites: the leak check).
// Everything here is 2-D; a 3-D region would answer the same questions.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sphcore/types.hpp"

namespace sph {

struct Bounds {
  Vec2 min, max;
};

// The nearest point of a region's surface to a point, and the unit normal
// there that points out of the region.
struct SurfacePoint {
  Vec2 point;
  Vec2 outward;
  double distance;
};

class Shape {
 public:
  enum class Kind { box, polygon, circle };

  static Shape box(const Vec2& min, const Vec2& max);
  // Vertices in order, either orientation; see polygon_defect for what is refused.
  static Shape polygon(std::vector<Vec2> vertices);
  static Shape circle(const Vec2& centre, double radius);

  // This region less `hole`.
  Shape& subtract(Shape hole);

  Kind kind() const { return kind_; }
  const std::vector<Shape>& holes() const { return holes_; }
  // The box of the outline, holes not counted.
  Bounds bounds() const;

  // Points on the surface count as inside.
  bool contains(const Vec2& p) const;
  // The nearest point of the surface (outline or holes), from inside or out.
  SurfacePoint nearest_surface(const Vec2& p) const;
  // Distance from p to the surface; 0 outside.
  double depth(const Vec2& p) const;
  // Whether the segment from a to b has a point in the region, its ends
  // and the surface included.
  bool meets(const Vec2& a, const Vec2& b) const;
  // The highest point of the outline straight above or below p.x, for a
  // water column's hydrostatic depth; the top of the bounds if none.
  double top_at(double x) const;

 private:
  Shape(Kind kind, std::vector<Vec2> vertices, double radius);
  bool outline_contains(const Vec2& p) const;
  bool in_a_hole(const Vec2& p) const;
  // Where the segment a + t (b - a), t in [0, 1], crosses the outline.
  std::vector<double> outline_crossings(const Vec2& a, const Vec2& b) const;
  SurfacePoint nearest_on_outline(const Vec2& p) const;

  Kind kind_;
  // box: min, max; polygon: the vertices, counter-clockwise; circle: the centre.
  std::vector<Vec2> vertices_;
  double radius_ = 0.0;
  std::vector<Shape> holes_;
};

// What makes a polygon unusable, in words for an error message, or nothing:
// fewer than 3 vertices, no area, or two edges that cross or touch other than
// at their shared vertex.
std::optional<std::string> polygon_defect(const std::vector<Vec2>& vertices);

// Twice the greatest depth of a point of the shape: the diameter of the
// largest circle inside it, the least side of a box. Exact for a box without
// holes; otherwise found on a lattice of the given spacing, less than the
// truth by at most twice the spacing.
double thickness(const Shape& shape, double spacing);

// Centres of the spacing x spacing lattice cells, anchored half a spacing in
// from the lower-left corner of the shape's bounds, that lie inside the shape.
// For a box, exactly the cells that tile it (its width is rounded to a whole
// number of spacings, so that 17.9999 spacings give 18 columns, not 17).
std::vector<Vec2> fill(const Shape& shape, double spacing);

}  // namespace sph
