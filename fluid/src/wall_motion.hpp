// The rigid motion of one of fluid.moving_walls (docs/physics.md, "Moving
// walls"): where a wall particle drawn at x0 is at time t, how fast it moves
// and how it accelerates.
//   piston:   x = x0 + d(t) e,               v = d' e,        a = d'' e
//   rotation: x = c + R(theta) (x0 - c) = c + r,  v = theta' J r,  a = theta'' J r - theta'^2 r
// with e the unit stroke direction and J r = (-r_y, r_x) (a quarter turn).
#pragma once

#include <string>
#include <vector>

#include "prescribed_motion.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/types.hpp"

namespace cosph::fluid {

struct WallKinematics {
  sph::Vec2 x, v, a;
};

class WallMotion {
 public:
  static WallMotion piston(const sph::Vec2& direction, PrescribedMotion displacement);
  static WallMotion rotation(const sph::Vec2& center, PrescribedMotion angle);

  WallKinematics at(const sph::Vec2& x0, double t) const;

 private:
  bool rotates_ = false;
  sph::Vec2 axis_ = sph::Vec2::Zero();  // piston: unit direction; rotation: the centre
  PrescribedMotion motion_;
};

// The motions of the case's fluid.moving_walls, in order. Throws
// sph::ConfigError naming the file, the field and the reason: not exactly one
// of piston and rotation, a zero direction, a sinusoid without a positive
// amplitude and period, a negative ramp, or a motion file that is missing,
// malformed (its line given), too short or not increasing in time.
std::vector<WallMotion> read_wall_motions(const sph::CaseFile& case_file);

// The samples of a motion file: "t,value" per line, "#" comments and blank
// lines skipped. Throws sph::ConfigError "PATH:LINE: reason".
PrescribedMotion read_motion_file(const std::string& path);

}  // namespace cosph::fluid
