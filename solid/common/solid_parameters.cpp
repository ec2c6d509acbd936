#include "solid_parameters.hpp"

#include <algorithm>
#include <cmath>

#include "hooke_pressure.hpp"
#include "sphcore/region.hpp"
#include "sphcore/region_reader.hpp"

namespace cosph::solid {

using sph::format_number;
using sph::require;

namespace {

// The elastic constants of the body or of a weakened region.
void check_elastic(const sph::CaseFile& case_file, const std::string& field, double E, double nu) {
  require(E > 0.0, case_file, field + ".youngs_modulus",
          "must be positive, got " + format_number(E) + " Pa");
  require(nu > -1.0 && nu < 0.5, case_file, field + ".poisson_ratio",
          "must lie in (-1, 0.5) (at 0.5 the bulk modulus E / (3 (1 - 2 nu)) is infinite), got " +
              format_number(nu));
}

// The region's bounds at least dx wide and high, so that it holds a particle.
sph::Shape checked_region(const cosph::config::Region& region, const sph::CaseFile& case_file,
                          const std::string& field, double dx) {
  sph::Shape shape = sph::read_region(region, case_file, field);
  const sph::Bounds b = shape.bounds();
  require(b.max.x() - b.min.x() >= dx && b.max.y() - b.min.y() >= dx, case_file, field,
          "must be at least one spacing wide and high (max > min)");
  return shape;
}

std::vector<sph::Shape> checked_regions(
    const google::protobuf::RepeatedPtrField<cosph::config::Region>& regions,
    const sph::CaseFile& case_file, const std::string& field, double dx) {
  std::vector<sph::Shape> shapes;
  for (int k = 0; k < regions.size(); ++k)
    shapes.push_back(
        checked_region(regions[k], case_file, field + "[" + std::to_string(k) + "]", dx));
  return shapes;
}

ArtificialStressParameters read_artificial_stress(const sph::CaseFile& case_file) {
  const auto& block = case_file.config.solid().artificial_stress();
  require(block.epsilon() >= 0.0, case_file, "solid.artificial_stress.epsilon",
          "must not be negative, got " + format_number(block.epsilon()));
  require(block.exponent() >= 0.0, case_file, "solid.artificial_stress.exponent",
          "must not be negative, got " + format_number(block.exponent()));
  return {block.enabled(), block.epsilon() > 0.0 ? block.epsilon() : 0.3,
          block.exponent() > 0.0 ? block.exponent() : 4.0};
}

FractureParameters read_fracture(const sph::CaseFile& case_file, double dx, double nu) {
  const auto& block = case_file.config.solid().fracture();
  FractureParameters p{block.enabled(), block.yield_stress(), {}};
  if (p.enabled)
    require(block.yield_stress() > 0.0, case_file, "solid.fracture.yield_stress",
            "must be positive when fracture is enabled, got " +
                format_number(block.yield_stress()) + " Pa");
  for (int k = 0; k < block.weakened_size(); ++k) {
    const auto& weak = block.weakened(k);
    const std::string field = "solid.fracture.weakened[" + std::to_string(k) + "]";
    check_elastic(case_file, field, weak.youngs_modulus(), nu);
    sph::Shape region = checked_region(weak.region(), case_file, field + ".region", dx);
    require(
        weak.yield_stress() >= 0.0, case_file, field + ".yield_stress",
        "must not be negative (0: the body's), got " + format_number(weak.yield_stress()) + " Pa");
    p.weakened.push_back(
        {std::move(region), weak.youngs_modulus(),
         weak.yield_stress() > 0.0 ? std::optional<double>(weak.yield_stress()) : std::nullopt});
  }
  return p;
}

}  // namespace

SolidParameters read_solid_parameters(const sph::CaseFile& case_file) {
  require(case_file.config.has_solid(), case_file, "solid", "missing: this case has no solid");
  const auto& solid = case_file.config.solid();
  SolidParameters p;
  p.run = sph::read_run_parameters(case_file);

  require(solid.model().empty() || solid.model() == "jaumann" ||
              solid.model() == "total_lagrangian" || solid.model() == "shell",
          case_file, "solid.model",
          "unknown model '" + solid.model() +
              "' (known: jaumann, total_lagrangian, shell; a solid model of your own: name its "
              "program in solid.executable)");
  p.model = solid.model() == "total_lagrangian" ? SolidModel::total_lagrangian
            : solid.model() == "shell"          ? SolidModel::shell
                                                : SolidModel::jaumann;
  const sph::Resolution resolution =
      sph::read_resolution(case_file, "solid", solid.spacing(), solid.h_factor());
  p.dx = resolution.dx;
  p.h = resolution.h;
  p.rho0 = sph::read_density(case_file, "solid", solid.density());
  check_elastic(case_file, "solid", solid.youngs_modulus(), solid.poisson_ratio());
  p.E = solid.youngs_modulus();
  p.nu = solid.poisson_ratio();
  p.K = bulk_modulus(p.E, p.nu);
  p.G = shear_modulus(p.E, p.nu);
  p.c0 = longitudinal_sound_speed(p.K, p.G, p.rho0);

  const sph::ArtificialViscosityCoefficients av = sph::read_artificial_viscosity(
      case_file, "solid", solid.artificial_viscosity(), solid.artificial_viscosity_quadratic(),
      sph::kSolidArtificialViscosity);
  p.A = av.A;
  p.B = av.B;

  const std::string& gradient = solid.velocity_gradient();
  require(gradient.empty() || gradient == "quadratic" || gradient == "linear", case_file,
          "solid.velocity_gradient", "unknown '" + gradient + "' (known: quadratic, linear)");
  p.velocity_gradient =
      gradient == "quadratic" ? VelocityGradient::quadratic : VelocityGradient::linear;

  require(solid.body_size() > 0, case_file, "solid.body", "no solid region given");
  // A shell's body and clamp boxes may be thinner than a spacing: its
  // thickness is a property, not particles (solid/shell/shell_line.hpp).
  const double least_side = p.model == SolidModel::shell ? 0.0 : p.dx;
  p.bodies = checked_regions(solid.body(), case_file, "solid.body", least_side);
  p.clamps = checked_regions(solid.clamp(), case_file, "solid.clamp", least_side);
  require(!solid.has_end_load() || p.model == SolidModel::shell, case_file, "solid.end_load",
          "applies to solid.model 'shell' only");
  require(!solid.has_shell_damping() || p.model == SolidModel::shell, case_file,
          "solid.shell_damping", "applies to solid.model 'shell' only");
  p.shell_damping = !solid.has_shell_damping() || solid.shell_damping();

  p.artificial_stress = read_artificial_stress(case_file);
  p.fracture = read_fracture(case_file, p.dx, p.nu);
  // Failure needs a rule for what a failed particle's neighbours still
  // transmit: the total-Lagrangian solid (its reference neighbours) and the
  // shell (its line's bending) have none yet. Refused here, where
  // cosph-case reads it too, so the run stops before any process starts.
  require(!(p.fracture.enabled && p.model != SolidModel::jaumann), case_file,
          "solid.fracture.enabled",
          std::string("von Mises failure is not implemented for solid.model '") +
              model_name(p.model) + "' (use 'jaumann', or turn fracture off)");

  if (solid.has_initial_velocity()) {
    const auto& mode = solid.initial_velocity();
    require(mode.length() > 0.0, case_file, "solid.initial_velocity.length",
            "must be positive, got " + format_number(mode.length()) + " m");
    require(std::abs(mode.tip_speed()) < p.c0, case_file, "solid.initial_velocity.tip_speed",
            "must be below the sound speed " + format_number(p.c0) + " m/s, got " +
                format_number(mode.tip_speed()) + " m/s");
    p.bending_mode = BendingModeParameters{mode.tip_speed(), mode.root_x(), mode.length()};
  }
  require(!solid.has_hourglass_control() || p.model != SolidModel::jaumann, case_file,
          "solid.hourglass_control", "applies to solid.model 'total_lagrangian' or 'shell' only");
  require(!solid.has_hourglass_control() || solid.hourglass_control() >= 0.0, case_file,
          "solid.hourglass_control",
          "must not be negative (0 turns it off), got " + format_number(solid.hourglass_control()));
  p.hourglass_alpha = solid.has_hourglass_control()  ? solid.hourglass_control()
                      : p.model == SolidModel::shell ? kDefaultShellHourglassControl
                                                     : kDefaultHourglassControl;
  if (solid.has_broken_part_below_y()) {
    const double top = solid.broken_part_below_y();
    const bool below_some_body =
        std::any_of(p.bodies.begin(), p.bodies.end(),
                    [&](const sph::Shape& body) { return body.bounds().min.y() < top; });
    require(
        below_some_body, case_file, "solid.broken_part_below_y",
        "no solid lies below it (" + format_number(top) + " m): the broken part would be empty");
    p.broken_part_below_y = top;
  }
  for (const sph::Shape& wall : checked_regions(solid.walls(), case_file, "solid.walls", p.dx))
    p.walls.emplace_back(wall, 0.5 * p.dx);
  if (solid.walls().empty() && case_file.config.has_fluid()) {
    const auto water_walls =
        sph::read_regions(case_file.config.fluid().walls(), case_file, "fluid.walls");
    for (std::size_t k = 0; k < water_walls.size(); ++k)
      p.unmet_walls.emplace_back(static_cast<int>(k), water_walls[k], 0.5 * p.dx);
  }
  if (solid.has_tip_gauge()) p.tip_gauge = sph::Vec2(solid.tip_gauge().x(), solid.tip_gauge().y());
  return p;
}

const char* model_name(SolidModel model) {
  switch (model) {
    case SolidModel::total_lagrangian:
      return "total_lagrangian";
    case SolidModel::shell:
      return "shell";
    case SolidModel::jaumann:
      break;
  }
  return "jaumann";
}

const char* model_executable(SolidModel model) {
  switch (model) {
    case SolidModel::total_lagrangian:
      return "cosph-solid-tl";
    case SolidModel::shell:
      return "cosph-solid-shell";
    case SolidModel::jaumann:
      break;
  }
  return "cosph-solid-jaumann";
}

void require_model(const sph::CaseFile& case_file, const SolidParameters& parameters,
                   SolidModel model) {
  require(parameters.model == model, case_file, "solid.model",
          std::string("is '") + model_name(parameters.model) + "', which " +
              model_executable(model) + " does not run: run " + model_executable(parameters.model) +
              " (coupler/cosph picks it), or set "
              "solid.model: \"" +
              model_name(model) + "\"");
}

}  // namespace cosph::solid
