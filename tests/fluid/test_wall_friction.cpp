// fluid.wall_friction (proto/case.proto): with "dissipation" the momentum
// equation's dissipation term acts between the water and its walls and brakes
// water sliding along a wall; with "none" (free-slip walls) it is left out
// against walls, in the water's accelerations and in the force on the wall
// alike, and nothing else changes.
#include <gtest/gtest.h>

#include <string>

#include "fluid_dynamics.hpp"
#include "fluid_parameters.hpp"
#include "fluid_test_support.hpp"
#include "sphcore/case_file.hpp"

namespace cosph::fluid {
namespace {

using testing::Neighbourhood;
using testing::sort_and_find_neighbours;
using testing::water_parameters;

const std::string kDamBreak = std::string(COSPH_SOURCE_DIR) + "/cases/dam_break.pbtxt";

// Water at rest density sliding at 1 m/s along a floor of wall particles, no
// gravity and no pressure anywhere: within the water nothing moves relative
// to anything, so any force along the floor is the walls' friction.
struct SlidingWater {
  FluidParticles P;
  Neighbourhood n;
  double largest_braking = 0.0;  // the largest -a_x of a water particle, m/s^2
  Vec2 force_on_floor = Vec2::Zero();
  int water = 0;

  explicit SlidingWater(bool wall_friction) {
    FluidParameters p = water_parameters(0.01);
    p.wall_friction = wall_friction;
    p.B = 0.0;
    const int columns = 30, rows = 6;
    for (int i = 0; i < columns; ++i)
      for (int j = 0; j < rows; ++j) {
        P.add(water, Kind::water, Vec2((i + 0.5) * p.dx, (j + 0.5) * p.dx), p.rho0,
              p.rho0 * p.dx * p.dx);
        P.v.back() = Vec2(1.0, 0.0);
        ++water;
      }
    int id = water;
    for (int i = -3; i < columns + 3; ++i)
      for (int layer = 0; layer < 3; ++layer)
        P.add(id++, Kind::wall, Vec2((i + 0.5) * p.dx, -(layer + 0.5) * p.dx), p.rho0,
              p.rho0 * p.dx * p.dx);
    P.first_wall_id = {water};
    sort_and_find_neighbours(P, p, n);
    compute_continuity_and_gradients(P, n.pairs, p);
    for (std::size_t i = 0; i < P.size(); ++i) P.p[i] = 0.0;
    compute_accelerations(P, n.pairs, p);
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.is_water(i)) largest_braking = std::max(largest_braking, -P.a[i].x());
    force_on_floor = forces_on_walls(P, n.pairs, p).at(0);
  }
};

TEST(WallFriction, TheDissipationAgainstAWallBrakesWaterSlidingAlongIt) {
  const SlidingWater with(true);
  EXPECT_GT(with.largest_braking, 1.0);      // m/s^2: the first rows are braked
  EXPECT_GT(with.force_on_floor.x(), 1e-3);  // N/m: dragged along by the water
}

TEST(WallFriction, FreeSlipWallsLeaveSlidingWaterAlone) {
  const SlidingWater free_slip(false);
  EXPECT_LT(free_slip.largest_braking, 1e-9);
  EXPECT_LT(std::abs(free_slip.force_on_floor.x()), 1e-9);
}

TEST(WallFriction, IsReadFromTheCaseAndAnUnknownValueIsRefusedNamingTheField) {
  EXPECT_TRUE(read_fluid_parameters(sph::load_case(kDamBreak, {})).wall_friction);
  EXPECT_FALSE(
      read_fluid_parameters(sph::load_case(kDamBreak, {"fluid.wall_friction=none"})).wall_friction);
  try {
    read_fluid_parameters(sph::load_case(kDamBreak, {"fluid.wall_friction=slip"}));
    FAIL() << "an unknown wall friction was accepted";
  } catch (const sph::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("fluid.wall_friction"), std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find("slip"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace cosph::fluid
