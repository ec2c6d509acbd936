// Builds the solid solver's particles from a case: the body on a square
// lattice at its reference density, the clamp, weakened regions, and the
// initial velocity (at rest, or a cantilever's first bending mode).
#pragma once

#include "solid_parameters.hpp"
#include "solid_particles.hpp"
#include "sphcore/case_file.hpp"

namespace cosph::solid {

SolidParticles build_solid_scene(const sph::CaseFile& case_file, const SolidParameters& parameters);

}  // namespace cosph::solid
