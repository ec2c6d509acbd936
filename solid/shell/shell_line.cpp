#include "shell_line.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "bending_mode.hpp"

namespace cosph::solid::shell {

double ShellLine::phi0() const {
  return std::atan2(tangent.y(), tangent.x());
}

ShellLine read_shell_line(const sph::CaseFile& case_file, double dx) {
  const auto& solid = case_file.config.solid();
  sph::require(solid.body_size() == 1, case_file, "solid.body",
               "the shell model takes exactly one body box (the plate), got " +
                   std::to_string(solid.body_size()));
  const auto& box = solid.body(0);
  sph::require(box.has_min() && box.has_max() && box.subtract().empty(), case_file, "solid.body[0]",
               "the shell model takes a box (min and max) without subtract: it reads the box as a "
               "straight plate");
  const double width = box.max().x() - box.min().x(), height = box.max().y() - box.min().y();
  const bool along_x = width >= height;
  const double length = along_x ? width : height, thickness = along_x ? height : width;
  sph::require(thickness > 0.0, case_file, "solid.body[0]", "must have max > min");
  sph::require(thickness * kLeastSlenderness <= length, case_file, "solid.body[0]",
               "a box " + sph::format_number(width) + " x " + sph::format_number(height) +
                   " m is not a thin plate: the shell model reads the box as a plate of "
                   "thickness its short side, which must be at most 1/" +
                   sph::format_number(kLeastSlenderness) +
                   " of its long side; use solid.model \"jaumann\" or \"total_lagrangian\" "
                   "for a thick body");
  ShellLine line;
  line.tangent = along_x ? Vec2(1.0, 0.0) : Vec2(0.0, 1.0);
  line.start = along_x ? Vec2(box.min().x(), 0.5 * (box.min().y() + box.max().y()))
                       : Vec2(0.5 * (box.min().x() + box.max().x()), box.min().y());
  line.length = length;
  line.thickness = thickness;
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
  sph::require(!parameters.bending_mode || line.tangent.x() > 0.0, case_file,
               "solid.initial_velocity",
               "the shell starts a bending mode on a horizontal plate only (the mode's speed is "
               "vertical and its shape runs along x)");
  ShellParticles P;
  for (int k = 0; k < line.count; ++k) {
    const double S = k * line.ds;
    const Vec2 X = line.start + S * line.tangent;
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
  P.resize_derived();
  for (int k = 0; k + 1 < line.count; ++k)
    if (!P.clamped[static_cast<std::size_t>(k)] || !P.clamped[static_cast<std::size_t>(k + 1)])
      P.stress.add(k, line.ds);
  return P;
}

}  // namespace cosph::solid::shell
