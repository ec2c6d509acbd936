#include "wall_acceleration_choice.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fluid_parameters.hpp"
#include "solid_parameters.hpp"
#include "substep_choice.hpp"

namespace cosph::coupler {

double acceleration_feedback_ratio(double fluid_density, double fluid_smoothing_length,
                                   double solid_density, double solid_thickness) {
  for (const double value : {fluid_density, fluid_smoothing_length, solid_density, solid_thickness})
    if (!(value > 0.0) || !std::isfinite(value))
      throw std::invalid_argument(
          "the acceleration's feedback ratio needs positive, finite inputs");
  return fluid_density * fluid_smoothing_length / (solid_density * solid_thickness);
}

WallAccelerationChoice read_wall_acceleration_choice(const sph::CaseFile& case_file) {
  const auto& coupling = case_file.config.coupling();
  if (coupling.interface() == "stress_sum")
    return {false, -1.0, "none (coupling.interface \"stress_sum\" has no wall pressure)"};
  if (coupling.has_wall_acceleration()) {
    const bool take = coupling.wall_acceleration();
    return {take, -1.0,
            std::string(take ? "taken" : "left out") + " (coupling.wall_acceleration " +
                (take ? "true" : "false") + ", as set)"};
  }
  const double thickness = solid_thickness(case_file);
  if (!(thickness > 0.0))
    return {false, -1.0,
            "left out (automatic: the case gives no solid.body to take the structure's "
            "thickness from, so the term's feedback ratio is unknown)"};
  try {
    const auto fluid = cosph::fluid::read_fluid_parameters(case_file);
    const auto solid = cosph::solid::read_solid_parameters(case_file);
    const double mu = acceleration_feedback_ratio(fluid.rho0, fluid.h, solid.rho0, thickness);
    const bool take = mu <= kMaxAccelerationFeedbackRatio;
    std::ostringstream why;
    why << (take ? "taken" : "left out") << " (automatic: the term's feedback ratio " << mu
        << (take ? " <= " : " > ") << kMaxAccelerationFeedbackRatio
        << "; rho_f h_f / (rho_s e) with rho_f " << fluid.rho0 << " kg/m^3, h_f " << fluid.h
        << " m, rho_s " << solid.rho0 << " kg/m^3, e " << thickness << " m"
        << (take ? "" : ": the lagged a_w would drive the plate's acceleration unstable") << ")";
    return {take, mu, why.str()};
  } catch (const sph::ConfigError& error) {
    return {false, -1.0,
            std::string("left out (automatic: the term's feedback ratio is unknown, ") +
                error.what() + ")"};
  }
}

}  // namespace cosph::coupler
