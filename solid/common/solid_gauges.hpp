// The solid measurements of timeseries.csv.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "sphcore/gauge.hpp"
#include "sphcore/types.hpp"
#include "sphcore/von_mises.hpp"

namespace cosph::solid {

using sph::Vec2;

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

// The gauges of any solid model's particles (id, x, v, m, sigma, and failed
// where the model has it), with x0 their initial positions and
// elastic_energy(i) particle i's strain energy per unit depth.
template <class Particles, class ElasticEnergy>
SolidGauges measure(const Particles& P, const std::vector<Vec2>& x0,
                    const std::vector<int>& tip_ids, ElasticEnergy&& elastic_energy) {
  SolidGauges g{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0};
  const Vec2 tip = mean_displacement(P.id, P.x, x0, tip_ids);
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double speed2 = P.v[i].squaredNorm();
    g.kinetic_energy += 0.5 * P.m[i] * speed2;
    g.max_speed = std::max(g.max_speed, speed2);
    g.elastic_energy += elastic_energy(i);
    g.max_von_mises = std::max(g.max_von_mises, sph::von_mises(P.sigma[i]));
    if constexpr (requires { P.failed; }) g.failed += P.failed[i];
  }
  g.tip_dx = tip.x();
  g.tip_dy = tip.y();
  g.max_speed = std::sqrt(g.max_speed);
  return g;
}

}  // namespace cosph::solid
