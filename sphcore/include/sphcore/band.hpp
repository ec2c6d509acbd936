// A band: a strip of even thickness about a line through points, the outline
// of a curved or kinked plate (proto/case.proto Band). Its polygon runs out
// along one side of the line and back along the other, each side the line
// offset by half the thickness along its normal; at a corner the two offsets
// meet at their mitre, so the strip keeps its thickness through the turn.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sphcore/types.hpp"

namespace sph {

// A corner may turn the line by less than this: the mitre of a sharper one
// reaches far beyond half the thickness (1 / cos(turn / 2) of it).
inline constexpr double kBandMostTurnDegrees = 90.0;

// What makes a line unusable as a band's, in words for an error message, or
// nothing: fewer than 2 points, two neighbours that coincide, a corner that
// turns by kBandMostTurnDegrees or more, a thickness that is not positive.
// (An outline that then crosses itself, a bend tighter than half the
// thickness, is polygon_defect's to find.)
std::optional<std::string> band_defect(const std::vector<Vec2>& line, double thickness);

// The band's outline: line.size() points along the left side (the line's
// normal (-t_y, t_x) side), then line.size() back along the right. The line
// must have no band_defect.
std::vector<Vec2> band_outline(const std::vector<Vec2>& line, double thickness);

}  // namespace sph
