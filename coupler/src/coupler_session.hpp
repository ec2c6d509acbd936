// The coupler process's work: bind one endpoint, greet the fluid and the
// solid, then, step after step, take both interfaces, fix the common step,
// compute the cross-phase forces and answer each side with its share.
#pragma once

#include <limits>
#include <string>

#include "cross_phase_forces.hpp"
#include "participant/curve_keys.hpp"
#include "sphcore/checkpoint.hpp"
#include "sphcore/run_parameters.hpp"

namespace cosph::coupler {

struct CouplerSettings {
  std::string endpoint;
  coupling::CurveKeyFiles keys;  // none: no CURVE (ipc:// only)
  std::string out_dir;
  sph::RunParameters run;
  CrossPhaseParameters cross_phase;
  int max_substeps = 1;         // 1: synchronised steps; more: multi-rate (common_step.hpp)
  std::string stepping_reason;  // for the run's log: which stepping and why
  // mu_W when the stepping was chosen automatically (substep_choice.hpp), else
  // -1: the solid's Hello can still make an automatic multi-rate choice
  // synchronised or bound its windows (account_for_the_solids_damping).
  double added_mass_ratio = -1.0;
  double coupling_stiffness_share = 1.0;  // s of the damping bound, by the water
  // s, the longest multi-rate window the solid's damping allows
  // (account_for_the_solids_damping), set from its Hello; infinite: no bound.
  double max_window = std::numeric_limits<double>::infinity();
  // coupling.solid_step = "fluid": the fluid's step, taken whole by the solid
  // too (a stability test that must end in an error).
  bool solid_at_fluid_step = false;
  double timeout_seconds;
  sph::CheckpointSettings checkpoints;  // docs/restart.md
};

// Returns the exit code; throws cosph::coupling::CouplingError when a peer
// fails, vanishes or misbehaves (after telling the other peer).
int run_coupler(const CouplerSettings& settings);

}  // namespace cosph::coupler
