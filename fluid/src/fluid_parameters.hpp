// The case's "fluid" block, validated, with the defaults applied (docs/cases.md;
// their rules: docs/physics.md).
#pragma once

#include <vector>

#include "dissipation.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/kernel_shape.hpp"
#include "sphcore/run_parameters.hpp"
#include "sphcore/shape.hpp"
#include "wall_motion.hpp"

namespace cosph::fluid {

struct FluidParameters {
  sph::RunParameters run;
  double dx;                    // initial spacing
  double h;                     // smoothing length
  double rho0;                  // reference density
  double mu;                    // dynamic viscosity
  double c0;                    // artificial sound speed
  double delta;                 // delta-SPH coefficient; 0 = off
  double A, B;                  // Monaghan artificial viscosity
  double left_wall_x, floor_y;  // gauges
  std::vector<sph::Vec2> pressure_probes;
  std::vector<sph::Shape> water;         // fluid.water
  std::vector<sph::Shape> walls;         // fluid.walls
  std::vector<double> level_probes;      // x of each water-level gauge
  std::vector<WallMotion> wall_motions;  // of fluid.moving_walls, in order

  // Of the water's sound waves and pressure noise.
  Dissipation dissipation = Dissipation::delta_sph;
  sph::kernel::Shape kernel = sph::kernel::Shape::cubic_spline;
  bool delta_plus_shifting = false;  // particle_shifting.hpp
  // fluid.wall_friction: how the momentum dissipation term acts against walls.
  WallFriction wall_friction = WallFriction::dissipation;
};

// Throws sph::ConfigError naming the file, field and reason for bad input.
FluidParameters read_fluid_parameters(const sph::CaseFile& case_file);

// fluid.dissipation alone, checked as read_fluid_parameters checks it: the
// coupler reads it too, to meet the solid with the water's wall terms.
Dissipation read_dissipation(const sph::CaseFile& case_file);

// fluid.wall_friction alone, likewise: the coupler meets the solid with the
// water's wall friction, as a moving wall.
WallFriction read_wall_friction(const sph::CaseFile& case_file);

// fluid.kernel alone, likewise: the coupler pairs the water with the solid
// through the water's kernel.
sph::kernel::Shape read_kernel_shape(const sph::CaseFile& case_file);

}  // namespace cosph::fluid
