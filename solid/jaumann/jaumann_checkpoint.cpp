// The Jaumann solid's part of a checkpoint (docs/restart.md): the particles'
// state (failed ones included), every field the next step reads before
// recomputing it, and the counters. The cell grid and the Verlet list are
// built again from the positions of the last sort, which are in the grid's
// order already, so they come out as they were and the continuation matches
// bit for bit.
#include <stdexcept>
#include <utility>
#include <vector>

#include "jaumann_solver.hpp"

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
  checkpoint.put("x_at_sort", verlet_.x_at_sort());
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
  std::vector<sph::Vec2> x_at_sort;
  checkpoint.get("x_at_sort", x_at_sort);
  time_ = checkpoint.value("time");
  steps_ = checkpoint.count("steps");
  if (P.id.size() != P.size() || P.a.size() != P.size() || x_at_sort.size() != P.size())
    throw std::runtime_error(checkpoint.path() + ": the solid's arrays differ in length");
  P.neighbours.resize(P.size());
  // The filters of sort(): the same list as at the sort itself.
  const bool whole = parameters_.velocity_gradient == VelocityGradient::quadratic;
  if (!verlet_.restore(
          std::move(x_at_sort), [&P](long i) { return !P.inert[i]; },
          [&P, whole](long i, int j) { return whole || j > i || P.inert[j]; }))
    throw std::runtime_error(checkpoint.path() +
                             ": the solid's positions at its last sort are not in cell order");
}

}  // namespace cosph::solid::jaumann
