// A scene drawn with shapes (docs/scenes.md): water in a V-shaped basin cut
// out of a thick wall. The water starts in hydrostatic balance below its own
// free surface, and the wall keeps its particles within the kernel support 2h
// of its surface and drops the deeper ones.
#include <gtest/gtest.h>

#include "equation_of_state.hpp"
#include "fluid_parameters.hpp"
#include "fluid_scene.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/shape.hpp"
#include "test_support.hpp"

namespace cosph::fluid {
namespace {

constexpr const char* kBasin = R"(
run { end_time: 0.1 gravity { x: 0 y: -9.81 } }
fluid {
  spacing: 0.01
  density: 1000
  water { polygon { point { x: 0.05 y: 0.25 } point { x: 0.2 y: 0.1 } point { x: 0.35 y: 0.25 } } }
  walls {
    min { x: -0.1 y: -0.1 } max { x: 0.5 y: 0.3 }
    subtract { polygon { point { x: -0.01 y: 0.31 } point { x: 0.2 y: 0.1 } point { x: 0.41 y: 0.31 } } }
  }
}
)";

struct Basin {
  FluidParameters parameters;
  FluidParticles particles;
};

Basin build_basin() {
  cosph::testing::ScratchDir dir("shaped_scene");
  const std::string path = dir.file("basin.pbtxt");
  cosph::testing::write_text(path, kBasin);
  const sph::CaseFile case_file = sph::load_case(path);
  Basin basin{read_fluid_parameters(case_file), {}};
  basin.particles = build_fluid_scene(case_file, basin.parameters);
  return basin;
}

TEST(ShapedScene, WaterStartsHydrostaticBelowItsSurface) {
  const Basin basin = build_basin();
  const FluidParameters& p = basin.parameters;
  const FluidParticles& P = basin.particles;
  const TaitEquationOfState eos(p.rho0, p.c0);
  long water = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!P.is_water(i)) continue;
    ++water;
    EXPECT_TRUE(p.water[0].contains(P.x[i])) << P.x[i].transpose();
    EXPECT_DOUBLE_EQ(P.rho[i], eos.density(p.rho0 * 9.81 * (0.25 - P.x[i].y())))
        << "at " << P.x[i].transpose();
  }
  // The triangle's area, 0.15 * 0.15 m^2, in particles of 1e-4 m^2, to
  // within the cells its two slopes cut.
  EXPECT_NEAR(static_cast<double>(water), 225.0, 2.0 * 15.0);
}

TEST(ShapedScene, WallParticlesReachTwoSmoothingLengthsIntoTheWall) {
  const Basin basin = build_basin();
  const FluidParameters& p = basin.parameters;
  const FluidParticles& P = basin.particles;
  const sph::Shape& wall = p.walls[0];
  const double reach = sph::kernel::kSupport * p.h, tolerance = 0.5 * p.dx;
  long kept = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.is_water(i)) continue;
    ++kept;
    EXPECT_LE(wall.depth(P.x[i]), reach + tolerance) << P.x[i].transpose();
  }
  // Every lattice site shallower than 2h has its particle.
  long shallow = 0, deep = 0;
  for (const Vec2& x : sph::fill(wall, p.dx))
    (wall.depth(x) < reach - tolerance ? shallow : deep)++;
  EXPECT_GE(kept, shallow);
  EXPECT_GT(deep, 0);  // the wall is thick: the test can see particles dropped
  EXPECT_LT(kept, shallow + deep);
}

}  // namespace
}  // namespace cosph::fluid
