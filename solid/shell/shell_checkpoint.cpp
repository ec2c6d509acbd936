// The shell's part of a checkpoint (docs/restart.md): the line's state, every
// field derived from it that the next step reads before recomputing it, and
// the counters. The reference line (its stress points, arc lengths) is
// fixed for the run and built again from the case.
#include <stdexcept>

#include "shell_solver.hpp"

namespace cosph::solid::shell {

namespace {

// Every array the next step reads, once for both directions (Particles is
// const when saving).
template <class Particles, class Visit>
void visit_state(Particles& P, const Visit& visit) {
  visit("x", P.x);
  visit("v", P.v);
  visit("theta", P.theta);
  visit("omega", P.omega);
  visit("external_a", P.external_a);
  visit("external_alpha", P.external_alpha);
  visit("kick_a", P.kick_a);
  visit("kick_alpha", P.kick_alpha);
  visit("N", P.N);
  visit("Q", P.Q);
  visit("M", P.M);
  visit("stress_dx_dS", P.stress.dx_dS);
  visit("stress_kappa", P.stress.kappa);
  visit("stress_N", P.stress.N);
  visit("stress_Q", P.stress.Q);
  visit("stress_M", P.stress.M);
  visit("stress_n", P.stress.n);
  visit("stress_couple", P.stress.couple);
  visit("stress_strain_energy", P.stress.strain_energy);
  visit("a", P.a);
  visit("alpha", P.alpha);
}

}  // namespace

void ShellSolver::save(sph::Checkpoint& checkpoint) const {
  checkpoint.put("id", particles_.id);
  visit_state(particles_, sph::CheckpointPut{checkpoint});
  sph::put_clock(checkpoint, time_, steps_);
}

void ShellSolver::restore(const sph::Checkpoint& checkpoint) {
  ShellParticles& P = particles_;
  std::vector<int> id;
  checkpoint.get("id", id);
  if (id != P.id)
    throw std::runtime_error(checkpoint.path() + ": the shell's particles are not the case's");
  visit_state(P, sph::CheckpointGet{checkpoint});
  sph::take_clock(checkpoint, time_, steps_);
  if (P.x.size() != id.size() || P.alpha.size() != id.size())
    throw std::runtime_error(checkpoint.path() + ": the shell's arrays differ in length");
}

}  // namespace cosph::solid::shell
