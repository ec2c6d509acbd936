// The shell's part of a checkpoint (docs/restart.md): the line's state, every
// field derived from it that the next step reads before recomputing it, and
// the counters. The reference line (its stress points, arc lengths) is
// fixed for the run and built again from the case.
#include <stdexcept>

#include "shell_solver.hpp"

namespace cosph::solid::shell {

void ShellSolver::save(sph::Checkpoint& checkpoint) const {
  const ShellParticles& P = particles_;
  checkpoint.put("id", P.id);
  checkpoint.put("x", P.x);
  checkpoint.put("v", P.v);
  checkpoint.put("theta", P.theta);
  checkpoint.put("omega", P.omega);
  checkpoint.put("external_a", P.external_a);
  checkpoint.put("external_alpha", P.external_alpha);
  checkpoint.put("kick_a", P.kick_a);
  checkpoint.put("kick_alpha", P.kick_alpha);
  checkpoint.put("N", P.N);
  checkpoint.put("Q", P.Q);
  checkpoint.put("M", P.M);
  checkpoint.put("stress_dx_dS", P.stress.dx_dS);
  checkpoint.put("stress_kappa", P.stress.kappa);
  checkpoint.put("stress_N", P.stress.N);
  checkpoint.put("stress_Q", P.stress.Q);
  checkpoint.put("stress_M", P.stress.M);
  checkpoint.put("stress_n", P.stress.n);
  checkpoint.put("stress_couple", P.stress.couple);
  checkpoint.put("stress_strain_energy", P.stress.strain_energy);
  checkpoint.put("a", P.a);
  checkpoint.put("alpha", P.alpha);
  checkpoint.put_value("time", time_);
  checkpoint.put_count("steps", steps_);
}

void ShellSolver::restore(const sph::Checkpoint& checkpoint) {
  ShellParticles& P = particles_;
  std::vector<int> id;
  checkpoint.get("id", id);
  if (id != P.id)
    throw std::runtime_error(checkpoint.path() + ": the shell's particles are not the case's");
  checkpoint.get("x", P.x);
  checkpoint.get("v", P.v);
  checkpoint.get("theta", P.theta);
  checkpoint.get("omega", P.omega);
  checkpoint.get("external_a", P.external_a);
  checkpoint.get("external_alpha", P.external_alpha);
  checkpoint.get("kick_a", P.kick_a);
  checkpoint.get("kick_alpha", P.kick_alpha);
  checkpoint.get("N", P.N);
  checkpoint.get("Q", P.Q);
  checkpoint.get("M", P.M);
  checkpoint.get("stress_dx_dS", P.stress.dx_dS);
  checkpoint.get("stress_kappa", P.stress.kappa);
  checkpoint.get("stress_N", P.stress.N);
  checkpoint.get("stress_Q", P.stress.Q);
  checkpoint.get("stress_M", P.stress.M);
  checkpoint.get("stress_n", P.stress.n);
  checkpoint.get("stress_couple", P.stress.couple);
  checkpoint.get("stress_strain_energy", P.stress.strain_energy);
  checkpoint.get("a", P.a);
  checkpoint.get("alpha", P.alpha);
  time_ = checkpoint.value("time");
  steps_ = checkpoint.count("steps");
  if (P.x.size() != id.size() || P.alpha.size() != id.size())
    throw std::runtime_error(checkpoint.path() + ": the shell's arrays differ in length");
}

}  // namespace cosph::solid::shell
