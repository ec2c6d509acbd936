// Small solid cases for the tests, written as case files so that the tests go
// through the same reading and validation as a user's case.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "bending_mode.hpp"
#include "solid_parameters.hpp"
#include "sphcore/runaway_error.hpp"
#include "sphcore/types.hpp"

namespace cosph::solid::testing {

inline std::string temporary_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("cosph_solid_test_" + name)).string();
}

// Written whole and then renamed into place: tests in other processes (ctest
// -j) write and read the same case at the same time, and must never see it
// half written.
inline std::string write_case(const std::string& name, const std::string& text) {
  const std::string path = temporary_path(name + ".pbtxt");
  const std::string part = path + "." + std::to_string(::getpid()) + ".part";
  std::ofstream(part) << text;
  std::filesystem::rename(part, path);
  return path;
}

// A 0.1 x 0.04 m block 20 mm above a floor (solid.walls), under gravity:
// it falls and must come to rest on the floor. `extra` goes into the solid
// block (the model, a gauge).
inline std::string dropped_block_case(const std::string& name, const std::string& extra = "") {
  return write_case(name, R"(
run { gravity { x: 0 y: -9.81 } end_time: 1 }
solid {
  spacing: 0.01 density: 1000 youngs_modulus: 1e6 poisson_ratio: 0.3
  body { min { x: 0 y: 0.02 } max { x: 0.1 y: 0.06 } }
  walls { min { x: -0.1 y: -0.05 } max { x: 0.2 y: 0 } }
)" + extra + "\n}\n");
}

// A coupled case's solid part: a 0.1 x 0.04 m block 20 mm above the water's
// floor, fluid.walls[1], and no solid.walls, so that the solid does not meet
// the floor (unmet_walls.hpp). The water and fluid.walls[0], a wall on the
// left, are out of the block's way. `extra` goes into the solid block;
// `body_bottom` is the block's lower face.
inline std::string tank_drop_case(const std::string& name, const std::string& extra = "",
                                  double body_bottom = 0.02) {
  return write_case(name, R"(
run { gravity { x: 0 y: -9.81 } end_time: 1 }
fluid {
  spacing: 0.01
  water { min { x: -0.3 y: 0 } max { x: -0.2 y: 0.1 } }
  walls { min { x: -0.35 y: 0 } max { x: -0.3 y: 0.2 } }
  walls { min { x: -0.35 y: -0.05 } max { x: 0.2 y: 0 } }
}
solid {
  spacing: 0.01 density: 1000 youngs_modulus: 1e6 poisson_ratio: 0.3
  body { min { x: 0 y: )" + std::to_string(body_bottom) +
                              R"( } max { x: 0.1 y: 0.06 } }
)" + extra + "\n}\n");
}

// Steps the solver until `end_time` and returns the message of the
// sph::RunawayError that stopped it, or "" if none did.
template <class Solver>
std::string runaway_message_before(Solver& solver, double end_time) {
  try {
    while (solver.time() < end_time) solver.step(solver.step_limits().smallest());
  } catch (const sph::RunawayError& error) {
    return error.what();
  }
  return "";
}

// The lowest particle height above `floor`; a block resting on the floor
// y = 0 has its lowest particles half a spacing (5 mm) above it.
template <class Particles>
double lowest_y(const Particles& particles, double floor = -1.0) {
  double lowest = 1.0;
  for (const auto& x : particles.x)
    if (x.y() > floor) lowest = std::min(lowest, x.y());
  return lowest;
}

// The free end's period, from the zero crossings of its y displacement after
// t = 0.01 s (the start-up transient), stepping the solver to `end_time`:
// twice the mean time between crossings. Throws if it crossed fewer than
// twice.
template <class Solver>
double tip_period_until(Solver& solver, double end_time) {
  std::vector<double> crossings;
  double previous_t = 0.0, previous_y = 0.0;
  while (solver.time() < end_time) {
    solver.step(solver.step_limits().smallest());
    const double y = solver.gauges().tip_dy, t = solver.time();
    if (previous_t > 0.01 && (y > 0.0) != (previous_y > 0.0))
      crossings.push_back(previous_t + (t - previous_t) * previous_y / (previous_y - y));
    previous_t = t;
    previous_y = y;
  }
  if (crossings.size() < 2)
    throw std::runtime_error("the free end crossed zero " + std::to_string(crossings.size()) +
                             " times, too few for a period");
  return 2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

// The oscillating plate of cases/oscillating_plate.pbtxt.
inline std::string plate_case_path() {
  return std::string(COSPH_SOURCE_DIR) + "/cases/oscillating_plate.pbtxt";
}

// The period of that plate (0.2 m long, 0.02 m thick, clamped at one end)
// by thin-plate theory, with the case's material.
inline double thin_plate_period(const SolidParameters& par) {
  return 2.0 * std::numbers::pi / cantilever_angular_frequency(par.E, par.nu, par.rho0, 0.02, 0.2);
}

// The particles' total momentum sum m v, per unit depth.
template <class Particles>
sph::Vec2 total_momentum(const Particles& P) {
  sph::Vec2 sum = sph::Vec2::Zero();
  for (std::size_t i = 0; i < P.size(); ++i) sum += P.m[i] * P.v[i];
  return sum;
}

// sum m |v|: the scale that a change of total momentum is round-off against.
template <class Particles>
double momentum_scale(const Particles& P) {
  double scale = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) scale += P.m[i] * P.v[i].norm();
  return scale;
}

}  // namespace cosph::solid::testing
