// The case's "solid" block, validated, with the defaults of docs/physics.md applied.
#pragma once

#include <optional>
#include <vector>

#include "case.pb.h"
#include "sphcore/case_file.hpp"
#include "sphcore/region.hpp"
#include "sphcore/run_parameters.hpp"
#include "sphcore/shape.hpp"
#include "sphcore/types.hpp"
#include "unmet_walls.hpp"
#include "wall_contact.hpp"

namespace cosph::solid {

struct ArtificialStressParameters {
  bool enabled;
  double epsilon;   // eps
  double exponent;  // n
};

struct WeakRegion {
  sph::Shape region;
  double E;
  std::optional<double> yield_stress;  // the body's when absent
};

struct FractureParameters {
  bool enabled;
  double yield_stress;               // sigma_y of the body
  std::vector<WeakRegion> weakened;  // applies whether or not failure is enabled
};

struct BendingModeParameters {
  double tip_speed, root_x, length;
};

// Default of solid.hourglass_control, the alpha of Ganzenmueller's hourglass
// control (solid/total_lagrangian/hourglass_control.hpp), by a stated rule,
// not fitted to a scene: the coefficient of the algorithm author's reference
// implementation, LAMMPS smd/tlsph, whose examples (aluminum_strip_pull,
// rubber_strip_pull, rubber_rings_3d, fluid_structure_interaction in
// examples/USER/smd) all use hg = 10. LAMMPS writes the pair's error as
// delta = 0.5 (gamma . x_ij / r) with gamma the mean of the two predictions, so
// its force is hg/4 (delta_i + delta_j) where Ganzenmueller 2015 (CMAME 286)
// writes alpha/2 (delta_i + delta_j): hg = 10 is alpha = 5 here.
inline constexpr double kDefaultHourglassControl = 5.0;

// Default of solid.hourglass_control for the shell (solid/shell/line_hourglass.hpp):
// the control's stiffness of a neighbour pair is then the field's own (GA for
// the position, EI for the rotation) over the pair's distance squared,
// kernel-weighted. Chosen by that rule, not fitted; docs/results/shell.md
// gives the period with it off.
inline constexpr double kDefaultShellHourglassControl = 1.0;

// The constitutive model, each with its own executable (solid.model).
enum class SolidModel {
  jaumann,           // cosph-solid-jaumann: Gray, Monaghan & Swift 2001, Jaumann stress rate
  total_lagrangian,  // cosph-solid-tl: total-Lagrangian SPH, St Venant-Kirchhoff
  shell,             // cosph-solid-shell: a Reissner-Mindlin line on a thin body's mid-line
};

// How the Jaumann solid takes its velocity gradient (solid.velocity_gradient).
enum class VelocityGradient {
  linear,     // renormalised kernel gradient (docs/physics.md, "Jaumann solid"), exact for linear
              // fields; the default
  quadratic,  // least-squares fit exact for quadratic fields (sphcore/quadratic_gradient.hpp):
              // for small deformations; it is not paired with the stress divergence as the
              // linear one is, and a large-amplitude plate blows up with it
};

struct SolidParameters {
  SolidModel model;
  sph::RunParameters run;
  double dx;                           // initial spacing
  double h;                            // smoothing length
  double rho0;                         // reference density
  double E, nu;                        // Young's modulus, Poisson's ratio of the body
  double K, G;                         // bulk and shear modulus of the body
  double c0;                           // longitudinal sound speed of the body
  double A, B;                         // Monaghan artificial viscosity
  VelocityGradient velocity_gradient;  // jaumann only; the total-Lagrangian solid notes it
  ArtificialStressParameters artificial_stress;
  FractureParameters fracture;
  std::optional<BendingModeParameters> bending_mode;
  std::optional<sph::Vec2> tip_gauge;
  std::optional<double> broken_part_below_y;
  std::vector<sph::Shape> bodies;  // solid.body
  std::vector<sph::Shape> clamps;  // solid.clamp
  std::vector<SolidWall> walls;    // solid.walls grown by dx/2 (wall_contact.hpp)
  double hourglass_alpha;          // total_lagrangian: hourglass control (Ganzenmueller 2015)
  bool shell_damping = true;       // shell: Kelvin-Voigt damping of its strain rates
  // The water's walls when the case lists no solid.walls (unmet_walls.hpp).
  std::vector<UnmetWall> unmet_walls;
};

// Throws sph::ConfigError naming the file, field and reason for bad input.
SolidParameters read_solid_parameters(const sph::CaseFile& case_file);

// The case's model name, and the executable that runs it.
const char* model_name(SolidModel model);
const char* model_executable(SolidModel model);

// Throws sph::ConfigError naming the file and solid.model unless the case
// asks for `model`: each executable runs one model and refuses the other.
void require_model(const sph::CaseFile& case_file, const SolidParameters& parameters,
                   SolidModel model);

}  // namespace cosph::solid
