// Building fluid particle sets by hand for the tests of the neighbour passes,
// without a case file: the particles sorted into the grid's order and their
// neighbour list built, as FluidSolver does each step.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fluid_parameters.hpp"
#include "fluid_particles.hpp"
#include "sphcore/cell_grid.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/neighbour_list.hpp"
#include "sphcore/permutation.hpp"

namespace cosph::fluid::testing {

// Parameters of water at spacing dx, without gravity unless given: delta-SPH
// with the cubic spline at h = 1.3 dx and the walls' friction, the water these
// tests were written for, spelled out rather than taken from the defaults.
inline FluidParameters water_parameters(double dx, const Vec2& gravity = Vec2::Zero()) {
  FluidParameters p{};
  p.run = sph::RunParameters{1.0, 0.01, 0.1, 0.25, gravity, 0};
  p.dx = dx;
  p.h = 1.3 * dx;
  p.rho0 = 1000.0;
  p.mu = 1.307e-3;
  p.c0 = 20.0;
  p.delta = 0.1;
  p.A = 0.02;
  p.B = 0.1;
  p.dissipation = Dissipation::delta_sph;
  p.kernel = sph::kernel::Shape::cubic_spline;
  p.wall_friction = WallFriction::dissipation;
  p.left_wall_x = 0.0;
  p.floor_y = 0.0;
  return p;
}

struct Neighbourhood {
  sph::CellGrid grid;
  sph::CandidateList candidates;  // within 2h: a Verlet list without a skin
  sph::NeighbourList pairs;
};

// Sorts the particles' state into the grid's order, sizes the derived fields
// (zeroing grad_rho: set it afterwards if a test needs it) and lists the pairs.
inline void sort_and_find_neighbours(FluidParticles& P, const FluidParameters& p,
                                     Neighbourhood& n) {
  n.grid.build(P.x, sph::kernel::kSupport * p.h);
  sph::permute(n.grid.order(), P.id, P.kind, P.x, P.v, P.rho, P.m);
  P.resize_derived();
  n.candidates.build(n.grid, P.x, sph::kernel::kSupport * p.h,
                     [&P](long i) { return P.is_water(i); });
  n.pairs.build(n.candidates, P.x, p.h);
}

struct Run {
  int exit_code;    // -1 if it did not exit normally
  std::string err;  // stderr
};

// Runs build/bin/cosph-fluid --case CASE --out OUT_DIR [--set ARG ...], stdout
// and stderr kept in OUT_DIR's sibling files.
inline Run run_cosph_fluid(const std::string& case_path, const std::string& out_dir,
                           const std::vector<std::string>& overrides = {}) {
  auto quoted = [](const std::string& s) { return "'" + s + "'"; };
  std::string command = quoted(std::string(COSPH_BIN_DIR) + "/cosph-fluid") + " --case " +
                        quoted(case_path) + " --out " + quoted(out_dir);
  for (const std::string& o : overrides) command += " --set " + quoted(o);
  const std::string err_path = out_dir + ".stderr";
  command += " > " + quoted(out_dir + ".stdout") + " 2> " + quoted(err_path);
  const int status = std::system(command.c_str());
  Run run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, ""};
  std::ifstream err(err_path);
  run.err.assign(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>());
  return run;
}

}  // namespace cosph::fluid::testing
