// The water measurements of timeseries.csv.
#pragma once

#include "fluid_parameters.hpp"
#include "fluid_particles.hpp"

namespace cosph::fluid {

struct WaterGauges {
  double front;           // surge front: farthest water from the left wall, plus dx/2
  double height;          // water height at the left wall (first two columns of particles)
  double kinetic_energy;  // per unit depth, J/m
  double max_speed;
  long water_particles;
};

WaterGauges measure(const FluidParticles& particles, const FluidParameters& parameters);

// The water's pressure at `probe` as a fixed wall particle there would have
// it (Adami et al. 2012, sphcore/wall_pressure.hpp): the kernel-weighted mean
// of the water within 2h, with the hydrostatic correction to the probe's own
// height. Zero with no water in reach.
double probe_pressure(const FluidParticles& particles, const FluidParameters& parameters,
                      const Vec2& probe);

}  // namespace cosph::fluid
