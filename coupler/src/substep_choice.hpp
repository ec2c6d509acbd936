// Which stepping a coupled run takes: coupling.max_substeps as set (1 or
// more), or, at 0, chosen by the added-mass ratio of a coupling window
// (docs/auto_substeps.md).
//
// In a multi-rate window the cross-phase forces are held: the solid moves for
// the whole window W under the force the water exerted at the window's start.
// On times short against L / c_f a weakly compressible fluid answers a wall's
// motion as an acoustic layer, p = rho_f c_f v: the water that responds
// within W is the layer a sound wave crosses in W, rho_f c_f W per unit of
// interface, not the incompressible rho_f L (van Brummelen 2009, J. Appl.
// Mech. 76:021206; the incompressible case: Causin, Gerbeau & Nobile 2005,
// CMAME 194:4506). A plate of mass rho_s e per unit of interface under that
// load, held over the window, moves as v_next = (1 - mu_W) v with
//     mu_W = rho_f c_f W / (rho_s e),
// the added-mass ratio of a window: the held force overshoots past
// mu_W = 1 and the plate's motion grows past mu_W = 2. Multi-rate coupling
// is taken where mu_W <= 1, a safety factor 2 on the growth bound; otherwise
// synchronised steps, whose window is the solid's own short step.
//
// W is bounded from the case alone: a window is never longer than the larger
// of the two solvers' proposals, each at most cfl h / c (sphcore/time_step.hpp),
// so W <= cfl max(h_f / c_f, h_s / c_s). The plan (cosph-case, which places
// the processes on cores) and the coupler both decide before any step.
#pragma once

#include <limits>
#include <string>

#include "sphcore/case_file.hpp"

namespace cosph::coupler {

// The largest added-mass ratio of a window that multi-rate coupling may take.
inline constexpr double kMaxWindowAddedMassRatio = 1.0;
// Sub-steps a window may hold when chosen automatically: the cap the elastic
// plate's multi-rate rows were validated with (scripts/validate_elastic_plate.py).
inline constexpr int kAutomaticMaxSubsteps = 32;

struct AddedMassInputs {
  double cfl;
  double fluid_density, fluid_sound_speed, fluid_smoothing_length;  // kg/m^3, m/s, m
  double solid_density, solid_sound_speed, solid_smoothing_length;  // kg/m^3, m/s, m
  double solid_thickness;  // m, e: the structure's extent along the interface normal
};

// mu_W for the longest window multi-rate coupling can take. Throws
// std::invalid_argument unless every input is positive and finite.
double window_added_mass_ratio(const AddedMassInputs& in);

struct SubstepChoice {
  int max_substeps;              // 1: synchronised; more: multi-rate (common_step.hpp)
  double added_mass_ratio = -1;  // mu_W when chosen automatically, else -1
  std::string reason;            // for the run's log: what was chosen and why
  // s, the held force's share of a solid mode's stiffness that the damping
  // bound takes (account_for_the_solids_damping): by the case's water,
  // coupling_stiffness_share.
  double coupling_stiffness_share = 1.0;
  // s, the longest multi-rate window the solid's damping allows
  // (account_for_the_solids_damping); infinite: no such bound.
  double max_window = std::numeric_limits<double>::infinity();
};

// The automatic choice from the added-mass ratio.
SubstepChoice choose_substeps(const AddedMassInputs& in);

// The case's coupling.max_substeps: >= 1 as set, 0 automatic (with the
// coupling share s of the case's water, for the damping bound). A case that
// does not give what the rule needs (no solid.body, a solid program's own
// fields) gets synchronised steps, the safe side, and the reason says so.
// Throws sph::ConfigError for a negative value.
SubstepChoice read_substep_choice(const sph::CaseFile& case_file);

// What the solid's Hello says about its own dissipation (coupling.proto).
struct SolidDamping {
  bool undamped_modes = false;                // modes it does not damp at all
  double fastest_mode_angular_frequency = 0;  // rad/s, omega; 0: not sent
  double fastest_mode_damping_ratio = 0;      // zeta, by the solid's own damping
};

// The coupling's share s of a mode's stiffness that the negative damping of
// a held force is taken at. For a water whose pair terms against the solid
// solve the acoustic Riemann problem (fluid.dissipation riemann) the share
// measured on the shell's fastest mode: the smallest bound the quiet long-
// window runs of docs/results/shell_window_waters.md set, rounded down (the
// delta-SPH waters pumped the same shell at the same windows). For any other
// water the whole (the coupling no stiffer than the mode itself), the safe
// side where nothing was measured.
inline constexpr double kRiemannCouplingStiffnessShare = 0.2;
inline constexpr double kCouplingStiffnessShare = 1.0;
// The window is kept at this fraction of the length where the mode's own
// damping only just outweighs the hold's: a safety factor 2, as the
// added-mass ratio takes on its growth bound.
inline constexpr double kDampingWindowMargin = 0.5;

// A held force lags the motion it answers by about half a window, W/2: for a
// mode of angular frequency omega and a coupling share s of its stiffness, a
// negative damping ratio s omega W / 4 (docs/auto_substeps.md). The mode's
// own damping ratio zeta outweighs it for W < 4 zeta / (s omega); with the
// margin, an automatic multi-rate choice keeps
//     W <= 2 zeta / (s omega),
// with s = choice.coupling_stiffness_share, the window bound it takes from
// the solid's Hello (max_window; the window is then no longer than that, nor
// shorter than the smaller proposal: common_step.hpp). A solid that reports
// modes it does not damp (zeta = 0) gets synchronised steps. An explicit max_substeps, a
// choice that is synchronised already and a solid that sends nothing are
// returned unchanged.
SubstepChoice account_for_the_solids_damping(const SubstepChoice& choice,
                                             const SolidDamping& damping,
                                             const std::string& solid_name);

// The thinnest of the case's solid.body regions, in m (0 without any): the
// plate's thickness e, the lightest mass per unit of interface. A region's
// thickness is the diameter of the largest circle inside it (sph::thickness),
// a box's its least side, a band's (without subtract) the thickness it gives.
double solid_thickness(const sph::CaseFile& case_file);

}  // namespace cosph::coupler
