// solid.walls of any shape (solid/common/wall_contact.hpp): a particle that
// comes within half a spacing of a wall is put on the grown surface along the
// wall's outward normal, and loses only its velocity into the wall.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "jaumann_solver.hpp"
#include "solid_test_cases.hpp"
#include "sphcore/shape.hpp"
#include "wall_contact.hpp"

namespace cosph::solid::jaumann {
namespace {

TEST(ShapedWallContact, ASlopeSendsAParticleOutAlongItsNormal) {
  // A 45-degree slope rising to the right, grown by 5 mm.
  const SolidWall slope(sph::Shape::polygon({{0, 0}, {1, 0}, {1, 1}}), 0.005);
  const Vec2 n = Vec2(-1.0, 1.0) / std::sqrt(2.0);  // out of the slope's face
  const Vec2 t = Vec2(1.0, 1.0) / std::sqrt(2.0);   // along it
  Vec2 x = Vec2(0.5, 0.5) - 0.002 * n, v = 3.0 * t - 2.0 * n;
  EXPECT_TRUE(push_out_of_wall(slope, x, v));
  EXPECT_NEAR((x - (Vec2(0.5, 0.5) + 0.005 * n)).norm(), 0.0, 1e-15);
  // Frictionless: the speed along it stays (the normal is found from a
  // 2 mm offset, to about 1e-13).
  EXPECT_NEAR((v - 3.0 * t).norm(), 0.0, 1e-12);
  // Within the grown margin but outside the slope: pushed too.
  Vec2 near = Vec2(0.5, 0.5) + 0.003 * n, w = -n;
  EXPECT_TRUE(push_out_of_wall(slope, near, w));
  EXPECT_NEAR((near - (Vec2(0.5, 0.5) + 0.005 * n)).norm(), 0.0, 1e-15);
  // Beyond the margin, or leaving: untouched.
  Vec2 far = Vec2(0.5, 0.5) + 0.006 * n, u = -n;
  EXPECT_FALSE(push_out_of_wall(slope, far, u));
  EXPECT_EQ(u, -n);
}

TEST(ShapedWallContact, ABoxWallMovesParticlesExactlyAsBefore) {
  const sph::Shape floor = sph::Shape::box(Vec2(-1.0, -0.1), Vec2(1.0, 0.0));
  const SolidWall wall(floor, 0.005);
  const sph::Region grown = sph::Region{Vec2(-1.0, -0.1), Vec2(1.0, 0.0)}.grown(0.005);
  for (const Vec2& start : {Vec2(0.3, -0.01), Vec2(0.999, -0.05), Vec2(0.3, 0.004)}) {
    Vec2 x = start, v(0.5, -2.0), y = start, w(0.5, -2.0);
    EXPECT_EQ(push_out_of_wall(wall, x, v), push_out_of_wall(grown, y, w));
    EXPECT_EQ(x, y);
    EXPECT_EQ(v, w);
  }
}

// A block dropped onto a dome, a circle of radius 1 m whose top is at y = 0:
// it comes to rest on it, every particle half a spacing or more off it,
// instead of falling through.
TEST(ShapedWallContact, DroppedBlockRestsOnADome) {
  const std::string path = testing::write_case("dome_drop", R"(
run { gravity { x: 0 y: -9.81 } end_time: 1 }
solid {
  spacing: 0.01 density: 1000 youngs_modulus: 1e6 poisson_ratio: 0.3
  body { min { x: 0 y: 0.02 } max { x: 0.1 y: 0.06 } }
  walls { circle { center { x: 0.05 y: -1 } radius: 1 } }
}
)");
  const sph::CaseFile case_file = sph::load_case(path);
  JaumannSolver solver(case_file, read_solid_parameters(case_file));
  while (solver.time() < 0.2) solver.step(solver.step_limits().smallest());
  double closest = 1.0;
  for (const Vec2& x : solver.particles().x)
    closest = std::min(closest, (x - Vec2(0.05, -1.0)).norm() - 1.0);
  EXPECT_GE(closest, 0.005 - 1e-12);  // it fell 20 mm (free fall: 0.2 m in 0.2 s)
  EXPECT_LT(closest, 0.005 + 0.001);  // and rests on the dome
}

}  // namespace
}  // namespace cosph::solid::jaumann
