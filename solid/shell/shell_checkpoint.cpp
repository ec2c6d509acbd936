// The shell's part of a checkpoint (docs/restart.md): the line's state, every
// field derived from it that the next step reads before recomputing it, and
// the counters. The reference line (neighbours, arc lengths) is fixed for the
// run and built again from the case.
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
  checkpoint.put("dx_dS", P.dx_dS);
  checkpoint.put("kappa", P.kappa);
  checkpoint.put("N", P.N);
  checkpoint.put("Q", P.Q);
  checkpoint.put("M", P.M);
  checkpoint.put("strain_energy", P.strain_energy);
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
  checkpoint.get("dx_dS", P.dx_dS);
  checkpoint.get("kappa", P.kappa);
  checkpoint.get("N", P.N);
  checkpoint.get("Q", P.Q);
  checkpoint.get("M", P.M);
  checkpoint.get("strain_energy", P.strain_energy);
  checkpoint.get("a", P.a);
  checkpoint.get("alpha", P.alpha);
  time_ = checkpoint.value("time");
  steps_ = checkpoint.count("steps");
  if (P.x.size() != id.size() || P.alpha.size() != id.size())
    throw std::runtime_error(checkpoint.path() + ": the shell's arrays differ in length");
}

}  // namespace cosph::solid::shell
