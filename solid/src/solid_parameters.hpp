// The case's "solid" block, validated, with the defaults of SPEC.md applied.
#pragma once

#include <optional>
#include <vector>

#include "case.pb.h"
#include "sphcore/case_file.hpp"
#include "sphcore/run_parameters.hpp"
#include "sphcore/types.hpp"

namespace cosph::solid {

struct ArtificialStressParameters {
  bool enabled;
  double epsilon;   // eps
  double exponent;  // n
};

struct WeakRegion {
  cosph::config::Box region;
  double E;
};

struct FractureParameters {
  bool enabled;
  double yield_stress;               // sigma_y
  std::vector<WeakRegion> weakened;  // applies whether or not failure is enabled
};

struct BendingModeParameters {
  double tip_speed, root_x, length;
};

struct SolidParameters {
  sph::RunParameters run;
  double dx;     // initial spacing
  double h;      // smoothing length
  double rho0;   // reference density
  double E, nu;  // Young's modulus, Poisson's ratio of the body
  double K, G;   // bulk and shear modulus of the body
  double c0;     // longitudinal sound speed of the body
  double A, B;   // Monaghan artificial viscosity
  ArtificialStressParameters artificial_stress;
  FractureParameters fracture;
  std::optional<BendingModeParameters> bending_mode;
  std::optional<sph::Vec2> tip_gauge;
};

// Throws sph::ConfigError naming the file, field and reason for bad input.
SolidParameters read_solid_parameters(const sph::CaseFile& case_file);

}  // namespace cosph::solid
