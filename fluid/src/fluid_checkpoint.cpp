// The fluid solver's part of a checkpoint (docs/restart.md): the particles'
// state and every field the next step reads before recomputing it, the
// counters, and the Verlet list's state. The cell grid and the Verlet list
// are not stored: built again from the positions of the last sort, which are
// in the grid's order already, they come out as they were, and the next
// step's pairs with them, so the continuation matches bit for bit.
#include <stdexcept>
#include <utility>
#include <vector>

#include "fluid_solver.hpp"

namespace cosph::fluid {

namespace {

// Every array the next step reads, once for both directions (Particles is
// const when saving); the kinds are stored as bytes apart.
template <class Particles, class Visit>
void visit_state(Particles& P, const Visit& visit) {
  visit("id", P.id);
  visit("x", P.x);
  visit("v", P.v);
  visit("rho", P.rho);
  visit("m", P.m);
  visit("grad_rho", P.grad_rho);
  visit("external_a", P.external_a);
  visit("p", P.p);
  visit("tau", P.tau);
  visit("inverse_rho", P.inverse_rho);
  visit("grad_rho_next", P.grad_rho_next);
  visit("volume", P.volume);
  visit("a", P.a);
  visit("drho", P.drho);
  visit("external_drho", P.external_drho);
  visit("spray", P.spray);
  visit("shift", P.shift);
  visit("x_drawn", P.x_drawn);
  visit("wall_a", P.wall_a);
}

}  // namespace

void FluidSolver::save(sph::Checkpoint& checkpoint) const {
  const FluidParticles& P = particles_;
  std::vector<std::uint8_t> kind(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) kind[i] = static_cast<std::uint8_t>(P.kind[i]);
  checkpoint.put("kind", kind);
  visit_state(P, sph::CheckpointPut{checkpoint});
  checkpoint.put("x_at_sort", verlet_.x_at_sort());
  checkpoint.put("walls_in_reach", walls_in_reach_);
  checkpoint.put_count("sorts", sorts_);
  checkpoint.put_flag("spray_left", spray_left_);
  checkpoint.put_count("spray_removed", spray_removed_);
  checkpoint.put("wall_forces_before_removal", wall_forces_before_removal_);
  sph::put_clock(checkpoint, time_, steps_);
}

void FluidSolver::restore(const sph::Checkpoint& checkpoint) {
  FluidParticles& P = particles_;
  std::vector<std::uint8_t> kind;
  checkpoint.get("kind", kind);
  P.kind.resize(kind.size());
  for (std::size_t i = 0; i < kind.size(); ++i) P.kind[i] = static_cast<Kind>(kind[i]);
  visit_state(P, sph::CheckpointGet{checkpoint});
  P.sigma.resize(P.size());  // from p and tau, before the momentum pass reads it
  std::vector<sph::Vec2> x_at_sort;
  checkpoint.get("x_at_sort", x_at_sort);
  checkpoint.get("walls_in_reach", walls_in_reach_);
  sorts_ = checkpoint.count("sorts");
  spray_left_ = checkpoint.flag("spray_left");
  spray_removed_ = checkpoint.count("spray_removed");
  checkpoint.get("wall_forces_before_removal", wall_forces_before_removal_);
  sph::take_clock(checkpoint, time_, steps_);
  if (P.v.size() != P.size() || P.a.size() != P.size() || x_at_sort.size() != P.size())
    throw std::runtime_error(checkpoint.path() + ": the fluid's arrays differ in length");
  interface_index_.clear();
  // Spray left since the last sort: the next step sorts again, and nothing
  // reads the grid or the lists before it does.
  if (spray_left_) return;
  if (!verlet_.restore(std::move(x_at_sort), [&P](long i) { return P.is_water(i); }))
    throw std::runtime_error(checkpoint.path() +
                             ": the fluid's positions at its last sort are not in cell order");
  pairs_.build(verlet_.candidates(), P.x, parameters_.h, parameters_.kernel);
}

}  // namespace cosph::fluid
