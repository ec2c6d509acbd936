// Builds the fluid solver's particles from a case: water at rest with a
// hydrostatic density profile, and the rigid walls around it.
#pragma once

#include "fluid_parameters.hpp"
#include "fluid_particles.hpp"
#include "sphcore/case_file.hpp"

namespace cosph::fluid {

// Throws sph::ConfigError if the water could flow out of the walls (and the
// solid, if the case has one) to the left, the right or the bottom, or if a wall
// or a solid body overlaps the water.
void check_walls_close(const sph::CaseFile& case_file, const FluidParameters& parameters);

FluidParticles build_fluid_scene(const sph::CaseFile& case_file, const FluidParameters& parameters);

}  // namespace cosph::fluid
