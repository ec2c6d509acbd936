// Moving walls (docs/physics.md, "Moving walls"): the prescribed motions
// against their own derivatives, a tank accelerated upwards against
// hydrostatics with g + a, a rolling tank that keeps its water, and bad
// motions refused with the file, the field and the reason.
#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "fluid_parameters.hpp"
#include "fluid_solver.hpp"
#include "fluid_test_support.hpp"
#include "prescribed_motion.hpp"
#include "sphcore/case_file.hpp"
#include "test_support.hpp"
#include "wall_motion.hpp"

namespace cosph::fluid {
namespace {

using cosph::testing::ScratchDir;
using cosph::testing::write_text;

// q, dq/dt and d2q/dt2 of `motion` at t against central differences of q.
void expect_consistent_derivatives(const PrescribedMotion& motion, double t, double scale) {
  const double e = 1e-4;
  const MotionState q = motion.at(t), before = motion.at(t - e), after = motion.at(t + e);
  EXPECT_NEAR(q.rate, (after.value - before.value) / (2 * e), 1e-6 * scale) << "t = " << t;
  EXPECT_NEAR(q.acceleration, (after.value - 2 * q.value + before.value) / (e * e), 1e-3 * scale)
      << "t = " << t;
}

TEST(PrescribedMotion, RampedSinusoidHasItsOwnDerivatives) {
  const PrescribedMotion motion = PrescribedMotion::sinusoid(0.03, 0.8, 1.0);
  for (double t : {0.1, 0.37, 0.9, 1.3, 2.05}) expect_consistent_derivatives(motion, t, 1.0);
  // After the ramp: the sinusoid itself.
  const double w = 2 * std::numbers::pi / 0.8;
  EXPECT_NEAR(motion.at(1.7).value, 0.03 * std::sin(w * 1.7), 1e-15);
  EXPECT_NEAR(motion.at(1.7).acceleration, -w * w * 0.03 * std::sin(w * 1.7), 1e-12);
  EXPECT_EQ(motion.at(0.0).rate, 0.0);  // it starts from rest
}

TEST(PrescribedMotion, SamplesOfAQuadraticGiveItExactly) {
  // d = 1 + 0.5 t - 2.45 t^2 on uneven times: value, rate and acceleration
  // exact between the samples, the end intervals included.
  std::vector<double> t = {0.0, 0.1, 0.25, 0.3, 0.5, 0.8}, d;
  const auto exact = [](double s) { return 1.0 + 0.5 * s - 2.45 * s * s; };
  for (double s : t) d.push_back(exact(s));
  const PrescribedMotion motion = PrescribedMotion::samples(t, d);
  for (double s : {0.03, 0.1, 0.2, 0.27, 0.41, 0.79}) {
    const MotionState q = motion.at(s);
    EXPECT_NEAR(q.value, exact(s), 1e-12) << s;
    EXPECT_NEAR(q.rate, 0.5 - 4.9 * s, 1e-11) << s;
    EXPECT_NEAR(q.acceleration, -4.9, 1e-9) << s;
  }
  // Outside the samples it holds still at the end values.
  EXPECT_EQ(motion.at(-1.0).value, d.front());
  EXPECT_EQ(motion.at(2.0).value, d.back());
  EXPECT_EQ(motion.at(2.0).rate, 0.0);
}

TEST(WallMotion, RotationMovesRigidlyWithItsDerivatives) {
  const sph::Vec2 centre(0.2, 0.1), x0(0.5, -0.3);
  const WallMotion wall = WallMotion::rotation(centre, PrescribedMotion::sinusoid(0.3, 1.1, 0.5));
  const double e = 1e-5;
  for (double t : {0.2, 0.7, 1.6}) {
    const WallKinematics k = wall.at(x0, t), before = wall.at(x0, t - e),
                         after = wall.at(x0, t + e);
    EXPECT_NEAR((k.x - centre).norm(), (x0 - centre).norm(), 1e-14);
    EXPECT_LT((k.v - (after.x - before.x) / (2 * e)).norm(), 1e-8);
    EXPECT_LT((k.a - (after.x - 2 * k.x + before.x) / (e * e)).norm(), 1e-3);
  }
  const WallMotion piston = WallMotion::piston({3.0, 4.0}, PrescribedMotion::sinusoid(0.1, 1.0, 0));
  EXPECT_LT((piston.at(x0, 0.25).x - (x0 + sph::Vec2(0.06, 0.08))).norm(), 1e-15);
}

// A closed tank 0.2 m wide, water H = 0.1 m deep, whose three walls all
// accelerate upwards at a(t) rising smoothly from 0 to a0 = g / 2 over
// 0.1 s, written to a motion file (d(t) = the integral twice).
constexpr double kA0 = 0.5 * 9.81, kRamp = 0.1, kH = 0.1, kG = 9.81;

double lift(double t) {
  const double k = std::numbers::pi / kRamp;
  if (t <= kRamp) return 0.5 * kA0 * (0.5 * t * t + (std::cos(k * t) - 1.0) / (k * k));
  const double v = 0.5 * kA0 * kRamp, s = t - kRamp;
  return lift(kRamp) + v * s + 0.5 * kA0 * s * s;
}

std::string tank_case(const std::string& motion_file, double gravity) {
  std::ostringstream c;
  c << "run { end_time: 0.5 cfl: 0.25 gravity { x: 0 y: " << -gravity << " } }\n"
    << R"(
fluid {
  spacing: 0.005
  density: 1000
  viscosity: 1.307e-3
  sound_speed: 17.2
  water { min { x: 0 y: 0 } max { x: 0.2 y: 0.1 } }
)";
  for (const char* box : {"min { x: -0.015 y: -0.015 } max { x: 0.215 y: 0 }",
                          "min { x: -0.015 y: 0 } max { x: 0 y: 0.2 }",
                          "min { x: 0.2 y: 0 } max { x: 0.215 y: 0.2 }"})
    c << "  moving_walls { region { " << box << " } piston { direction { y: 1 } motion_file: \""
      << motion_file << "\" } }\n";
  c << "}\n";
  return c.str();
}

std::string accelerated_tank(const std::string& motion_file) {
  return tank_case(motion_file, kG);
}

struct TankPressure {
  double floor = 0.0;   // the floor's top row under the middle, over rho (g + a) depth
  double water = 0.0;   // the water below y = 0.025 m (drawn), likewise
  long water_lost = 0;  // particles that left
};

// Runs the tank, lifted by lift(t) scaled to a0 (0: at rest), under gravity g,
// and averages the pressures over the last 0.1 s (the start's sound waves,
// period 4 H / c0 = 0.02 s, have settled by then).
TankPressure run_tank(const std::string& name, double a0, double g) {
  ScratchDir dir("moving_walls");
  std::ostringstream samples;
  samples.precision(17);
  for (int k = 0; k <= 200; ++k) samples << k * 0.005 << "," << a0 / kA0 * lift(k * 0.005) << "\n";
  write_text(dir.file(name + ".csv"), samples.str());
  const std::string path = dir.file(name + ".pbtxt");
  write_text(path, tank_case(name + ".csv", g));
  omp_set_num_threads(1);
  const sph::CaseFile case_file = sph::load_case(path);
  FluidSolver solver(case_file, read_fluid_parameters(case_file));
  const long water = solver.gauges().water_particles;
  double floor_measured = 0.0, floor_expected = 0.0, band_measured = 0.0, band_expected = 0.0;
  const double end_time = 0.5;
  while (solver.time() < end_time - 1e-12) {
    solver.step(std::min(solver.step_limits().smallest(), end_time - solver.time()));
    if (solver.time() < 0.4) continue;
    const FluidParticles& P = solver.particles();
    const double rise = a0 / kA0 * lift(solver.time());
    for (std::size_t i = 0; i < P.size(); ++i) {
      const double depth = kH - (P.x[i].y() - rise);  // below the still surface
      if (P.is_moving_wall(i) && std::abs(P.x_drawn[i].y() + 0.0025) < 1e-9 &&
          std::abs(P.x[i].x() - 0.1) < 0.06) {
        floor_measured += P.p[i];
        floor_expected += 1000 * (g + a0) * depth;
      } else if (P.is_water(i) && depth > kH - 0.025) {
        band_measured += P.p[i];
        band_expected += 1000 * (g + a0) * depth;
      }
    }
  }
  return {floor_measured / floor_expected, band_measured / band_expected,
          water - solver.gauges().water_particles};
}

// The floor of a tank accelerated upwards at a0 carries rho (g + a0) (H + dx/2)
// in its top row, as the floor of a tank at rest under gravity g + a0 does:
// the wall pressure's (g - a_w). Measured: 0.9936 of it accelerated, 0.9955
// at rest; without a_w in the extrapolation the accelerated floor read 0.9816,
// 0.014 below the one at rest, out of both tolerances here.
TEST(MovingWalls, UniformlyAcceleratedTankHoldsHydrostaticsOfGPlusA) {
  const TankPressure accelerated = run_tank("accelerated", kA0, kG);
  const TankPressure at_rest = run_tank("at_rest", 0.0, kG + kA0);
  EXPECT_EQ(accelerated.water_lost, 0);
  EXPECT_NEAR(accelerated.floor, at_rest.floor, 0.004)
      << "floor over rho (g + a) depth: accelerated " << accelerated.floor
      << ", at rest under g + a " << at_rest.floor;
  EXPECT_NEAR(accelerated.floor, 1.0, 0.01);
  EXPECT_NEAR(accelerated.water, 1.0, 0.01) << "the water's pressure near the floor";
}

constexpr const char* kRollingTank = R"(
run { end_time: 1.5 cfl: 0.25 gravity { x: 0 y: -9.81 } }
fluid {
  spacing: 0.005
  density: 1000
  viscosity: 1.307e-3
  water { min { x: 0 y: 0 } max { x: 0.2 y: 0.06 } }
  moving_walls { region { min { x: -0.015 y: -0.015 } max { x: 0.215 y: 0 } } ROLL }
  moving_walls { region { min { x: -0.015 y: 0 } max { x: 0 y: 0.2 } } ROLL }
  moving_walls { region { min { x: 0.2 y: 0 } max { x: 0.215 y: 0.2 } } ROLL }
}
)";

TEST(MovingWalls, RollingTankKeepsItsWater) {
  ScratchDir dir("moving_walls");
  std::string text = kRollingTank;
  const std::string roll =
      "rotation { center { x: 0.1 y: 0.03 } amplitude: 0.2 period: 1.0 ramp_time: 0.5 }";
  for (std::size_t at; (at = text.find("ROLL")) != std::string::npos;) text.replace(at, 4, roll);
  const std::string path = dir.file("rolling_tank.pbtxt");
  write_text(path, text);
  omp_set_num_threads(1);
  const sph::CaseFile case_file = sph::load_case(path);
  const FluidParameters parameters = read_fluid_parameters(case_file);
  FluidSolver solver(case_file, parameters);
  const long water = solver.gauges().water_particles;
  const sph::Vec2 centre(0.1, 0.03);
  const PrescribedMotion roll_angle = PrescribedMotion::sinusoid(0.2, 1.0, 0.5);
  double largest_tilt = 0.0;
  while (solver.time() < 1.5 - 1e-12) {
    solver.step(std::min(solver.step_limits().smallest(), 1.5 - solver.time()));
    // Every water particle, seen from the tank, stays inside it.
    const double angle = roll_angle.at(solver.time()).value;
    largest_tilt = std::max(largest_tilt, std::abs(angle));
    const double c = std::cos(-angle), s = std::sin(-angle);
    const FluidParticles& P = solver.particles();
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (!P.is_water(i)) continue;
      const sph::Vec2 r = P.x[i] - centre;
      const sph::Vec2 in_tank = centre + sph::Vec2(c * r.x() - s * r.y(), s * r.x() + c * r.y());
      // Pressed by a moving wall, water comes within a fraction of a
      // spacing of its face; through it, it would pass the wall particles'
      // first row, half a spacing in.
      const double tolerance = 0.0025;
      ASSERT_TRUE(in_tank.x() > -tolerance && in_tank.x() < 0.2 + tolerance &&
                  in_tank.y() > -tolerance)
          << "water particle " << P.id[i] << " at " << in_tank.transpose()
          << " in the tank's frame, t = " << solver.time();
    }
  }
  EXPECT_GT(largest_tilt, 0.19);
  EXPECT_EQ(solver.gauges().water_particles, water);
  // The water sloshes, as water in a rolling tank does.
  EXPECT_GT(solver.gauges().max_speed, 0.05);
}

// The accelerated tank's case with its motion replaced, through cosph-fluid.
struct BadMotion {
  std::string motion, motion_file_text, expected;
};

TEST(MovingWalls, BadMotionIsRefusedWithFileFieldAndReason) {
  ScratchDir dir("moving_walls");
  const std::string lift = dir.file("lift.csv");
  const std::vector<BadMotion> cases = {
      {"piston { direction { y: 1 } motion_file: \"missing.csv\" }", "",
       ": fluid.moving_walls[0].piston.motion_file: " + dir.file("missing.csv") +
           ": cannot read the motion file"},
      {"piston { direction { y: 1 } motion_file: \"lift.csv\" }", "0,0\n0.1,0.01\n0.1 0.02\n",
       ": fluid.moving_walls[0].piston.motion_file: " + lift +
           ":3: expected \"t,value\" (two numbers)"},
      {"piston { direction { y: 1 } motion_file: \"lift.csv\" }", "# t,d\n0,0\n0.2,0.01\n0.1,0\n",
       ": fluid.moving_walls[0].piston.motion_file: " + lift + ":4: time 0.1 s does not increase"},
      {"piston { direction { y: 1 } motion_file: \"lift.csv\" }", "0,0\n",
       ": fluid.moving_walls[0].piston.motion_file: " + lift + ": needs at least 2 lines"},
      {"piston { direction { } amplitude: 0.01 period: 1 }", "",
       ": fluid.moving_walls[0].piston.direction: must be a nonzero vector"},
      {"piston { direction { x: 1 } period: 1 }", "",
       ": fluid.moving_walls[0].piston.amplitude: must be positive"},
      {"rotation { amplitude: 0.1 period: -1 }", "",
       ": fluid.moving_walls[0].rotation.period: must be positive"},
      {"piston { direction { x: 1 } amplitude: 0.01 period: 1 } rotation { amplitude: 0.1 }", "",
       ": fluid.moving_walls[0]: has both piston and rotation"},
      {"", "", ": fluid.moving_walls[0]: needs a motion: piston or rotation"},
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    std::string text = accelerated_tank("lift.csv");
    const std::string original = "piston { direction { y: 1 } motion_file: \"lift.csv\" }";
    text.replace(text.find(original), original.size(), cases[k].motion);
    const std::string path = dir.file("bad" + std::to_string(k) + ".pbtxt");
    write_text(path, text);
    if (!cases[k].motion_file_text.empty()) write_text(lift, cases[k].motion_file_text);
    const auto run = testing::run_cosph_fluid(path, dir.file("out" + std::to_string(k)));
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find(path + cases[k].expected), std::string::npos)
        << "expected \"" << path + cases[k].expected << "\" in: " << run.err;
  }
}

}  // namespace
}  // namespace cosph::fluid
