// The total-Lagrangian solid's part of a checkpoint (docs/restart.md): the
// state, every field derived from it that the next step reads before
// recomputing it, and the counters. The reference configuration (neighbours,
// L0) is fixed for the run and built again from the case.
#include <stdexcept>

#include "tl_solver.hpp"

namespace cosph::solid::tl {

namespace {

// Every array the next step reads, once for both directions (Particles is
// const when saving).
template <class Particles, class Visit>
void visit_state(Particles& P, const Visit& visit) {
  visit("x", P.x);
  visit("v", P.v);
  visit("external_a", P.external_a);
  visit("kick_a", P.kick_a);
  visit("F", P.F);
  visit("J", P.J);
  visit("rho", P.rho);
  visit("P_L0", P.P_L0);
  visit("sigma", P.sigma);
  visit("sigma_zz", P.sigma_zz);
  visit("strain_energy", P.strain_energy);
  visit("a", P.a);
}

}  // namespace

void TLSolver::save(sph::Checkpoint& checkpoint) const {
  checkpoint.put("id", particles_.id);
  visit_state(particles_, sph::CheckpointPut{checkpoint});
  sph::put_clock(checkpoint, time_, steps_);
}

void TLSolver::restore(const sph::Checkpoint& checkpoint) {
  TLParticles& P = particles_;
  std::vector<int> id;
  checkpoint.get("id", id);
  if (id != P.id)
    throw std::runtime_error(checkpoint.path() + ": the solid's particles are not the case's");
  visit_state(P, sph::CheckpointGet{checkpoint});
  sph::take_clock(checkpoint, time_, steps_);
  if (P.x.size() != id.size() || P.a.size() != id.size())
    throw std::runtime_error(checkpoint.path() + ": the solid's arrays differ in length");
}

}  // namespace cosph::solid::tl
