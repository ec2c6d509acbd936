// Must not compile: a solver with every member a coupled run needs except
// gauge_values. CoupledRun's concept (participant/coupled_solver.hpp) refuses
// it, and the test coupled_solver_contract (CMakeLists.txt) checks that the
// compiler's message names the missing member.
#include <vector>

#include "participant/coupled_run.hpp"

namespace {

struct SolverWithoutGauges {
  void begin_step(double) {}
  void end_step(double) {}
  sph::StepLimits step_limits() const { return {1.0, 1.0, 1.0}; }
  void collect_interface(const sph::Region&, sph::InterfaceParticles&) {}
  void set_interface_accelerations(const std::vector<sph::Vec2>&) {}
  sph::Region interaction_bounds() const { return {}; }
  double max_smoothing_length() const { return 1.0; }
  double time() const { return 0.0; }
  long steps() const { return 0; }
  sph::Snapshot snapshot() const { return sph::Snapshot(std::vector<sph::Vec2>{}); }
  std::vector<sph::Vec2> particles() const { return {}; }
};

}  // namespace

template class cosph::coupling::CoupledRun<SolverWithoutGauges>;
