// cosph-fluid: the weakly compressible SPH water solver. Runs a case alone when
// the case has no solid; coupled runs come through the coupler.
#include <omp.h>

#include <iostream>

#include "fluid_parameters.hpp"
#include "fluid_solver.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/solver_cli.hpp"
#include "sphcore/standalone_run.hpp"

namespace {

using cosph::fluid::FluidSolver;

int run_fluid(int argc, char** argv) {
  const sph::SolverArgs args = sph::parse_solver_args(
      argc, argv, "cosph-fluid", "Weakly compressible SPH water solver (SPEC.md \"Fluid\").");
  const sph::CaseFile case_file = sph::load_case(args.case_path, args.overrides);
  const auto parameters = cosph::fluid::read_fluid_parameters(case_file);
  if (case_file.config.has_solid() || !args.endpoint.empty())
    throw sph::ConfigError(args.case_path +
                           ": solid: this case is coupled; coupled runs are not built yet");
  sph::make_output_dir(args.out_dir);
  sph::install_stop_handlers();

  FluidSolver solver(case_file, parameters);
  omp_set_num_threads(sph::choose_threads(parameters.run.threads, solver.particles().size()));
  std::cout << "cosph-fluid: " << solver.gauges().water_particles << " water and "
            << solver.particles().size() - solver.gauges().water_particles
            << " wall particles, dx = " << parameters.dx << " m, h = " << parameters.h
            << " m, c0 = " << parameters.c0 << " m/s, " << omp_get_max_threads() << " threads"
            << std::endl;
  sph::StandaloneRun<FluidSolver> run(solver, parameters.run, args.out_dir, "fluid",
                                      {{"front", "m"},
                                       {"height", "m"},
                                       {"kinetic_energy", "J/m"},
                                       {"max_speed", "m/s"},
                                       {"water_particles", "1"}},
                                      [](const FluidSolver& s) {
                                        const auto g = s.gauges();
                                        return std::vector<double>{
                                            g.front, g.height, g.kinetic_energy, g.max_speed,
                                            static_cast<double>(g.water_particles)};
                                      });
  return run.run();
}

}  // namespace

int main(int argc, char** argv) {
  return sph::run_guarded("cosph-fluid", [&] { return run_fluid(argc, argv); });
}
