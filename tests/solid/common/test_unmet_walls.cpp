// The water's walls that a case without solid.walls leaves the solid blind to
// (unmet_walls.hpp): a body that goes into one stops the run with a message
// that says what to add.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "jaumann_solver.hpp"
#include "solid_parameters.hpp"
#include "solid_test_cases.hpp"

namespace cosph::solid {
namespace {

bool mentions(const std::string& message, const std::string& part) {
  return message.find(part) != std::string::npos;
}

// The block's lowest particles start 25 mm above the floor and are wholly
// inside it half a spacing (5 mm) below its face: 30 mm of free fall.
TEST(UnmetWalls, ABlockFallingIntoTheWatersFloorStopsTheRun) {
  const sph::CaseFile case_file = sph::load_case(testing::tank_drop_case("tank_drop"));
  jaumann::JaumannSolver solver(case_file, read_solid_parameters(case_file));
  const std::string message = testing::runaway_message_before(solver, 0.2);
  ASSERT_FALSE(message.empty()) << "the block went through the floor, t = " << solver.time();
  EXPECT_NEAR(solver.time(), std::sqrt(2.0 * 0.03 / 9.81), 0.002);
  EXPECT_TRUE(mentions(message, "fluid.walls[1]")) << message;
  EXPECT_TRUE(mentions(message, "solid.walls")) << message;
}

// Every water wall is watched until the case lists a wall for the solid.
TEST(UnmetWalls, NoneWhenTheCaseListsSolidWalls) {
  const auto unmet_walls = [](const std::string& name, const std::string& extra) {
    return read_solid_parameters(sph::load_case(testing::tank_drop_case(name, extra))).unmet_walls;
  };
  EXPECT_EQ(unmet_walls("tank_drop_unlisted", "").size(), 2u);
  EXPECT_TRUE(
      unmet_walls("tank_drop_listed", "  walls { min { x: -0.35 y: -0.05 } max { x: 0.2 y: 0 } }")
          .empty());
}

// A block whose lowest row starts inside the floor: the case put it there, so
// the floor is left out and only the left wall is watched.
TEST(UnmetWalls, AWallAFreeParticleStartsInsideIsLeftOut) {
  const sph::CaseFile case_file =
      sph::load_case(testing::tank_drop_case("tank_drop_inside", "", -0.02));
  jaumann::JaumannSolver solver(case_file, read_solid_parameters(case_file));
  ASSERT_EQ(solver.parameters().unmet_walls.size(), 1u);
  EXPECT_EQ(solver.parameters().unmet_walls[0].index, 0);
  EXPECT_NO_THROW(for (int step = 0; step < 20; ++step)
                      solver.step(solver.step_limits().smallest()));
}

// A particle is wholly inside a wall when its centre lies half a spacing or
// more inside it: for a box, inside the box shrunk by that much, as always;
// for a circle, within its radius less that much.
TEST(UnmetWalls, WhollyInsideAWallOfAnyShape) {
  const double half = 0.005;
  const UnmetWall disc(0, sph::Shape::circle(Vec2(0.0, 0.0), 0.1), half);
  EXPECT_TRUE(disc.contains(Vec2(0.0, 0.0)));
  EXPECT_TRUE(disc.contains(Vec2(0.0, 0.095)));
  EXPECT_FALSE(disc.contains(Vec2(0.0, 0.097)));
  EXPECT_FALSE(disc.contains(Vec2(0.09, 0.09)));  // inside the disc's bounds, outside the disc
  const UnmetWall floor(1, sph::Shape::box(Vec2(-1.0, -0.1), Vec2(1.0, 0.0)), half);
  const sph::Region shrunk = sph::Region{Vec2(-1.0, -0.1), Vec2(1.0, 0.0)}.grown(-half);
  for (const Vec2& x : {Vec2(0.0, -0.005), Vec2(0.0, -0.004), Vec2(0.996, -0.05), Vec2(0, 0.1)})
    EXPECT_EQ(floor.contains(x), shrunk.contains(x)) << x.transpose();
}

}  // namespace
}  // namespace cosph::solid
