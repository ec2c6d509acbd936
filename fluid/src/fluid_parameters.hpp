// The case's "fluid" block, validated, with the defaults applied (docs/cases.md;
// their rules: docs/physics.md).
#pragma once

#include <string>
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

  // Of the water's sound waves and pressure noise. These defaults are the
  // case's: the readers below return them for an unset field (docs/physics.md,
  // "Choice of water").
  Dissipation dissipation = Dissipation::riemann;
  sph::kernel::Shape kernel = sph::kernel::Shape::wendland_c2;
  bool delta_plus_shifting = false;  // particle_shifting.hpp
  // fluid.wall_friction: how the momentum dissipation term acts against walls.
  WallFriction wall_friction = WallFriction::normal;
};

// h / dx when fluid.h_factor is unset: 1.5 for the Wendland C2 kernel, whose
// lattice sums at 1.3 leave a still tank 2.7 % over hydrostatic pressure, and
// 1.3 for the cubic spline (docs/physics.md, "Kernel").
double default_h_factor(sph::kernel::Shape kernel);

// A warning for the case's reader, or "": the Wendland C2 kernel below
// h = 1.5 dx (an h_factor written for the cubic spline) holds still water
// over hydrostatic pressure.
std::string kernel_resolution_warning(const FluidParameters& p);

// A note for the end of a run, or "": the fastest water moved faster than a
// tenth of the sound speed. Weakly compressible water stands for
// incompressible water only while the Mach number stays below about 0.1
// (Monaghan 1994): its density varies by about Mach^2. What a faster sound
// changes on the dam break: docs/validation.md, "The sound speed".
std::string mach_number_note(double fastest_water, const FluidParameters& p);

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
