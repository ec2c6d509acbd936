#include "substep_choice.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fluid_parameters.hpp"
#include "solid_parameters.hpp"
#include "sphcore/region_reader.hpp"

namespace cosph::coupler {

namespace {

std::string multi_rate_words(int max_substeps) {
  return "multi-rate, at most " + std::to_string(max_substeps) + " sub-steps a window";
}

}  // namespace

double window_added_mass_ratio(const AddedMassInputs& in) {
  for (const double value :
       {in.cfl, in.fluid_density, in.fluid_sound_speed, in.fluid_smoothing_length, in.solid_density,
        in.solid_sound_speed, in.solid_smoothing_length, in.solid_thickness})
    if (!(value > 0.0) || !std::isfinite(value))
      throw std::invalid_argument("the added-mass ratio needs positive, finite inputs");
  const double window = in.cfl * std::max(in.fluid_smoothing_length / in.fluid_sound_speed,
                                          in.solid_smoothing_length / in.solid_sound_speed);
  return in.fluid_density * in.fluid_sound_speed * window / (in.solid_density * in.solid_thickness);
}

SubstepChoice choose_substeps(const AddedMassInputs& in) {
  const double mu = window_added_mass_ratio(in);
  const bool multi_rate = mu <= kMaxWindowAddedMassRatio;
  std::ostringstream why;
  why << (multi_rate ? multi_rate_words(kAutomaticMaxSubsteps) : "synchronised")
      << " (automatic: added-mass ratio of a window " << mu << (multi_rate ? " <= " : " > ")
      << kMaxWindowAddedMassRatio << "; rho_f c_f W / (rho_s e) with rho_f " << in.fluid_density
      << " kg/m^3, c_f " << in.fluid_sound_speed << " m/s, W <= " << in.cfl
      << " max(h_f / c_f, h_s / c_s) = "
      << in.cfl * std::max(in.fluid_smoothing_length / in.fluid_sound_speed,
                           in.solid_smoothing_length / in.solid_sound_speed)
      << " s, rho_s " << in.solid_density << " kg/m^3, e " << in.solid_thickness << " m)";
  return {multi_rate ? kAutomaticMaxSubsteps : 1, mu, why.str()};
}

double solid_thickness(const sph::CaseFile& case_file) {
  const auto& solid = case_file.config.solid();
  double thinnest = 0.0;
  const std::vector<sph::Shape> bodies = sph::read_regions(solid.body(), case_file, "solid.body");
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const auto& region = solid.body(static_cast<int>(k));
    // Other outlines than a box and a band: found on a lattice of a quarter
    // of the solid's spacing (of a twentieth of the body's least side
    // without one), which reads a band up to twice that too thin.
    const sph::Bounds b = bodies[k].bounds();
    const double least_side = std::min(b.max.x() - b.min.x(), b.max.y() - b.min.y());
    const double side =
        region.has_band() && region.subtract().empty()
            ? region.band().thickness()
            : sph::thickness(bodies[k],
                             solid.spacing() > 0.0 ? 0.25 * solid.spacing() : 0.05 * least_side);
    thinnest = thinnest == 0.0 ? side : std::min(thinnest, side);
  }
  return thinnest;
}

SubstepChoice read_substep_choice(const sph::CaseFile& case_file) {
  const int set = case_file.config.coupling().max_substeps();
  sph::require(set >= 0, case_file, "coupling.max_substeps",
               "must not be negative (0: automatic, 1: synchronised, more: multi-rate)");
  if (set >= 1)
    return {set, -1.0,
            (set == 1 ? std::string("synchronised") : multi_rate_words(set)) +
                " (coupling.max_substeps " + std::to_string(set) + ", as set)"};
  const double thickness = solid_thickness(case_file);
  if (!(thickness > 0.0))
    return {1, -1.0,
            "synchronised (automatic: the case gives no solid.body to take the "
            "structure's thickness from, so the added-mass ratio is unknown)"};
  try {
    const auto fluid = cosph::fluid::read_fluid_parameters(case_file);
    const auto solid = cosph::solid::read_solid_parameters(case_file);
    SubstepChoice choice = choose_substeps(
        {fluid.run.cfl, fluid.rho0, fluid.c0, fluid.h, solid.rho0, solid.c0, solid.h, thickness});
    choice.coupling_stiffness_share = fluid.dissipation == cosph::fluid::Dissipation::riemann
                                          ? kRiemannCouplingStiffnessShare
                                          : kCouplingStiffnessShare;
    return choice;
  } catch (const sph::ConfigError& error) {
    // The solvers check their own blocks; a solid program of the user's own
    // may read fields the built-in solids refuse.
    return {1, -1.0,
            std::string("synchronised (automatic: the added-mass ratio is unknown, ") +
                error.what() + ")"};
  }
}

SubstepChoice account_for_the_solids_damping(const SubstepChoice& choice,
                                             const SolidDamping& damping,
                                             const std::string& solid_name) {
  const bool automatic_multi_rate = choice.added_mass_ratio >= 0.0 && choice.max_substeps > 1;
  const double omega = damping.fastest_mode_angular_frequency;
  const double zeta = damping.fastest_mode_damping_ratio;
  const bool states_a_mode = omega > 0.0 && std::isfinite(omega) && zeta >= 0.0;
  if (!automatic_multi_rate || (!damping.undamped_modes && !states_a_mode)) return choice;
  const std::string solid = "the solid '" + solid_name + "'";
  const std::string added_mass = "; the added-mass ratio alone would allow " + choice.reason;
  if (damping.undamped_modes || !(zeta > 0.0))
    return {1, choice.added_mass_ratio,
            "synchronised (automatic: " + solid +
                " reports modes it does not damp, which the held forces of multi-rate windows "
                "pump; docs/auto_substeps.md" +
                added_mass + ")",
            choice.coupling_stiffness_share};
  const double s = choice.coupling_stiffness_share;
  const double max_window = kDampingWindowMargin * 4.0 * zeta / (s * omega);
  std::ostringstream why;
  why << multi_rate_words(choice.max_substeps) << ", windows at most " << max_window
      << " s (automatic: set by the damping of " << solid
      << " at its fastest mode: a held force's negative damping s omega W / 4 below the mode's "
         "damping ratio with a safety factor 2, W <= 2 zeta / (s omega) with zeta "
      << zeta << ", omega " << omega << " rad/s, s " << s
      << (s == kRiemannCouplingStiffnessShare ? " (the Riemann water's, measured)"
                                              : " (the whole mode's)")
      << "; omega W <= " << omega * max_window << added_mass << ")";
  return {choice.max_substeps, choice.added_mass_ratio, why.str(), s, max_window};
}

}  // namespace cosph::coupler
