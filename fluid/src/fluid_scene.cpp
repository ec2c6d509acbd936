#include "fluid_scene.hpp"

#include <algorithm>
#include <cmath>

#include "equation_of_state.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/region_reader.hpp"

namespace cosph::fluid {
namespace {

// A wall particle deep inside the walls, with nothing but wall within the
// kernel support around it, can never meet water: it is left out, so that thick
// walls cost nothing at fine resolutions.
bool within_reach_of_water(const std::vector<sph::Shape>& walls, const Vec2& x,
                           const FluidParameters& p) {
  const double reach = sph::kernel::kSupport * p.h, step = 0.5 * p.dx;
  // Deeper than the reach inside one wall: every probe below lies inside it.
  // Most wall particles are such, and this saves the probes' cost at start-up.
  if (std::any_of(walls.begin(), walls.end(),
                  [&](const sph::Shape& wall) { return wall.depth(x) > reach; }))
    return false;
  const int samples = static_cast<int>(std::ceil(reach / step));
  for (int i = -samples; i <= samples; ++i)
    for (int j = -samples; j <= samples; ++j) {
      const Vec2 offset(i * step, j * step);
      if (offset.norm() > reach) continue;
      const Vec2 probe = x + offset;
      if (std::none_of(walls.begin(), walls.end(),
                       [&](const sph::Shape& wall) { return wall.contains(probe); }))
        return true;
    }
  return false;
}

}  // namespace

FluidParticles build_fluid_scene(const sph::CaseFile& case_file, const FluidParameters& p) {
  check_walls_close(case_file, p);
  const TaitEquationOfState eos(p.rho0, p.c0);
  const double area = p.dx * p.dx;
  const double g = p.run.gravity.norm();
  FluidParticles particles;
  int next_id = 0;
  // Water starts in hydrostatic balance, so that a still tank stays still and a
  // dam break starts without a pressure wave from a uniform density.
  for (const sph::Shape& water : p.water) {
    for (const Vec2& x : sph::fill(water, p.dx)) {
      const double depth = water.top_at(x.x()) - x.y();
      const double rho = eos.density(p.rho0 * g * depth);
      particles.add(next_id++, Kind::water, x, rho, rho * area);
    }
  }
  for (const sph::Shape& wall : p.walls) {
    particles.first_wall_id.push_back(next_id);
    for (const Vec2& x : sph::fill(wall, p.dx))
      if (within_reach_of_water(p.walls, x, p))
        particles.add(next_id++, Kind::wall, x, p.rho0, p.rho0 * area);
  }
  particles.fixed_walls = particles.first_wall_id.size();
  const auto& fluid = case_file.config.fluid();
  // A moving wall keeps its particles within 2h of its own surface: it moves
  // rigidly, so the others can never meet water.
  const double reach = sph::kernel::kSupport * p.h;
  for (int k = 0; k < fluid.moving_walls_size(); ++k) {
    const sph::Shape shape =
        sph::read_region(fluid.moving_walls(k).region(), case_file,
                         "fluid.moving_walls[" + std::to_string(k) + "].region");
    particles.first_wall_id.push_back(next_id);
    for (const Vec2& x : sph::fill(shape, p.dx))
      if (shape.depth(x) < reach)
        particles.add(next_id++, Kind::moving_wall, x, p.rho0, p.rho0 * area);
  }
  particles.resize_derived();
  return particles;
}

}  // namespace cosph::fluid
