#include "sphcore/shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace sph {
namespace {

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double signed_area(const std::vector<Vec2>& v) {
  double twice = 0.0;
  for (std::size_t i = 0, n = v.size(); i < n; ++i) twice += cross(v[i], v[(i + 1) % n]);
  return 0.5 * twice;
}

// Whether segments ab and cd share a point (touching counts).
bool segments_meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const auto side = [](const Vec2& p, const Vec2& q, const Vec2& r) {
    const double s = cross(q - p, r - p);
    return (s > 0.0) - (s < 0.0);
  };
  const auto on_segment = [](const Vec2& p, const Vec2& q, const Vec2& r) {
    return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
           std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
  };
  const int d1 = side(c, d, a), d2 = side(c, d, b), d3 = side(a, b, c), d4 = side(a, b, d);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && on_segment(c, d, a)) || (d2 == 0 && on_segment(c, d, b)) ||
         (d3 == 0 && on_segment(a, b, c)) || (d4 == 0 && on_segment(a, b, d));
}

// The nearest point to p on segment ab.
Vec2 nearest_on_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return a + t * ab;
}

}  // namespace

Shape::Shape(Kind kind, std::vector<Vec2> vertices, double radius)
    : kind_(kind), vertices_(std::move(vertices)), radius_(radius) {}

Shape Shape::box(const Vec2& min, const Vec2& max) {
  return Shape(Kind::box, {min, max}, 0.0);
}

Shape Shape::polygon(std::vector<Vec2> vertices) {
  // Counter-clockwise, so that each edge's outward normal is its direction
  // turned clockwise.
  if (signed_area(vertices) < 0.0) std::reverse(vertices.begin(), vertices.end());
  return Shape(Kind::polygon, std::move(vertices), 0.0);
}

Shape Shape::circle(const Vec2& centre, double radius) {
  return Shape(Kind::circle, {centre}, radius);
}

Shape& Shape::subtract(Shape hole) {
  holes_.push_back(std::move(hole));
  return *this;
}

Bounds Shape::bounds() const {
  switch (kind_) {
    case Kind::box:
      return {vertices_[0], vertices_[1]};
    case Kind::circle:
      return {vertices_[0] - Vec2(radius_, radius_), vertices_[0] + Vec2(radius_, radius_)};
    case Kind::polygon:
      break;
  }
  Bounds b{vertices_[0], vertices_[0]};
  for (const Vec2& v : vertices_) {
    b.min = b.min.cwiseMin(v);
    b.max = b.max.cwiseMax(v);
  }
  return b;
}

bool Shape::outline_contains(const Vec2& p) const {
  switch (kind_) {
    case Kind::box:
      return p.x() >= vertices_[0].x() && p.x() <= vertices_[1].x() && p.y() >= vertices_[0].y() &&
             p.y() <= vertices_[1].y();
    case Kind::circle:
      return (p - vertices_[0]).squaredNorm() <= radius_ * radius_;
    case Kind::polygon:
      break;
  }
  // Crossing number, with points on an edge counted as inside.
  bool inside = false;
  for (std::size_t i = 0, n = vertices_.size(), j = n - 1; i < n; j = i++) {
    const Vec2& a = vertices_[i];
    const Vec2& b = vertices_[j];
    if (cross(b - a, p - a) == 0.0 && std::min(a.x(), b.x()) <= p.x() &&
        p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
        p.y() <= std::max(a.y(), b.y()))
      return true;
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

bool Shape::in_a_hole(const Vec2& p) const {
  return std::any_of(holes_.begin(), holes_.end(), [&](const Shape& hole) {
    return hole.contains(p) && hole.nearest_surface(p).distance > 0.0;
  });
}

bool Shape::contains(const Vec2& p) const {
  return outline_contains(p) && !in_a_hole(p);
}

std::vector<double> Shape::outline_crossings(const Vec2& a, const Vec2& b) const {
  const Vec2 d = b - a;
  std::vector<double> crossings;
  if (kind_ == Kind::circle) {
    // |a + t d - c|^2 = r^2
    const Vec2 f = a - vertices_[0];
    const double A = d.squaredNorm(), B = 2.0 * f.dot(d), C = f.squaredNorm() - radius_ * radius_;
    const double discriminant = B * B - 4.0 * A * C;
    if (A == 0.0 || discriminant < 0.0) return crossings;
    for (const double sign : {-1.0, 1.0}) {
      const double t = (-B + sign * std::sqrt(discriminant)) / (2.0 * A);
      if (t >= 0.0 && t <= 1.0) crossings.push_back(t);
    }
    return crossings;
  }
  std::vector<Vec2> corners = vertices_;
  if (kind_ == Kind::box) {
    const Vec2 lo = vertices_[0], hi = vertices_[1];
    corners = {lo, Vec2(hi.x(), lo.y()), hi, Vec2(lo.x(), hi.y())};
  }
  for (std::size_t i = 0, n = corners.size(); i < n; ++i) {
    const Vec2& e0 = corners[i];
    const Vec2& e1 = corners[(i + 1) % n];
    if (!segments_meet(a, b, e0, e1)) continue;
    const double across = cross(d, e1 - e0);
    // Along the edge: its nearer end is where the segment first touches it.
    const double t = across != 0.0 ? cross(e0 - a, e1 - e0) / across
                     : d.squaredNorm() > 0.0
                         ? std::min((e0 - a).dot(d), (e1 - a).dot(d)) / d.squaredNorm()
                         : 0.0;
    crossings.push_back(std::clamp(t, 0.0, 1.0));
  }
  return crossings;
}

bool Shape::meets(const Vec2& a, const Vec2& b) const {
  const Bounds box = bounds();
  if (std::max(a.x(), b.x()) < box.min.x() || std::min(a.x(), b.x()) > box.max.x() ||
      std::max(a.y(), b.y()) < box.min.y() || std::min(a.y(), b.y()) > box.max.y())
    return false;
  if (contains(a) || contains(b)) return true;
  // Neither end inside: the segment meets the region where it crosses the
  // outline, or a hole's edge inside the outline, outside every hole.
  const auto at = [&](double t) -> Vec2 { return a + t * (b - a); };
  for (const double t : outline_crossings(a, b))
    if (!in_a_hole(at(t))) return true;
  for (const Shape& hole : holes_)
    for (const double t : hole.outline_crossings(a, b))
      if (outline_contains(at(t)) && !in_a_hole(at(t))) return true;
  return false;
}

SurfacePoint Shape::nearest_on_outline(const Vec2& p) const {
  switch (kind_) {
    case Kind::box: {
      const Vec2& lo = vertices_[0];
      const Vec2& hi = vertices_[1];
      if (outline_contains(p)) {
        // The nearest face, ties to the top, then the bottom, left and right.
        const double left = p.x() - lo.x(), right = hi.x() - p.x();
        const double bottom = p.y() - lo.y(), top = hi.y() - p.y();
        const double depth = std::min({left, right, bottom, top});
        if (depth == top) return {Vec2(p.x(), hi.y()), Vec2(0, 1), depth};
        if (depth == bottom) return {Vec2(p.x(), lo.y()), Vec2(0, -1), depth};
        if (depth == left) return {Vec2(lo.x(), p.y()), Vec2(-1, 0), depth};
        return {Vec2(hi.x(), p.y()), Vec2(1, 0), depth};
      }
      const Vec2 q = p.cwiseMax(lo).cwiseMin(hi);
      return {q, (p - q).normalized(), (p - q).norm()};
    }
    case Kind::circle: {
      const Vec2 r = p - vertices_[0];
      const double length = r.norm();
      const Vec2 outward = length > 0.0 ? Vec2(r / length) : Vec2(0, 1);
      return {vertices_[0] + radius_ * outward, outward, std::abs(length - radius_)};
    }
    case Kind::polygon:
      break;
  }
  SurfacePoint best{p, Vec2(0, 1), std::numeric_limits<double>::infinity()};
  for (std::size_t i = 0, n = vertices_.size(); i < n; ++i) {
    const Vec2& a = vertices_[i];
    const Vec2& b = vertices_[(i + 1) % n];
    const Vec2 q = nearest_on_segment(p, a, b);
    const double distance = (p - q).norm();
    if (distance < best.distance) {
      const Vec2 edge = (b - a).normalized();
      best = {q, Vec2(edge.y(), -edge.x()), distance};
    }
  }
  // At a vertex the edge's normal is only one of two: the direction to p,
  // away from the region or into it, is the surface's.
  if (best.distance > 0.0) {
    const Vec2 away = (p - best.point) / best.distance;
    best.outward = outline_contains(p) ? Vec2(-away) : away;
  }
  return best;
}

SurfacePoint Shape::nearest_surface(const Vec2& p) const {
  SurfacePoint best = nearest_on_outline(p);
  for (const Shape& hole : holes_) {
    SurfacePoint q = hole.nearest_surface(p);
    if (q.distance < best.distance) {
      q.outward = -q.outward;  // out of the hole is into this region
      best = q;
    }
  }
  return best;
}

double Shape::depth(const Vec2& p) const {
  return contains(p) ? nearest_surface(p).distance : 0.0;
}

double Shape::top_at(double x) const {
  const Bounds b = bounds();
  switch (kind_) {
    case Kind::box:
      return b.max.y();
    case Kind::circle: {
      const double dx = x - vertices_[0].x();
      return dx * dx <= radius_ * radius_
                 ? vertices_[0].y() + std::sqrt(radius_ * radius_ - dx * dx)
                 : b.max.y();
    }
    case Kind::polygon:
      break;
  }
  double top = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = vertices_.size(); i < n; ++i) {
    const Vec2& a = vertices_[i];
    const Vec2& c = vertices_[(i + 1) % n];
    if (x < std::min(a.x(), c.x()) || x > std::max(a.x(), c.x())) continue;
    const double y = a.x() == c.x() ? std::max(a.y(), c.y())
                                    : a.y() + (c.y() - a.y()) * (x - a.x()) / (c.x() - a.x());
    top = std::max(top, y);
  }
  return std::isfinite(top) ? top : b.max.y();
}

std::optional<std::string> polygon_defect(const std::vector<Vec2>& v) {
  const std::size_t n = v.size();
  if (n < 3) return "a polygon needs at least 3 points, got " + std::to_string(n);
  Bounds b{v[0], v[0]};
  for (const Vec2& p : v) {
    b.min = b.min.cwiseMin(p);
    b.max = b.max.cwiseMax(p);
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (v[i] == v[(i + 1) % n])
      return "points " + std::to_string(i + 1) + " and " + std::to_string((i + 1) % n + 1) +
             " are the same";
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      const Vec2 &a = v[i], &b1 = v[(i + 1) % n], &c = v[j], &d = v[(j + 1) % n];
      if (adjacent) {
        // Neighbours share a vertex; they may not fold back along each other.
        const Vec2& shared = j == i + 1 ? b1 : a;
        const Vec2& p = j == i + 1 ? a : b1;
        const Vec2& q = j == i + 1 ? d : c;
        if (cross(p - shared, q - shared) == 0.0 && (p - shared).dot(q - shared) > 0.0)
          return "edges " + std::to_string(i + 1) + " and " + std::to_string(j + 1) + " overlap";
        continue;
      }
      if (segments_meet(a, b1, c, d))
        return "the polygon intersects itself: edge " + std::to_string(i + 1) + " (points " +
               std::to_string(i + 1) + "-" + std::to_string((i + 1) % n + 1) + ") meets edge " +
               std::to_string(j + 1) + " (points " + std::to_string(j + 1) + "-" +
               std::to_string((j + 1) % n + 1) + ")";
    }
  }
  const double scale = (b.max - b.min).squaredNorm();
  if (std::abs(signed_area(v)) <= 1e-12 * scale) return std::string("the polygon has no area");
  return std::nullopt;
}

double thickness(const Shape& shape, double spacing) {
  const Bounds b = shape.bounds();
  if (shape.kind() == Shape::Kind::box && shape.holes().empty())
    return std::min(b.max.x() - b.min.x(), b.max.y() - b.min.y());
  double deepest = 0.0;
  for (const Vec2& x : fill(shape, spacing)) deepest = std::max(deepest, shape.depth(x));
  return 2.0 * deepest;
}

std::vector<Vec2> fill(const Shape& shape, double spacing) {
  const Bounds b = shape.bounds();
  const bool box = shape.kind() == Shape::Kind::box;
  // A box holds a whole number of cells: round, not floor, so that a box
  // meant to hold 18 columns does not get 17 from 17.9999. Other outlines:
  // every lattice cell of the bounds whose centre lies inside.
  const auto count = [&](double length) {
    const double cells = length / spacing;
    return box ? std::lround(cells) : static_cast<long>(std::ceil(cells));
  };
  const long nx = count(b.max.x() - b.min.x());
  const long ny = count(b.max.y() - b.min.y());
  std::vector<Vec2> points;
  points.reserve(static_cast<std::size_t>(std::max(nx, 0L) * std::max(ny, 0L)));
  // The coordinates rounded exactly as the box fill of every earlier case
  // (built with FMA contraction) rounded them, so that those cases keep their
  // results bit for bit: x = min_x + (i + 1/2) dx in one rounding, a fused
  // multiply-add; y = min_y + (j + 1/2) dx in two, the product rounded on its
  // own (volatile, so that the compiler cannot fuse it into the sum).
  for (long j = 0; j < ny; ++j) {
    const volatile double row_offset = (static_cast<double>(j) + 0.5) * spacing;
    const double y = b.min.y() + row_offset;
    for (long i = 0; i < nx; ++i) {
      const Vec2 x(std::fma(static_cast<double>(i) + 0.5, spacing, b.min.x()), y);
      if (box ? shape.holes().empty() || shape.contains(x) : shape.contains(x)) points.push_back(x);
    }
  }
  return points;
}

}  // namespace sph
