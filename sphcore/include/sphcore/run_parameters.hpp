// The case's "run" block, and the fields every phase's block has alike,
// validated, with their defaults applied.
#pragma once

#include <cmath>
#include <string>

#include "sphcore/case_file.hpp"
#include "sphcore/types.hpp"

namespace sph {

struct RunParameters {
  double end_time;
  double output_interval;
  double snapshot_interval;
  double cfl;
  Vec2 gravity;
  int threads;  // 0: all cores
  // Simulated time between checkpoints (docs/restart.md); infinite: none.
  double checkpoint_interval = INFINITY;
};

RunParameters read_run_parameters(const CaseFile& case_file);

// A phase's particle spacing dx and smoothing length h = h_factor dx, from its
// block's `spacing` and `h_factor` (1.3 when unset), validated; `block`
// ("fluid", "solid") names the fields in errors.
struct Resolution {
  double dx;
  double h;
};
Resolution read_resolution(const CaseFile& case_file, const std::string& block, double spacing,
                           double h_factor);

// A phase's rest density from its block's `density`, which must be positive.
double read_density(const CaseFile& case_file, const std::string& block, double density);

// Monaghan's coefficients of a phase's pairs (docs/physics.md, "Artificial
// viscosity"): A the linear, B the quadratic term.
struct ArtificialViscosityCoefficients {
  double A;
  double B;
};
// The defaults, by the rule of docs/physics.md ("Artificial viscosity"):
// within the usual ranges, A = 0.01 to 0.1 and B = 0 for water, A ~ B ~ 1 for
// a solid. The coupler's pairs take one phase's (coupler_settings.cpp).
inline constexpr ArtificialViscosityCoefficients kWaterArtificialViscosity{0.02, 0.0};
inline constexpr ArtificialViscosityCoefficients kSolidArtificialViscosity{1.0, 1.0};

// A phase's coefficients from its block's `artificial_viscosity` (A) and
// `artificial_viscosity_quadratic` (B): neither may be negative; 0 takes the
// phase's default.
ArtificialViscosityCoefficients read_artificial_viscosity(
    const CaseFile& case_file, const std::string& block, double A, double B,
    const ArtificialViscosityCoefficients& defaults);

}  // namespace sph
