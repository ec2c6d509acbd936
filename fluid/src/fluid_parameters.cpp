#include "fluid_parameters.hpp"

#include <algorithm>
#include <cmath>

#include "sphcore/region_reader.hpp"

namespace cosph::fluid {

using sph::format_number;
using sph::require;

FluidParameters read_fluid_parameters(const sph::CaseFile& case_file) {
  require(case_file.config.has_fluid(), case_file, "fluid", "missing: this case has no fluid");
  const auto& fluid = case_file.config.fluid();
  FluidParameters p;
  p.run = sph::read_run_parameters(case_file);

  const sph::Resolution resolution =
      sph::read_resolution(case_file, "fluid", fluid.spacing(), fluid.h_factor());
  p.dx = resolution.dx;
  p.h = resolution.h;
  require(fluid.density() > 0.0, case_file, "fluid.density",
          "must be positive, got " + format_number(fluid.density()) + " kg/m^3");
  p.rho0 = fluid.density();
  require(fluid.viscosity() >= 0.0, case_file, "fluid.viscosity", "must not be negative");
  p.mu = fluid.viscosity();
  require(fluid.artificial_viscosity() >= 0.0, case_file, "fluid.artificial_viscosity",
          "must not be negative");
  require(fluid.artificial_viscosity_quadratic() >= 0.0, case_file,
          "fluid.artificial_viscosity_quadratic", "must not be negative");
  p.A = fluid.artificial_viscosity() > 0.0 ? fluid.artificial_viscosity() : 0.02;
  p.B = fluid.artificial_viscosity_quadratic();
  p.delta = fluid.density_diffusion() < 0.0   ? 0.0
            : fluid.density_diffusion() > 0.0 ? fluid.density_diffusion()
                                              : 0.1;
  require(
      fluid.dissipation().empty() || fluid.dissipation() == "delta_sph" ||
          fluid.dissipation() == "fourtakas" || fluid.dissipation() == "riemann",
      case_file, "fluid.dissipation",
      "unknown dissipation '" + fluid.dissipation() + "' (known: delta_sph, fourtakas, riemann)");
  p.dissipation = fluid.dissipation() == "riemann"     ? Dissipation::riemann
                  : fluid.dissipation() == "fourtakas" ? Dissipation::fourtakas
                                                       : Dissipation::delta_sph;

  require(fluid.water_size() > 0, case_file, "fluid.water", "no water region given");
  double tallest = 0.0;
  for (int k = 0; k < fluid.water_size(); ++k) {
    const auto& box = fluid.water(k);
    const std::string field = "fluid.water[" + std::to_string(k) + "]";
    require(box.max().x() - box.min().x() >= p.dx && box.max().y() - box.min().y() >= p.dx,
            case_file, field, "must be at least one spacing wide and high (max > min)");
    tallest = std::max(tallest, box.max().y() - box.min().y());
  }
  require(fluid.sound_speed() >= 0.0, case_file, "fluid.sound_speed", "must not be negative");
  const double g = p.run.gravity.norm();
  require(fluid.sound_speed() > 0.0 || g > 0.0, case_file, "fluid.sound_speed",
          "must be given when there is no gravity (the default is 10 sqrt(2 g H))");
  p.c0 = fluid.sound_speed() > 0.0 ? fluid.sound_speed() : 10.0 * std::sqrt(2.0 * g * tallest);

  for (int k = 0; k < fluid.walls_size(); ++k) {
    const auto& box = fluid.walls(k);
    const std::string field = "fluid.walls[" + std::to_string(k) + "]";
    const double thickness = std::min(box.max().x() - box.min().x(), box.max().y() - box.min().y());
    require(thickness >= 2.0 * p.h - 1e-9, case_file, field,
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
