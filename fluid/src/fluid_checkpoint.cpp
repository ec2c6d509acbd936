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

void FluidSolver::save(sph::Checkpoint& checkpoint) const {
  const FluidParticles& P = particles_;
  checkpoint.put("id", P.id);
  std::vector<std::uint8_t> kind(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) kind[i] = static_cast<std::uint8_t>(P.kind[i]);
  checkpoint.put("kind", kind);
  checkpoint.put("x", P.x);
  checkpoint.put("v", P.v);
  checkpoint.put("rho", P.rho);
  checkpoint.put("m", P.m);
  checkpoint.put("grad_rho", P.grad_rho);
  checkpoint.put("external_a", P.external_a);
  checkpoint.put("p", P.p);
  checkpoint.put("tau", P.tau);
  checkpoint.put("inverse_rho", P.inverse_rho);
  checkpoint.put("grad_rho_next", P.grad_rho_next);
  checkpoint.put("volume", P.volume);
  checkpoint.put("a", P.a);
  checkpoint.put("drho", P.drho);
  checkpoint.put("external_drho", P.external_drho);
  checkpoint.put("spray", P.spray);
  checkpoint.put("shift", P.shift);
  checkpoint.put("x_drawn", P.x_drawn);
  checkpoint.put("wall_a", P.wall_a);
  checkpoint.put("x_at_sort", verlet_.x_at_sort());
  checkpoint.put("walls_in_reach", walls_in_reach_);
  checkpoint.put_count("sorts", sorts_);
  checkpoint.put_flag("spray_left", spray_left_);
  checkpoint.put_count("spray_removed", spray_removed_);
  checkpoint.put("wall_forces_before_removal", wall_forces_before_removal_);
  checkpoint.put_value("time", time_);
  checkpoint.put_count("steps", steps_);
}

void FluidSolver::restore(const sph::Checkpoint& checkpoint) {
  FluidParticles& P = particles_;
  checkpoint.get("id", P.id);
  std::vector<std::uint8_t> kind;
  checkpoint.get("kind", kind);
  P.kind.resize(kind.size());
  for (std::size_t i = 0; i < kind.size(); ++i) P.kind[i] = static_cast<Kind>(kind[i]);
  checkpoint.get("x", P.x);
  checkpoint.get("v", P.v);
  checkpoint.get("rho", P.rho);
  checkpoint.get("m", P.m);
  checkpoint.get("grad_rho", P.grad_rho);
  checkpoint.get("external_a", P.external_a);
  checkpoint.get("p", P.p);
  checkpoint.get("tau", P.tau);
  checkpoint.get("inverse_rho", P.inverse_rho);
  checkpoint.get("grad_rho_next", P.grad_rho_next);
  checkpoint.get("volume", P.volume);
  checkpoint.get("a", P.a);
  checkpoint.get("drho", P.drho);
  checkpoint.get("external_drho", P.external_drho);
  checkpoint.get("spray", P.spray);
  checkpoint.get("shift", P.shift);
  checkpoint.get("x_drawn", P.x_drawn);
  checkpoint.get("wall_a", P.wall_a);
  P.sigma.resize(P.size());  // from p and tau, before the momentum pass reads it
  std::vector<sph::Vec2> x_at_sort;
  checkpoint.get("x_at_sort", x_at_sort);
  checkpoint.get("walls_in_reach", walls_in_reach_);
  sorts_ = checkpoint.count("sorts");
  spray_left_ = checkpoint.flag("spray_left");
  spray_removed_ = checkpoint.count("spray_removed");
  checkpoint.get("wall_forces_before_removal", wall_forces_before_removal_);
  time_ = checkpoint.value("time");
  steps_ = checkpoint.count("steps");
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
