#include "sphcore/band.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sphcore/case_file.hpp"

namespace sph {
namespace {

Vec2 left_normal(const Vec2& from, const Vec2& to) {
  const Vec2 t = (to - from).normalized();
  return {-t.y(), t.x()};
}

}  // namespace

std::optional<std::string> band_defect(const std::vector<Vec2>& line, double thickness) {
  if (line.size() < 2) return "a band needs at least 2 points, got " + std::to_string(line.size());
  if (!(std::isfinite(thickness) && thickness > 0.0))
    return "the thickness must be positive, got " + format_number(thickness) + " m";
  for (std::size_t k = 0; k + 1 < line.size(); ++k)
    if (line[k] == line[k + 1])
      return "points " + std::to_string(k + 1) + " and " + std::to_string(k + 2) + " coincide";
  const double least_cosine = std::cos(kBandMostTurnDegrees * std::numbers::pi / 180.0);
  for (std::size_t k = 1; k + 1 < line.size(); ++k) {
    const Vec2 in = (line[k] - line[k - 1]).normalized(),
               out = (line[k + 1] - line[k]).normalized();
    if (!(in.dot(out) > least_cosine))
      return "the line turns by " +
             format_number(std::acos(std::clamp(in.dot(out), -1.0, 1.0)) * 180.0 /
                           std::numbers::pi) +
             " degrees at point " + std::to_string(k + 1) + ": a corner must turn by less than " +
             format_number(kBandMostTurnDegrees) + " (give a bend as several points)";
  }
  return std::nullopt;
}

namespace {

// The unit normal of the line at its point k: its segment's at an end, the
// mitre's direction (the mean of its two segments' normals) at a corner.
Vec2 band_normal(const std::vector<Vec2>& line, std::size_t k) {
  if (k == 0) return left_normal(line[0], line[1]);
  const std::size_t last = line.size() - 1;
  if (k == last) return left_normal(line[last - 1], line[last]);
  return (left_normal(line[k - 1], line[k]) + left_normal(line[k], line[k + 1])).normalized();
}

}  // namespace

std::vector<Vec2> band_outline(const std::vector<Vec2>& line, double thickness) {
  const std::size_t n = line.size();
  std::vector<Vec2> offset(n);
  for (std::size_t k = 0; k < n; ++k) {
    // Half the thickness away from both segments' lines: the mitre's length
    // is (t / 2) / cos(turn / 2), cos(turn / 2) the normal's dot with either
    // segment's.
    const Vec2 normal = band_normal(line, k);
    const Vec2 segment =
        k + 1 < n ? left_normal(line[k], line[k + 1]) : left_normal(line[k - 1], line[k]);
    offset[k] = (0.5 * thickness / normal.dot(segment)) * normal;
  }
  std::vector<Vec2> outline;
  outline.reserve(2 * n);
  for (std::size_t k = 0; k < n; ++k) outline.push_back(line[k] + offset[k]);
  for (std::size_t k = n; k-- > 0;) outline.push_back(line[k] - offset[k]);
  return outline;
}

}  // namespace sph
