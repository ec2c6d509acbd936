// The solid measurements of timeseries.csv.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "solid_particles.hpp"
#include "sphcore/interface_particles.hpp"
#include "sphcore/types.hpp"

namespace cosph::solid {

struct SolidGauges {
  double tip_dx, tip_dy;  // mean displacement of the tip gauge's particles (0 without one)
  double kinetic_energy;  // per unit depth, J/m
  double elastic_energy;  // per unit depth, J/m
  double max_speed;
  double max_von_mises;
  long failed;  // failed particles
};

// The columns every solid model writes to timeseries.csv, named and with units.
inline std::vector<sph::Gauge> named_gauges(const SolidGauges& g) {
  return {{"tip_dx", "m", g.tip_dx},
          {"tip_dy", "m", g.tip_dy},
          {"kinetic_energy", "J/m", g.kinetic_energy},
          {"elastic_energy", "J/m", g.elastic_energy},
          {"max_speed", "m/s", g.max_speed},
          {"max_von_mises", "Pa", g.max_von_mises},
          {"failed", "1", static_cast<double>(g.failed)}};
}

// The particles a tip gauge at point p follows: those nearest p at the start
// (several when p lies midway between lattice sites, as a plate's mid-line
// does with an even number of particles across).
std::vector<int> tip_gauge_ids(const std::vector<int>& id, const std::vector<Vec2>& x0,
                               const sph::Vec2& p, double dx);
inline std::vector<int> tip_gauge_ids(const SolidParticles& particles, const sph::Vec2& p,
                                      double dx) {
  return tip_gauge_ids(particles.id, particles.x0, p, dx);
}

// Mean displacement x - x0 of the particles with the given (sorted) ids; zero for none.
Vec2 mean_displacement(const std::vector<int>& id, const std::vector<Vec2>& x,
                       const std::vector<Vec2>& x0, const std::vector<int>& tip_ids);

// Centre of mass of the free (not clamped) particles whose initial y lies
// below `below_y`: in the fracture scene, the part a crack above that height
// breaks off (before it breaks, the bending plate's lower part). Zero for none.
// The array form serves every solid model (x0: initial positions).
Vec2 broken_part_centre(const std::vector<Vec2>& x0, const std::vector<Vec2>& x,
                        const std::vector<double>& m, const std::vector<std::uint8_t>& clamped,
                        double below_y);
inline Vec2 broken_part_centre(const SolidParticles& particles, double below_y) {
  return broken_part_centre(particles.x0, particles.x, particles.m, particles.clamped, below_y);
}

// broken_x, broken_y (m) for timeseries.csv when the case sets
// solid.broken_part_below_y, else nothing.
inline std::vector<sph::Gauge> broken_part_gauges(const std::optional<double>& below_y,
                                                  const std::vector<Vec2>& x0,
                                                  const std::vector<Vec2>& x,
                                                  const std::vector<double>& m,
                                                  const std::vector<std::uint8_t>& clamped) {
  if (!below_y) return {};
  const Vec2 centre = broken_part_centre(x0, x, m, clamped, *below_y);
  return {{"broken_x", "m", centre.x()}, {"broken_y", "m", centre.y()}};
}

SolidGauges measure(const SolidParticles& particles, const std::vector<int>& tip_ids);

}  // namespace cosph::solid
