// Whether the moving wall's pressure takes the solid's acceleration:
// coupling.wall_acceleration as set, or, unset, chosen by the feedback ratio
// of the term (docs/physics.md, "Moving wall").
//
// Adami's extrapolation gives a solid particle the wall pressure
// P_w = sum(P_f + rho_f (g - a_w) . r_wf) W / sum W, and the coupler takes a_w
// from the solid's last closing kick: the term is explicit in the solid's
// acceleration. Accelerating into the water by a, the plate raises its wall
// pressure by about rho_f l a, with l the kernel-weighted distance from its
// particles to the water they extrapolate from; that pressure, on a plate of
// mass rho_s e per unit of interface, gives its next acceleration a part
//     -mu_a a,   mu_a = rho_f l / (rho_s e),
// the lagged added mass over the plate's own. The iteration grows, swinging
// sign each exchange, for mu_a > 1 (the explicit coupling's added-mass
// instability, Causin, Gerbeau & Nobile 2005, CMAME 194:4506). The term is
// taken where mu_a <= 1 with l = h_f, the water's smoothing length: the
// coupled elastic plate with the term loses stability between
// rho_s = 550 and 275 kg/m^3 (e = 5 mm, h_f = 3 mm), that is at l between
// 0.46 h_f and 0.92 h_f, so h_f is a bound above what was measured.
#pragma once

#include <string>

#include "sphcore/case_file.hpp"

namespace cosph::coupler {

// The largest feedback ratio at which the term is taken when unset.
inline constexpr double kMaxAccelerationFeedbackRatio = 1.0;

struct WallAccelerationChoice {
  bool take = true;
  double feedback_ratio = -1.0;  // mu_a when chosen automatically, else -1
  std::string reason;            // for the run's log: what was chosen and why
};

// mu_a = rho_f h_f / (rho_s e). Throws std::invalid_argument unless every
// input is positive and finite.
double acceleration_feedback_ratio(double fluid_density, double fluid_smoothing_length,
                                   double solid_density, double solid_thickness);

// The case's coupling.wall_acceleration: as set, or, unset, taken where
// mu_a <= kMaxAccelerationFeedbackRatio. A case that does not give what mu_a
// needs (no solid.body, a solid program's own fields) leaves the term out,
// the side that is stable at any mass (a wall at rest's pressure), and the
// reason says so. The stress sum has no wall pressure: false.
WallAccelerationChoice read_wall_acceleration_choice(const sph::CaseFile& case_file);

}  // namespace cosph::coupler
