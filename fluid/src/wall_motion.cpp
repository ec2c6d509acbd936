#include "wall_motion.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace cosph::fluid {

using sph::format_number;
using sph::require;
using sph::Vec2;

WallMotion WallMotion::piston(const Vec2& direction, PrescribedMotion displacement) {
  WallMotion wall;
  wall.axis_ = direction.normalized();
  wall.motion_ = std::move(displacement);
  return wall;
}

WallMotion WallMotion::rotation(const Vec2& center, PrescribedMotion angle) {
  WallMotion wall;
  wall.rotates_ = true;
  wall.axis_ = center;
  wall.motion_ = std::move(angle);
  return wall;
}

WallKinematics WallMotion::at(const Vec2& x0, double t) const {
  const MotionState q = motion_.at(t);
  if (!rotates_) return {x0 + q.value * axis_, q.rate * axis_, q.acceleration * axis_};
  const double c = std::cos(q.value), s = std::sin(q.value);
  const Vec2 r0 = x0 - axis_;
  const Vec2 r(c * r0.x() - s * r0.y(), s * r0.x() + c * r0.y());
  const Vec2 Jr(-r.y(), r.x());
  return {axis_ + r, q.rate * Jr, q.acceleration * Jr - q.rate * q.rate * r};
}

PrescribedMotion read_motion_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw sph::ConfigError(path + ": cannot read the motion file: " + std::strerror(errno));
  std::vector<double> times, values;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string content = line.substr(0, line.find('#'));
    if (content.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream fields(content);
    double t = 0.0, q = 0.0;
    char comma = 0;
    std::string rest;
    const std::string where = path + ":" + std::to_string(number) + ": ";
    if (!(fields >> t >> comma >> q) || comma != ',' || (fields >> rest) || !std::isfinite(t) ||
        !std::isfinite(q))
      throw sph::ConfigError(where + "expected \"t,value\" (two numbers), got \"" + line + "\"");
    if (!times.empty() && t <= times.back())
      throw sph::ConfigError(where + "time " + format_number(t) +
                             " s does not increase (the line before has " +
                             format_number(times.back()) + " s)");
    times.push_back(t);
    values.push_back(q);
  }
  if (times.size() < 2)
    throw sph::ConfigError(path + ": needs at least 2 lines \"t,value\", has " +
                           std::to_string(times.size()));
  return PrescribedMotion::samples(std::move(times), std::move(values));
}

namespace {

std::string beside_case(const sph::CaseFile& case_file, const std::string& path) {
  const std::filesystem::path file(path);
  if (file.is_absolute()) return path;
  return (std::filesystem::path(case_file.path).parent_path() / file).string();
}

// A piston's displacement or a rotation's angle, from its sinusoid or its file.
template <typename Message>
PrescribedMotion read_motion(const Message& m, const sph::CaseFile& case_file,
                             const std::string& field, const char* unit) {
  if (!m.motion_file().empty()) {
    require(m.amplitude() == 0.0 && m.period() == 0.0 && m.ramp_time() == 0.0, case_file, field,
            "give either motion_file or amplitude, period and ramp_time, not both");
    try {
      return read_motion_file(beside_case(case_file, m.motion_file()));
    } catch (const sph::ConfigError& error) {
      require(false, case_file, field + ".motion_file", error.what());
    }
  }
  require(std::isfinite(m.amplitude()) && m.amplitude() > 0.0, case_file, field + ".amplitude",
          "must be positive, got " + format_number(m.amplitude()) + " " + unit +
              " (or give motion_file)");
  require(std::isfinite(m.period()) && m.period() > 0.0, case_file, field + ".period",
          "must be positive, got " + format_number(m.period()) + " s");
  require(std::isfinite(m.ramp_time()) && m.ramp_time() >= 0.0, case_file, field + ".ramp_time",
          "must not be negative, got " + format_number(m.ramp_time()) + " s");
  return PrescribedMotion::sinusoid(m.amplitude(), m.period(), m.ramp_time());
}

}  // namespace

std::vector<WallMotion> read_wall_motions(const sph::CaseFile& case_file) {
  std::vector<WallMotion> motions;
  const auto& walls = case_file.config.fluid().moving_walls();
  for (int k = 0; k < walls.size(); ++k) {
    const auto& wall = walls[k];
    const std::string field = "fluid.moving_walls[" + std::to_string(k) + "]";
    require(wall.has_piston() != wall.has_rotation(), case_file, field,
            wall.has_piston() ? "has both piston and rotation: give one"
                              : "needs a motion: piston or rotation");
    if (wall.has_piston()) {
      const auto& piston = wall.piston();
      const Vec2 direction(piston.direction().x(), piston.direction().y());
      require(direction.allFinite() && direction.norm() > 0.0, case_file,
              field + ".piston.direction", "must be a nonzero vector");
      motions.push_back(
          WallMotion::piston(direction, read_motion(piston, case_file, field + ".piston", "m")));
    } else {
      const auto& rotation = wall.rotation();
      const Vec2 center(rotation.center().x(), rotation.center().y());
      require(center.allFinite(), case_file, field + ".rotation.center", "must be finite");
      motions.push_back(WallMotion::rotation(
          center, read_motion(rotation, case_file, field + ".rotation", "rad")));
    }
  }
  return motions;
}

}  // namespace cosph::fluid
