// How many particles a case would make, estimated before any is made, and the
// limit a case must stay under (run.max_particles): a spacing typed a hundred
// times too small must be refused, not allocated until the machine runs out.
#pragma once

#include <cstdint>

#include "sphcore/case_file.hpp"

namespace sph {

// The default of run.max_particles: 15 GB at kBytesPerParticle, within a
// workstation's memory; the largest case shipped, finest spacing, has some
// 10^5 particles.
inline constexpr double kDefaultMaxParticles = 5e6;

// Memory of one particle in a solver, all its arrays, neighbour list, cell
// grid, snapshot copy and the in-memory image of a checkpoint: cosph-fluid's
// peak resident size grew by 2.81 KiB a particle from the dam break at 1 mm
// spacing (50 402 particles, 144 MiB) to 0.5 mm (183 794, 511 MiB); rounded up.
inline constexpr double kBytesPerParticle = 3072.0;

struct ParticleEstimate {
  double particles;  // an upper bound: each region's bounding box / spacing^2
  double bytes;      // particles * kBytesPerParticle
};

// The estimate for every region that holds particles (fluid.water,
// fluid.walls, fluid.moving_walls[].region, solid.body), each at its phase's
// spacing; a phase whose spacing is not positive is left to its own check.
ParticleEstimate estimate_particles(const CaseFile& case_file);

// Throws ConfigError naming run.max_particles, the estimate and how to raise
// the limit when the estimate passes it, or naming the estimated memory when
// that passes the machine's physical memory.
void check_particle_budget(const CaseFile& case_file);

}  // namespace sph
