#include "coupler_settings.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fluid_parameters.hpp"
#include "participant/coupling_timeout.hpp"
#include "sphcore/run_parameters.hpp"
#include "substep_choice.hpp"

namespace cosph::coupler {
namespace {

void require_finite_non_negative(double value, const sph::CaseFile& case_file,
                                 const std::string& field) {
  sph::require(std::isfinite(value), case_file, field,
               "must be a finite number, got " + sph::format_number(value));
  sph::require(value >= 0.0, case_file, field,
               "must not be negative, got " + sph::format_number(value));
}

// The coefficients of the phase whose terms the interface model uses, which
// coupling.artificial_viscosity(_quadratic) override when given.
sph::ArtificialViscosityCoefficients phase_artificial_viscosity(const sph::CaseFile& case_file,
                                                                InterfaceModel model) {
  if (model == InterfaceModel::stress_sum) {
    // Damped as solid pairs are (A ~ 1 for a solid, docs/physics.md,
    // "Artificial viscosity"): c_ij there is mostly the solid's sound speed.
    // Damped as water (the water's A), the interface let water at negative
    // pressure clump into the bending plate; with the mean of the two
    // phases' coefficients the elastic plate still blew up.
    const auto& solid = case_file.config.solid();
    return sph::read_artificial_viscosity(case_file, "solid", solid.artificial_viscosity(),
                                          solid.artificial_viscosity_quadratic(),
                                          sph::kSolidArtificialViscosity);
  }
  // Water against a wall: the water's coefficients (and its sound speed).
  const auto& fluid = case_file.config.fluid();
  return sph::read_artificial_viscosity(case_file, "fluid", fluid.artificial_viscosity(),
                                        fluid.artificial_viscosity_quadratic(),
                                        sph::kWaterArtificialViscosity);
}

CrossPhaseParameters read_cross_phase_parameters(const sph::CaseFile& case_file) {
  const auto& coupling = case_file.config.coupling();
  const std::string& name = coupling.interface();
  sph::require(name.empty() || name == "moving_wall" || name == "stress_sum", case_file,
               "coupling.interface",
               "unknown interface model '" + name + "' (known: moving_wall, stress_sum)");
  require_finite_non_negative(coupling.artificial_viscosity(), case_file,
                              "coupling.artificial_viscosity");
  require_finite_non_negative(coupling.artificial_viscosity_quadratic(), case_file,
                              "coupling.artificial_viscosity_quadratic");
  CrossPhaseParameters par;
  par.model = name == "stress_sum" ? InterfaceModel::stress_sum : InterfaceModel::moving_wall;
  par.gravity = sph::read_run_parameters(case_file).gravity;
  const sph::ArtificialViscosityCoefficients phase =
      phase_artificial_viscosity(case_file, par.model);
  par.A = coupling.artificial_viscosity() > 0.0 ? coupling.artificial_viscosity() : phase.A;
  par.B = coupling.artificial_viscosity_quadratic() > 0.0
              ? coupling.artificial_viscosity_quadratic()
              : phase.B;
  // The water meets the solid as it meets its own walls, with the terms of
  // its dissipation (read as the fluid reads it). The stress sum is the
  // study's rule and keeps its own artificial viscosity.
  if (par.model == InterfaceModel::moving_wall &&
      cosph::fluid::read_dissipation(case_file) == cosph::fluid::Dissipation::riemann) {
    par.riemann_dissipation = true;
    par.rho0 = sph::read_density(case_file, "fluid", case_file.config.fluid().density());
  }
  // With its own wall friction too: a numerical friction left out against the
  // tank's walls is left out against the solid's.
  if (par.model == InterfaceModel::moving_wall)
    par.wall_friction = cosph::fluid::read_wall_friction(case_file);
  // And through its own kernel, as its wall pressure and wall pairs are
  // taken. The stress sum meets the solid's stress, whose pairs are all
  // cubic spline, and keeps that kernel.
  if (par.model == InterfaceModel::moving_wall)
    par.kernel = cosph::fluid::read_kernel_shape(case_file);
  return par;
}

}  // namespace

CouplerSettings read_coupler_settings(const sph::CaseFile& case_file) {
  sph::require(case_file.config.has_fluid() && case_file.config.has_solid(), case_file,
               "fluid, solid", "a coupled case needs both");
  const auto& coupling = case_file.config.coupling();
  CouplerSettings settings;
  settings.run = sph::read_run_parameters(case_file);
  settings.timeout_seconds = coupling::coupling_timeout_seconds(case_file);
  settings.cross_phase = read_cross_phase_parameters(case_file);
  settings.wall_acceleration = read_wall_acceleration_choice(case_file);
  settings.cross_phase.wall_acceleration = settings.wall_acceleration.take;
  settings.stepping = read_substep_choice(case_file);
  sph::require(coupling.solid_step().empty() || coupling.solid_step() == "own" ||
                   coupling.solid_step() == "fluid",
               case_file, "coupling.solid_step",
               "must be \"own\" (default) or \"fluid\", not \"" + coupling.solid_step() + "\"");
  settings.solid_at_fluid_step = coupling.solid_step() == "fluid";
  if (settings.solid_at_fluid_step)
    settings.stepping.reason =
        "the fluid's step, taken whole by the solid (coupling.solid_step \"fluid\")";
  return settings;
}

}  // namespace cosph::coupler
