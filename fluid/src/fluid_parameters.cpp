#include "fluid_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "sphcore/region_reader.hpp"

namespace cosph::fluid {

using sph::format_number;
using sph::require;

Dissipation read_dissipation(const sph::CaseFile& case_file) {
  const std::string& name = case_file.config.fluid().dissipation();
  require(name.empty() || name == "delta_sph" || name == "fourtakas" || name == "riemann",
          case_file, "fluid.dissipation",
          "unknown dissipation '" + name + "' (known: delta_sph, fourtakas, riemann)");
  if (name.empty()) return FluidParameters{}.dissipation;
  return name == "delta_sph"   ? Dissipation::delta_sph
         : name == "fourtakas" ? Dissipation::fourtakas
                               : Dissipation::riemann;
}

WallFriction read_wall_friction(const sph::CaseFile& case_file) {
  const std::string& name = case_file.config.fluid().wall_friction();
  require(name.empty() || name == "dissipation" || name == "none" || name == "normal", case_file,
          "fluid.wall_friction",
          "unknown wall friction '" + name + "' (known: dissipation, none, normal)");
  if (name.empty()) return FluidParameters{}.wall_friction;
  return name == "none"          ? WallFriction::none
         : name == "dissipation" ? WallFriction::dissipation
                                 : WallFriction::normal;
}

sph::kernel::Shape read_kernel_shape(const sph::CaseFile& case_file) {
  const std::string& name = case_file.config.fluid().kernel();
  require(name.empty() || name == "cubic_spline" || name == "wendland_c2", case_file,
          "fluid.kernel", "unknown kernel '" + name + "' (known: cubic_spline, wendland_c2)");
  if (name.empty()) return FluidParameters{}.kernel;
  return name == "cubic_spline" ? sph::kernel::Shape::cubic_spline
                                : sph::kernel::Shape::wendland_c2;
}

double default_h_factor(sph::kernel::Shape kernel) {
  return kernel == sph::kernel::Shape::wendland_c2 ? 1.5 : 1.3;
}

std::string kernel_resolution_warning(const FluidParameters& p) {
  const double wendland_h_factor = default_h_factor(sph::kernel::Shape::wendland_c2);
  if (p.kernel != sph::kernel::Shape::wendland_c2 || p.h >= (wendland_h_factor - 1e-9) * p.dx)
    return "";
  return "fluid.h_factor " + format_number(p.h / p.dx) + " with the Wendland C2 kernel: below " +
         format_number(wendland_h_factor) +
         " its lattice sums hold still water over hydrostatic pressure (2.7 % at 1.3); leave "
         "h_factor unset for the kernel's own " +
         format_number(wendland_h_factor) + " (docs/physics.md, \"Kernel\")";
}

std::string mach_number_note(double fastest_water, const FluidParameters& p) {
  constexpr double kLargestMach = 0.1;
  const double mach = fastest_water / p.c0;
  if (!(mach > kLargestMach)) return "";
  const double wanted_c0 = fastest_water / kLargestMach;
  return "the fastest water moved at " + format_number(fastest_water, 3) + " m/s, Mach " +
         format_number(mach, 3) + " against c0 = " + format_number(p.c0, 3) +
         " m/s: weakly compressible water stands for incompressible water while Mach stays "
         "below about 0.1 (Monaghan 1994), its density varying by about Mach^2. "
         "fluid.sound_speed = " +
         format_number(wanted_c0, 3) + " m/s keeps 0.1, at " + format_number(wanted_c0 / p.c0, 3) +
         " times the steps (docs/validation.md, \"The sound speed\")";
}

FluidParameters read_fluid_parameters(const sph::CaseFile& case_file) {
  require(case_file.config.has_fluid(), case_file, "fluid", "missing: this case has no fluid");
  const auto& fluid = case_file.config.fluid();
  FluidParameters p;
  p.run = sph::read_run_parameters(case_file);

  p.kernel = read_kernel_shape(case_file);
  const sph::Resolution resolution =
      sph::read_resolution(case_file, "fluid", fluid.spacing(),
                           fluid.h_factor() > 0.0 ? fluid.h_factor() : default_h_factor(p.kernel));
  p.dx = resolution.dx;
  p.h = resolution.h;
  p.rho0 = sph::read_density(case_file, "fluid", fluid.density());
  require(fluid.viscosity() >= 0.0, case_file, "fluid.viscosity", "must not be negative");
  p.mu = fluid.viscosity();
  const sph::ArtificialViscosityCoefficients av = sph::read_artificial_viscosity(
      case_file, "fluid", fluid.artificial_viscosity(), fluid.artificial_viscosity_quadratic(),
      sph::kWaterArtificialViscosity);
  p.A = av.A;
  p.B = av.B;
  p.delta = fluid.density_diffusion() < 0.0   ? 0.0
            : fluid.density_diffusion() > 0.0 ? fluid.density_diffusion()
                                              : 0.1;
  p.dissipation = read_dissipation(case_file);
  require(
      fluid.shifting().empty() || fluid.shifting() == "none" || fluid.shifting() == "delta_plus",
      case_file, "fluid.shifting",
      "unknown particle shifting '" + fluid.shifting() + "' (known: none, delta_plus)");
  p.delta_plus_shifting = fluid.shifting() == "delta_plus";
  p.wall_friction = read_wall_friction(case_file);

  require(fluid.water_size() > 0, case_file, "fluid.water", "no water region given");
  p.water = sph::read_regions(fluid.water(), case_file, "fluid.water");
  double tallest = 0.0;
  for (std::size_t k = 0; k < p.water.size(); ++k) {
    const sph::Bounds b = p.water[k].bounds();
    require(b.max.x() - b.min.x() >= p.dx && b.max.y() - b.min.y() >= p.dx, case_file,
            "fluid.water[" + std::to_string(k) + "]",
            "must be at least one spacing wide and high (max > min)");
    tallest = std::max(tallest, b.max.y() - b.min.y());
  }
  require(fluid.sound_speed() >= 0.0, case_file, "fluid.sound_speed", "must not be negative");
  const double g = p.run.gravity.norm();
  require(fluid.sound_speed() > 0.0 || g > 0.0, case_file, "fluid.sound_speed",
          "must be given when there is no gravity (the default is 10 sqrt(2 g H))");
  p.c0 = fluid.sound_speed() > 0.0 ? fluid.sound_speed() : 10.0 * std::sqrt(2.0 * g * tallest);

  p.walls = sph::read_regions(fluid.walls(), case_file, "fluid.walls");
  for (std::size_t k = 0; k < p.walls.size(); ++k) {
    // The diameter of the largest circle inside the wall: exact for a box,
    // found on a lattice of dx/4 otherwise, and allowed that lattice's error.
    const sph::Shape& wall = p.walls[k];
    const bool box = wall.kind() == sph::Shape::Kind::box && wall.holes().empty();
    const double thickness = sph::thickness(wall, 0.25 * p.dx);
    const double allowance = box ? 1e-9 : 0.5 * p.dx;
    require(thickness >= 2.0 * p.h - allowance, case_file, "fluid.walls[" + std::to_string(k) + "]",
            "is " + format_number(thickness) + " m thick, less than the kernel support 2h = " +
                format_number(2.0 * p.h) + " m: water would see through it");
  }
  for (int k = 0; k < fluid.moving_walls_size(); ++k) {
    const std::string field = "fluid.moving_walls[" + std::to_string(k) + "].region";
    require(fluid.moving_walls(k).has_region(), case_file, field, "missing: where is the wall?");
    const sph::Shape shape = sph::read_region(fluid.moving_walls(k).region(), case_file, field);
    if (shape.kind() != sph::Shape::Kind::box) continue;
    const sph::Bounds box = shape.bounds();
    const double thickness = (box.max - box.min).minCoeff();
    require(thickness >= 2.0 * p.h - 1e-9, case_file, field,
            "is " + format_number(thickness) + " m thick, less than the kernel support 2h = " +
                format_number(2.0 * p.h) + " m: water would see through it");
  }
  p.wall_motions = read_wall_motions(case_file);
  p.left_wall_x = fluid.gauges().left_wall_x();
  p.floor_y = fluid.gauges().floor_y();
  for (const auto& probe : fluid.gauges().pressure_probes())
    p.pressure_probes.emplace_back(probe.x(), probe.y());
  for (int k = 0; k < fluid.gauges().level_probes_size(); ++k) {
    const double x = fluid.gauges().level_probes(k);
    require(std::isfinite(x), case_file, "fluid.gauges.level_probes[" + std::to_string(k) + "]",
            "must be finite");
    p.level_probes.push_back(x);
  }
  return p;
}

}  // namespace cosph::fluid
