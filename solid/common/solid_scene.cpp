#include "solid_scene.hpp"

#include <algorithm>
#include <string>

#include "bending_mode.hpp"
#include "hooke_pressure.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/shape.hpp"

namespace cosph::solid {
namespace {

// Young's modulus at x: that of the last weakened region containing it, else the body's.
double youngs_modulus_at(const Vec2& x, const SolidParameters& p) {
  double E = p.E;
  for (const WeakRegion& weak : p.fracture.weakened)
    if (weak.region.contains(x)) E = weak.E;
  return E;
}

// Yield stress at x: that of the last weakened region containing it that
// gives one, else the body's.
double yield_stress_at(const Vec2& x, const SolidParameters& p) {
  double sigma_y = p.fracture.yield_stress;
  for (const WeakRegion& weak : p.fracture.weakened)
    if (weak.yield_stress && weak.region.contains(x)) sigma_y = *weak.yield_stress;
  return sigma_y;
}

double initial_vertical_speed(const Vec2& x, const BendingModeParameters& mode) {
  const double s = x.x() - mode.root_x;
  if (s <= 0.0) return 0.0;
  return mode.tip_speed * cantilever_mode_shape(s, mode.length) /
         cantilever_mode_shape(mode.length, mode.length);
}

// A free particle that starts inside one of solid.walls would be thrown onto
// the wall's face at the first step, on top of its neighbours: the case is
// wrong, and the user should hear so before the run, not see a squashed body.
// Clamped particles may sit in a wall (a plate held in the floor).
void require_free_particles_outside_walls(const sph::CaseFile& case_file, std::size_t body,
                                          const Vec2& x, const SolidParameters& p) {
  for (std::size_t k = 0; k < p.walls.size(); ++k) {
    const bool inside = p.walls[k].holds(x, 1e-6 * p.dx);
    sph::require(!inside, case_file, "solid.walls[" + std::to_string(k) + "]",
                 "a free particle of solid.body[" + std::to_string(body) + "] at (" +
                     sph::format_number(x.x()) + ", " + sph::format_number(x.y()) +
                     ") m starts inside it: move the body out of the wall, or clamp that part "
                     "(solid.clamp)");
  }
}

}  // namespace

SolidScene build_solid_scene(const sph::CaseFile& case_file, const SolidParameters& p) {
  const double mass = p.rho0 * p.dx * p.dx;
  SolidScene particles;
  int next_id = 0;
  for (std::size_t body = 0; body < p.bodies.size(); ++body) {
    for (const Vec2& x : sph::fill(p.bodies[body], p.dx)) {
      // Overlapping body boxes must not put two particles on one site.
      const bool taken = std::any_of(particles.x.begin(), particles.x.end(), [&](const Vec2& y) {
        return (y - x).squaredNorm() < 0.01 * p.dx * p.dx;
      });
      if (taken) continue;
      const bool clamped = std::any_of(p.clamps.begin(), p.clamps.end(),
                                       [&](const sph::Shape& clamp) { return clamp.contains(x); });
      if (!clamped) require_free_particles_outside_walls(case_file, body, x, p);
      const double E = youngs_modulus_at(x, p);
      const double K = bulk_modulus(E, p.nu), G = shear_modulus(E, p.nu);
      particles.id.push_back(next_id++);
      particles.x.push_back(x);
      particles.v.push_back(p.bending_mode && !clamped
                                ? Vec2(0.0, initial_vertical_speed(x, *p.bending_mode))
                                : Vec2::Zero());
      particles.rho.push_back(p.rho0);
      particles.m.push_back(mass);
      particles.K.push_back(K);
      particles.G.push_back(G);
      particles.c.push_back(longitudinal_sound_speed(K, G, p.rho0));
      particles.sigma_y.push_back(yield_stress_at(x, p));
      particles.clamped.push_back(clamped ? 1 : 0);
    }
  }
  return particles;
}

}  // namespace cosph::solid
