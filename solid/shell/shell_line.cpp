#include "shell_line.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "bending_mode.hpp"
#include "sphcore/region_reader.hpp"

namespace cosph::solid::shell {

namespace {

// The segment of `points` that holds arc length S (the last one past the
// end), and the arc length where it starts.
std::pair<std::size_t, double> segment_at(const std::vector<Vec2>& points, double S) {
  double start = 0.0;
  for (std::size_t j = 0; j + 2 < points.size(); ++j) {
    const double piece = (points[j + 1] - points[j]).norm();
    if (S <= start + piece) return {j, start};
    start += piece;
  }
  return {points.size() - 2, start};
}

Vec2 direction(const std::vector<Vec2>& points, std::size_t j) {
  return (points[j + 1] - points[j]).normalized();
}

}  // namespace

Vec2 ShellLine::at(double S) const {
  const auto [j, start] = segment_at(points, S);
  const Vec2 &from = points[j], &to = points[j + 1];
  return from + (S - start) * ((to - from) / (to - from).norm());
}

Vec2 ShellLine::tangent_at(double S) const {
  const auto [j, start] = segment_at(points, S);
  // On a vertex, to round-off of the line's length.
  const double on_vertex = 1e-9 * length;
  const double end = start + (points[j + 1] - points[j]).norm();
  if (j + 2 < points.size() && end - S < on_vertex)
    return (direction(points, j) + direction(points, j + 1)).normalized();
  if (j > 0 && S - start < on_vertex)
    return (direction(points, j - 1) + direction(points, j)).normalized();
  return direction(points, j);
}

namespace {

// The plate a body stands for: its mid-line's vertices and its thickness. A
// rectangle's mid-line runs along its long side, from the middle of one
// short side to the other's.
struct Plate {
  std::vector<Vec2> line;
  double thickness;
};

Plate plate_of_box(const cosph::config::Region& box) {
  const Vec2 min = sph::to_vec2(box.min()), max = sph::to_vec2(box.max());
  const double width = max.x() - min.x(), height = max.y() - min.y();
  const double mid_y = 0.5 * (min.y() + max.y()), mid_x = 0.5 * (min.x() + max.x());
  if (width >= height) return {{{min.x(), mid_y}, {max.x(), mid_y}}, height};
  return {{{mid_x, min.y()}, {mid_x, max.y()}}, width};
}

// A polygon of four vertices that is a rectangle, at any angle: its sides
// may miss square by kRectangleTolerance of the long side, which coordinates
// typed to four or five digits do.
constexpr double kRectangleTolerance = 1e-3;

Plate plate_of_rectangle(const sph::CaseFile& case_file, const cosph::config::Region& region) {
  const std::string field = "solid.body[0].polygon";
  const auto& points = region.polygon().point();
  sph::require(points.size() == 4, case_file, field,
               "the shell model reads a polygon as a plate only when it is a rectangle: 4 "
               "vertices, got " +
                   std::to_string(points.size()));
  const std::array<Vec2, 4> p{sph::to_vec2(points[0]), sph::to_vec2(points[1]),
                              sph::to_vec2(points[2]), sph::to_vec2(points[3])};
  const Vec2 side_a = p[1] - p[0], side_b = p[2] - p[1];
  const double longest = std::max(side_a.norm(), side_b.norm());
  const bool rectangle =
      (p[2] - p[3] - side_a).norm() <= kRectangleTolerance * longest &&
      (p[3] - p[0] - side_b).norm() <= kRectangleTolerance * longest &&
      std::abs(side_a.dot(side_b)) <= kRectangleTolerance * side_a.norm() * side_b.norm();
  sph::require(rectangle, case_file, field,
               "the shell model reads a polygon as a plate only when it is a rectangle (opposite "
               "sides equal and parallel, corners square, to " +
                   sph::format_number(kRectangleTolerance) + " of the long side)");
  // The short sides' middles are the line's ends.
  if (side_a.norm() >= side_b.norm())
    return {{0.5 * (p[3] + p[0]), 0.5 * (p[1] + p[2])}, side_b.norm()};
  return {{0.5 * (p[0] + p[1]), 0.5 * (p[2] + p[3])}, side_a.norm()};
}

// A band's line as it is given: sph::read_region has checked it.
Plate plate_of_band(const cosph::config::Band& band) {
  return {sph::band_line(band), band.thickness()};
}

double length_of(const std::vector<Vec2>& line) {
  double length = 0.0;
  for (std::size_t j = 0; j + 1 < line.size(); ++j) length += (line[j + 1] - line[j]).norm();
  return length;
}

}  // namespace

ShellLine read_shell_line(const sph::CaseFile& case_file, double dx) {
  const auto& solid = case_file.config.solid();
  sph::require(solid.body_size() == 1, case_file, "solid.body",
               "the shell model takes exactly one body (the plate), got " +
                   std::to_string(solid.body_size()));
  const auto& body = solid.body(0);
  const bool box = body.has_min() && body.has_max();
  sph::require((box || body.has_polygon() || body.has_band()) && body.subtract().empty(), case_file,
               "solid.body[0]",
               "the shell model takes a box (min and max), a rectangle at any angle (a "
               "polygon of 4 vertices) or a band about a mid-line, without subtract: it reads "
               "the body as a plate");
  sph::read_region(body, case_file, "solid.body[0]");
  Plate plate = box                  ? plate_of_box(body)
                : body.has_polygon() ? plate_of_rectangle(case_file, body)
                                     : plate_of_band(body.band());
  const double length = length_of(plate.line);
  sph::require(plate.thickness > 0.0, case_file, "solid.body[0]",
               "must have a thickness (max > min)");
  sph::require(plate.thickness * kLeastSlenderness <= length, case_file, "solid.body[0]",
               "a plate " + sph::format_number(length) + " m long and " +
                   sph::format_number(plate.thickness) +
                   " m thick is not a thin plate: the shell model reads the body as a plate of "
                   "that thickness, which must be at most 1/" +
                   sph::format_number(kLeastSlenderness) +
                   " of its length; use solid.model \"jaumann\" or \"total_lagrangian\" "
                   "for a thick body");
  // Towards +x (towards +y for an upright plate), as the box's line runs.
  const Vec2 chord = plate.line.back() - plate.line.front();
  if (chord.x() < 0.0 || (chord.x() == 0.0 && chord.y() < 0.0))
    std::reverse(plate.line.begin(), plate.line.end());
  ShellLine line;
  line.points = std::move(plate.line);
  line.length = length;
  line.thickness = plate.thickness;
  line.count = static_cast<int>(std::max(1L, std::lround(length / dx))) + 1;
  line.ds = length / (line.count - 1);
  return line;
}

namespace {

bool in_a_clamp(const SolidParameters& parameters, const Vec2& x) {
  return std::any_of(parameters.clamps.begin(), parameters.clamps.end(),
                     [&](const sph::Shape& clamp) { return clamp.contains(x); });
}

}  // namespace

ShellParticles build_shell(const sph::CaseFile& case_file, const SolidParameters& parameters,
                           const ShellLine& line, const ShellSection& section) {
  const bool horizontal = line.straight() && line.points[1].y() == line.points[0].y();
  sph::require(!parameters.bending_mode || horizontal, case_file, "solid.initial_velocity",
               "the shell starts a bending mode on a horizontal plate only (the mode's speed is "
               "vertical and its shape runs along x)");
  ShellParticles P;
  for (int k = 0; k < line.count; ++k) {
    const double S = k * line.ds;
    const Vec2 X = line.at(S);
    const double V = (k == 0 || k == line.count - 1) ? 0.5 * line.ds : line.ds;
    P.id.push_back(k);
    P.X.push_back(X);
    P.S.push_back(S);
    P.V.push_back(V);
    P.m.push_back(section.mass_per_length() * V);
    P.J.push_back(section.inertia_per_length() * V);
    P.c.push_back(section.sound_speed());
    const bool clamped = in_a_clamp(parameters, X);
    P.clamped.push_back(clamped);
    P.x.push_back(X);
    Vec2 v = Vec2::Zero();
    if (parameters.bending_mode && !clamped) {
      const BendingModeParameters& mode = *parameters.bending_mode;
      const double s = X.x() - mode.root_x;
      if (s > 0.0)
        v.y() = mode.tip_speed * cantilever_mode_shape(s, mode.length) /
                cantilever_mode_shape(mode.length, mode.length);
    }
    P.v.push_back(v);
    P.theta.push_back(0.0);
    P.omega.push_back(0.0);
  }
  // The chords between neighbours. A straight line's are ds long, exactly:
  // differences of positions would differ from it by round-off.
  std::vector<Vec2> chord;
  for (std::size_t k = 0; k + 1 < P.size(); ++k)
    chord.push_back(line.straight() ? Vec2(line.points[1] - line.points[0])
                                    : Vec2(P.X[k + 1] - P.X[k]));
  auto angle = [](const Vec2& v) { return std::atan2(v.y(), v.x()); };
  auto length = [&](const Vec2& v) { return line.straight() ? line.ds : v.norm(); };
  for (std::size_t k = 0; k < P.size(); ++k)
    P.phi0.push_back(line.straight() ? angle(chord[0]) : angle(line.tangent_at(P.S[k])));
  P.resize_derived();
  for (std::size_t k = 0; k < chord.size(); ++k)
    if (!P.clamped[k] || !P.clamped[k + 1])
      P.stress.add(static_cast<int>(k), length(chord[k]), angle(chord[k]));
  return P;
}

}  // namespace cosph::solid::shell
