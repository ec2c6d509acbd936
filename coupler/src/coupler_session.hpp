// The coupler process's work: bind one endpoint, greet the fluid and the
// solid, then, step after step, take both interfaces, fix the common step,
// compute the cross-phase forces and answer each side with its share.
#pragma once

#include <string>

#include "cross_phase_forces.hpp"
#include "participant/curve_keys.hpp"
#include "sphcore/checkpoint.hpp"
#include "sphcore/run_parameters.hpp"
#include "substep_choice.hpp"
#include "wall_acceleration_choice.hpp"

namespace cosph::coupler {

struct CouplerSettings {
  std::string endpoint;
  coupling::CurveKeyFiles keys;  // none: no CURVE (ipc:// only)
  std::string out_dir;
  sph::RunParameters run;
  CrossPhaseParameters cross_phase;
  // Which stepping and why (substep_choice.hpp): from the case, then, for an
  // automatic multi-rate choice, from the solid's Hello
  // (account_for_the_solids_damping).
  SubstepChoice stepping{1, -1.0, "", 1.0};
  // Whether the moving wall's pressure takes the solid's acceleration, and
  // why (wall_acceleration_choice.hpp); cross_phase.wall_acceleration is its
  // take.
  WallAccelerationChoice wall_acceleration;
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
