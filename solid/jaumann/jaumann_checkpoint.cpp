// The Jaumann solid's part of a checkpoint (docs/restart.md): the particles'
// state (failed ones included), every field the next step reads before
// recomputing it, and the counters. The cell grid and the Verlet list are
// built again from the positions of the last sort, which are in the grid's
// order already, so they come out as they were and the continuation matches
// bit for bit.
#include <numeric>
#include <stdexcept>

#include "jaumann_solver.hpp"
#include "sphcore/kernel.hpp"

namespace cosph::solid::jaumann {

void JaumannSolver::save(sph::Checkpoint& checkpoint) const {
  const JaumannParticles& P = particles_;
  checkpoint.put("id", P.id);
  checkpoint.put("x", P.x);
  checkpoint.put("v", P.v);
  checkpoint.put("x0", P.x0);
  checkpoint.put("rho", P.rho);
  checkpoint.put("m", P.m);
  checkpoint.put("s", P.s);
  checkpoint.put("K", P.K);
  checkpoint.put("G", P.G);
  checkpoint.put("c", P.c);
  checkpoint.put("sigma_y", P.sigma_y);
  checkpoint.put("clamped", P.clamped);
  checkpoint.put("failed", P.failed);
  checkpoint.put("inert", P.inert);
  checkpoint.put("external_a", P.external_a);
  checkpoint.put("p", P.p);
  checkpoint.put("sigma", P.sigma);
  checkpoint.put("R", P.R);
  checkpoint.put("L", P.L);
  checkpoint.put("sigma_L", P.sigma_L);
  checkpoint.put("a", P.a);
  checkpoint.put("drho", P.drho);
  checkpoint.put("volume", P.volume);
  checkpoint.put("inverse_rho", P.inverse_rho);
  checkpoint.put("ds", P.ds);
  checkpoint.put("x_at_sort", x_at_sort_);
  checkpoint.put_value("time", time_);
  checkpoint.put_count("steps", steps_);
}

void JaumannSolver::restore(const sph::Checkpoint& checkpoint) {
  JaumannParticles& P = particles_;
  checkpoint.get("id", P.id);
  checkpoint.get("x", P.x);
  checkpoint.get("v", P.v);
  checkpoint.get("x0", P.x0);
  checkpoint.get("rho", P.rho);
  checkpoint.get("m", P.m);
  checkpoint.get("s", P.s);
  checkpoint.get("K", P.K);
  checkpoint.get("G", P.G);
  checkpoint.get("c", P.c);
  checkpoint.get("sigma_y", P.sigma_y);
  checkpoint.get("clamped", P.clamped);
  checkpoint.get("failed", P.failed);
  checkpoint.get("inert", P.inert);
  checkpoint.get("external_a", P.external_a);
  checkpoint.get("p", P.p);
  checkpoint.get("sigma", P.sigma);
  checkpoint.get("R", P.R);
  checkpoint.get("L", P.L);
  checkpoint.get("sigma_L", P.sigma_L);
  checkpoint.get("a", P.a);
  checkpoint.get("drho", P.drho);
  checkpoint.get("volume", P.volume);
  checkpoint.get("inverse_rho", P.inverse_rho);
  checkpoint.get("ds", P.ds);
  checkpoint.get("x_at_sort", x_at_sort_);
  time_ = checkpoint.value("time");
  steps_ = checkpoint.count("steps");
  if (P.id.size() != P.size() || P.a.size() != P.size() || x_at_sort_.size() != P.size())
    throw std::runtime_error(checkpoint.path() + ": the solid's arrays differ in length");
  P.neighbours.resize(P.size());
  const double reach = sph::kernel::kSupport * parameters_.h + skin_;
  grid_.build(x_at_sort_, reach);
  std::vector<int> identity(P.size());
  std::iota(identity.begin(), identity.end(), 0);
  if (grid_.order() != identity)
    throw std::runtime_error(checkpoint.path() +
                             ": the solid's positions at its last sort are not in cell order");
  list_candidates(reach);
}

}  // namespace cosph::solid::jaumann
