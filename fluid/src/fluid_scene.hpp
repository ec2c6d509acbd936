// Builds the fluid solver's particles from a case: water at rest with a
// hydrostatic density profile, and the rigid walls around it.
#pragma once

#include "fluid_parameters.hpp"
#include "fluid_particles.hpp"
#include "sphcore/case_file.hpp"
#include "walls_close.hpp"

namespace cosph::fluid {

// Refuses the case first if the walls do not hold the water (walls_close.hpp).
FluidParticles build_fluid_scene(const sph::CaseFile& case_file, const FluidParameters& parameters);

}  // namespace cosph::fluid
