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

}  // namespace cosph::fluid
