#include "gauges.hpp"

#include <algorithm>
#include <cmath>

#include "sphcore/kernel_shape.hpp"
#include "sphcore/wall_pressure.hpp"

namespace cosph::fluid {

WaterGauges measure(const FluidParticles& P, const FluidParameters& par) {
  // A particle stands for the square of side dx around it: the water's edge is
  // half a spacing beyond the outermost particle centre.
  const double half = 0.5 * par.dx;
  WaterGauges g{0.0, 0.0, 0.0, 0.0, 0};
  double front_x = par.left_wall_x, top_y = par.floor_y;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!P.is_water(i)) continue;
    ++g.water_particles;
    front_x = std::max(front_x, P.x[i].x() + half);
    if (P.x[i].x() < par.left_wall_x + 2.0 * par.dx) top_y = std::max(top_y, P.x[i].y() + half);
    const double speed2 = P.v[i].squaredNorm();
    g.kinetic_energy += 0.5 * P.m[i] * speed2;
    g.max_speed = std::max(g.max_speed, speed2);
  }
  g.max_speed = std::sqrt(g.max_speed);
  g.front = front_x - par.left_wall_x;
  g.height = top_y - par.floor_y;
  return g;
}

double probe_pressure(const FluidParticles& P, const FluidParameters& par, const Vec2& probe) {
  const double support2 = sph::kernel::kSupport * par.h * sph::kernel::kSupport * par.h;
  const sph::kernel::ShapedValue W_of(par.kernel, par.h);
  sph::WallPressureSum sum;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!P.is_water(i)) continue;
    const Vec2 x_pi = probe - P.x[i];
    const double r2 = x_pi.squaredNorm();
    if (r2 < support2) sum.add(P.p[i], P.rho[i], x_pi, W_of(std::sqrt(r2)));
  }
  return sum.wall_pressure(par.run.gravity);
}

}  // namespace cosph::fluid
