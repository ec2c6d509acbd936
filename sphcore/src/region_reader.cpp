#include "sphcore/region_reader.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sphcore/band.hpp"

namespace sph {
namespace {

bool finite(const Vec2& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y());
}

std::string text(const Vec2& v) {
  std::ostringstream out;
  out << "(" << format_number(v.x()) << ", " << format_number(v.y()) << ")";
  return out.str();
}

// A polygon_file path relative to the case file's folder.
std::string beside_case(const CaseFile& case_file, const std::string& path) {
  const std::filesystem::path file(path);
  if (file.is_absolute()) return path;
  return (std::filesystem::path(case_file.path).parent_path() / file).string();
}

Shape checked_polygon(const std::vector<Vec2>& points, const CaseFile& case_file,
                      const std::string& field, const std::string& source) {
  for (std::size_t k = 0; k < points.size(); ++k)
    require(finite(points[k]), case_file, field,
            source + "point " + std::to_string(k + 1) + " is not finite");
  if (const auto defect = polygon_defect(points))
    require(false, case_file, field, source + *defect);
  return Shape::polygon(points);
}

}  // namespace

std::vector<Vec2> read_outline(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path + ": cannot read the outline file: " + std::strerror(errno));
  std::vector<Vec2> points;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string content = line.substr(0, line.find('#'));
    if (content.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream fields(content);
    double x = 0.0, y = 0.0;
    char comma = 0;
    std::string rest;
    if (!(fields >> x >> comma >> y) || comma != ',' || (fields >> rest) || !std::isfinite(x) ||
        !std::isfinite(y))
      throw ConfigError(path + ":" + std::to_string(number) +
                        ": expected \"x,y\" in metres, got \"" + line + "\"");
    points.emplace_back(x, y);
  }
  return points;
}

Shape read_region(const cosph::config::Region& region, const CaseFile& case_file,
                  const std::string& field) {
  const bool box = region.has_min() || region.has_max();
  const int outlines = static_cast<int>(box) + static_cast<int>(region.has_polygon()) +
                       static_cast<int>(region.has_circle()) +
                       static_cast<int>(!region.polygon_file().empty()) +
                       static_cast<int>(region.has_band());
  require(outlines == 1, case_file, field,
          outlines == 0
              ? "needs an outline: min and max (a box), polygon, circle, polygon_file or band"
              : "has more than one outline: give exactly one of min/max, polygon, circle, "
                "polygon_file, band (use subtract to combine regions)");
  Shape shape = Shape::box(Vec2::Zero(), Vec2::Zero());
  if (box) {
    const Vec2 lo = to_vec2(region.min()), hi = to_vec2(region.max());
    require(region.has_min() && region.has_max(), case_file, field, "a box needs both min and max");
    require(finite(lo) && finite(hi), case_file, field, "the box's corners must be finite");
    require(hi.x() > lo.x() && hi.y() > lo.y(), case_file, field,
            "max " + text(hi) + " m must lie above and to the right of min " + text(lo) + " m");
    shape = Shape::box(lo, hi);
  } else if (region.has_polygon()) {
    std::vector<Vec2> points;
    for (const auto& point : region.polygon().point()) points.push_back(to_vec2(point));
    shape = checked_polygon(points, case_file, field + ".polygon", "");
  } else if (region.has_circle()) {
    const Vec2 centre = to_vec2(region.circle().center());
    const double radius = region.circle().radius();
    require(finite(centre), case_file, field + ".circle.center", "must be finite");
    require(std::isfinite(radius) && radius > 0.0, case_file, field + ".circle.radius",
            "must be positive, got " + format_number(radius) + " m");
    shape = Shape::circle(centre, radius);
  } else if (region.has_band()) {
    const std::vector<Vec2> line = band_line(region.band());
    for (std::size_t k = 0; k < line.size(); ++k)
      require(finite(line[k]), case_file, field + ".band",
              "point " + std::to_string(k + 1) + " is not finite");
    const double thickness = region.band().thickness();
    if (const auto defect = band_defect(line, thickness))
      require(false, case_file, field + ".band", *defect);
    const std::vector<Vec2> outline = band_outline(line, thickness);
    if (const auto defect = polygon_defect(outline))
      require(false, case_file, field + ".band",
              "the line crosses itself or bends more tightly than half the thickness: its "
              "outline, the line offset by " +
                  format_number(0.5 * thickness) + " m to either side, is not a simple polygon (" +
                  *defect + ")");
    shape = Shape::polygon(outline);
  } else {
    const std::string path = beside_case(case_file, region.polygon_file());
    std::vector<Vec2> points;
    try {
      points = read_outline(path);
    } catch (const ConfigError& error) {
      require(false, case_file, field + ".polygon_file", error.what());
    }
    shape = checked_polygon(points, case_file, field + ".polygon_file", path + ": ");
  }
  for (int k = 0; k < region.subtract_size(); ++k)
    shape.subtract(
        read_region(region.subtract(k), case_file, field + ".subtract[" + std::to_string(k) + "]"));
  return shape;
}

std::vector<Shape> read_regions(
    const google::protobuf::RepeatedPtrField<cosph::config::Region>& regions,
    const CaseFile& case_file, const std::string& field) {
  std::vector<Shape> shapes;
  shapes.reserve(static_cast<std::size_t>(regions.size()));
  for (int k = 0; k < regions.size(); ++k)
    shapes.push_back(read_region(regions[k], case_file, field + "[" + std::to_string(k) + "]"));
  return shapes;
}

void check_regions(const CaseFile& case_file) {
  const auto& fluid = case_file.config.fluid();
  read_regions(fluid.water(), case_file, "fluid.water");
  read_regions(fluid.walls(), case_file, "fluid.walls");
  const auto& solid = case_file.config.solid();
  read_regions(solid.body(), case_file, "solid.body");
  read_regions(solid.clamp(), case_file, "solid.clamp");
  read_regions(solid.walls(), case_file, "solid.walls");
  const auto& weakened = solid.fracture().weakened();
  for (int k = 0; k < weakened.size(); ++k)
    read_region(weakened[k].region(), case_file,
                "solid.fracture.weakened[" + std::to_string(k) + "].region");
}

}  // namespace sph
