// Whether the walls hold the water, checked before anything runs.
#pragma once

#include "fluid_parameters.hpp"
#include "sphcore/case_file.hpp"

namespace cosph::fluid {

// Throws sph::ConfigError if a wall or a solid body overlaps the water, or if
// the water could flow out of the walls (and the solid, if the case has one):
// to the left, the right or through the bottom.
void check_walls_close(const sph::CaseFile& case_file, const FluidParameters& parameters);

}  // namespace cosph::fluid
