// The total-Lagrangian solid's part of a checkpoint (docs/restart.md): the
// state, every field derived from it that the next step reads before
// recomputing it, and the counters. The reference configuration (neighbours,
// L0) is fixed for the run and built again from the case.
#include <stdexcept>

#include "tl_solver.hpp"

namespace cosph::solid::tl {

void TLSolver::save(sph::Checkpoint& checkpoint) const {
  const TLParticles& P = particles_;
  checkpoint.put("id", P.id);
  checkpoint.put("x", P.x);
  checkpoint.put("v", P.v);
  checkpoint.put("external_a", P.external_a);
  checkpoint.put("F", P.F);
  checkpoint.put("J", P.J);
  checkpoint.put("rho", P.rho);
  checkpoint.put("P_L0", P.P_L0);
  checkpoint.put("sigma", P.sigma);
  checkpoint.put("sigma_zz", P.sigma_zz);
  checkpoint.put("strain_energy", P.strain_energy);
  checkpoint.put("a", P.a);
  checkpoint.put_value("time", time_);
  checkpoint.put_count("steps", steps_);
}

void TLSolver::restore(const sph::Checkpoint& checkpoint) {
  TLParticles& P = particles_;
  std::vector<int> id;
  checkpoint.get("id", id);
  if (id != P.id)
    throw std::runtime_error(checkpoint.path() + ": the solid's particles are not the case's");
  checkpoint.get("x", P.x);
  checkpoint.get("v", P.v);
  checkpoint.get("external_a", P.external_a);
  checkpoint.get("F", P.F);
  checkpoint.get("J", P.J);
  checkpoint.get("rho", P.rho);
  checkpoint.get("P_L0", P.P_L0);
  checkpoint.get("sigma", P.sigma);
  checkpoint.get("sigma_zz", P.sigma_zz);
  checkpoint.get("strain_energy", P.strain_energy);
  checkpoint.get("a", P.a);
  time_ = checkpoint.value("time");
  steps_ = checkpoint.count("steps");
  if (P.x.size() != id.size() || P.a.size() != id.size())
    throw std::runtime_error(checkpoint.path() + ": the solid's arrays differ in length");
}

}  // namespace cosph::solid::tl
