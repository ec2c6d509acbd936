#include "sphcore/particle_budget.hpp"

#include <unistd.h>

#include <string>

#include "sphcore/region_reader.hpp"

namespace sph {
namespace {

// Particles on the square lattice of `spacing` within the regions' bounding
// boxes: at least as many as the fill makes (holes and a wall's depth limit
// only remove some).
double lattice_count(const std::vector<Shape>& regions, double spacing) {
  double count = 0.0;
  for (const Shape& region : regions) {
    const Bounds b = region.bounds();
    count += ((b.max.x() - b.min.x()) / spacing + 1.0) * ((b.max.y() - b.min.y()) / spacing + 1.0);
  }
  return count;
}

double physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

std::string gigabytes(double bytes) {
  return format_number(bytes / 1e9) + " GB";
}

}  // namespace

ParticleEstimate estimate_particles(const CaseFile& case_file) {
  double particles = 0.0;
  const auto& fluid = case_file.config.fluid();
  if (case_file.config.has_fluid() && fluid.spacing() > 0.0) {
    particles +=
        lattice_count(read_regions(fluid.water(), case_file, "fluid.water"), fluid.spacing());
    particles +=
        lattice_count(read_regions(fluid.walls(), case_file, "fluid.walls"), fluid.spacing());
    for (int k = 0; k < fluid.moving_walls_size(); ++k)
      particles +=
          lattice_count({read_region(fluid.moving_walls(k).region(), case_file,
                                     "fluid.moving_walls[" + std::to_string(k) + "].region")},
                        fluid.spacing());
  }
  const auto& solid = case_file.config.solid();
  if (case_file.config.has_solid() && solid.spacing() > 0.0)
    particles +=
        lattice_count(read_regions(solid.body(), case_file, "solid.body"), solid.spacing());
  return {particles, particles * kBytesPerParticle};
}

void check_particle_budget(const CaseFile& case_file) {
  const double set = case_file.config.run().max_particles();
  require(set >= 0.0, case_file, "run.max_particles",
          "must not be negative (0: the default " + format_number(kDefaultMaxParticles) + ")");
  const double limit = set > 0.0 ? set : kDefaultMaxParticles;
  const ParticleEstimate estimate = estimate_particles(case_file);
  const std::string about = "the scene would make up to " + format_number(estimate.particles) +
                            " particles (about " + gigabytes(estimate.bytes) + ")";
  require(estimate.particles <= limit, case_file, "run.max_particles",
          about + ", more than the limit " + format_number(limit) +
              ": check the spacing, or raise the limit with --set run.max_particles=N");
  const double memory = physical_memory_bytes();
  require(memory <= 0.0 || estimate.bytes <= memory, case_file, "run.max_particles",
          about + ", more than this machine's memory (" + gigabytes(memory) +
              "): use a coarser spacing");
}

}  // namespace sph
