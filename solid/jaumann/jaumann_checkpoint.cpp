// The Jaumann solid's part of a checkpoint (docs/restart.md): the particles'
// state (failed ones included), every field the next step reads before
// recomputing it, and the counters. The cell grid and the Verlet list are
// built again from the positions of the last sort, which are in the grid's
// order already, so they come out as they were and the continuation matches
// bit for bit.
#include <stdexcept>
#include <utility>
#include <vector>

#include "clamp_reach.hpp"
#include "jaumann_solver.hpp"

namespace cosph::solid::jaumann {

namespace {

// Every array the next step reads, once for both directions (Particles is
// const when saving).
template <class Particles, class Visit>
void visit_state(Particles& P, const Visit& visit) {
  visit("id", P.id);
  visit("x", P.x);
  visit("v", P.v);
  visit("x0", P.x0);
  visit("rho", P.rho);
  visit("m", P.m);
  visit("s", P.s);
  visit("K", P.K);
  visit("G", P.G);
  visit("c", P.c);
  visit("sigma_y", P.sigma_y);
  visit("clamped", P.clamped);
  visit("failed", P.failed);
  visit("external_a", P.external_a);
  visit("kick_a", P.kick_a);
  visit("p", P.p);
  visit("sigma", P.sigma);
  visit("R", P.R);
  visit("L", P.L);
  visit("sigma_L", P.sigma_L);
  visit("a", P.a);
  visit("drho", P.drho);
  visit("volume", P.volume);
  visit("inverse_rho", P.inverse_rho);
  visit("ds", P.ds);
}

}  // namespace

void JaumannSolver::save(sph::Checkpoint& checkpoint) const {
  visit_state(particles_, sph::CheckpointPut{checkpoint});
  checkpoint.put("x_at_sort", verlet_.x_at_sort());
  sph::put_clock(checkpoint, time_, steps_);
}

void JaumannSolver::restore(const sph::Checkpoint& checkpoint) {
  JaumannParticles& P = particles_;
  visit_state(P, sph::CheckpointGet{checkpoint});
  set_clamp_reach();  // the clamp's inert and out-of-reach particles, from x0
  std::vector<sph::Vec2> x_at_sort;
  checkpoint.get("x_at_sort", x_at_sort);
  sph::take_clock(checkpoint, time_, steps_);
  if (P.id.size() != P.size() || P.a.size() != P.size() || x_at_sort.size() != P.size())
    throw std::runtime_error(checkpoint.path() + ": the solid's arrays differ in length");
  P.neighbours.resize(P.size());
  // The filters of sort(): the same list as at the sort itself.
  if (!verlet_.restore(
          std::move(x_at_sort), [&P](long i) { return !P.inert[i]; }, candidate_filter()))
    throw std::runtime_error(checkpoint.path() +
                             ": the solid's positions at its last sort are not in cell order");
  P.reach_end = reach_end(P.out_of_reach);
}

}  // namespace cosph::solid::jaumann
