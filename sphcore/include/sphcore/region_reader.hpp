// A case's regions (proto/case.proto Region) as shapes (sphcore/shape.hpp),
// checked: a bad outline is refused naming the file, the field and the reason.
#pragma once

#include <string>
#include <vector>

#include "case.pb.h"
#include "sphcore/case_file.hpp"
#include "sphcore/shape.hpp"

namespace sph {

// A case's point or vector (proto/case.proto Vec2) as the solvers' Vec2.
inline Vec2 to_vec2(const cosph::config::Vec2& v) {
  return {v.x(), v.y()};
}

// The points of a band's line (proto/case.proto Band), in order.
inline std::vector<Vec2> band_line(const cosph::config::Band& band) {
  std::vector<Vec2> line;
  for (const auto& point : band.point()) line.push_back(to_vec2(point));
  return line;
}

// The shape of `region`, the case's field `field` (e.g. "fluid.walls[2]").
// Throws ConfigError for a region with no outline or more than one, a polygon
// with a defect (polygon_defect), a band with one (band_defect, or an
// outline that crosses itself), a radius that is not positive, a box whose
// max is not above its min, or an outline file that is missing or malformed
// (its path and line in the message).
Shape read_region(const cosph::config::Region& region, const CaseFile& case_file,
                  const std::string& field);

// The shapes of a repeated region field, e.g. fluid.walls, each named
// "field[k]" in an error.
std::vector<Shape> read_regions(
    const google::protobuf::RepeatedPtrField<cosph::config::Region>& regions,
    const CaseFile& case_file, const std::string& field);

// Reads every region of the case (fluid.water, fluid.walls, solid.body,
// solid.clamp, solid.walls, solid.fracture.weakened[].region), so that a bad
// outline stops `cosph-case plan` before any process starts.
void check_regions(const CaseFile& case_file);

// The vertices of an outline file: "x,y" per line, "#" comments and blank
// lines skipped. Throws ConfigError naming the file and line.
std::vector<Vec2> read_outline(const std::string& path);

}  // namespace sph
