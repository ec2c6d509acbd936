// cosph-solid: the SPH linear elastic solid solver (Gray, Monaghan & Swift
// 2001). Runs a case alone when the case has no fluid; coupled runs come
// through the coupler.
#include <omp.h>

#include <iostream>

#include "solid_parameters.hpp"
#include "solid_solver.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/solver_cli.hpp"
#include "sphcore/standalone_run.hpp"

namespace {

using cosph::solid::SolidSolver;

int run_solid(int argc, char** argv) {
  const sph::SolverArgs args = sph::parse_solver_args(
      argc, argv, "cosph-solid", "SPH linear elastic solid solver (SPEC.md \"Solid\").");
  const sph::CaseFile case_file = sph::load_case(args.case_path, args.overrides);
  const auto parameters = cosph::solid::read_solid_parameters(case_file);
  if (case_file.config.has_fluid() || !args.endpoint.empty())
    throw sph::ConfigError(args.case_path +
                           ": fluid: this case is coupled; coupled runs are not built yet");
  if (parameters.run.threads > 0) omp_set_num_threads(parameters.run.threads);
  sph::make_output_dir(args.out_dir);
  sph::install_stop_handlers();

  SolidSolver solver(case_file, parameters);
  long clamped = 0;
  for (auto c : solver.particles().clamped) clamped += c;
  std::cout << "cosph-solid: " << solver.particles().size() << " solid particles (" << clamped
            << " clamped), dx = " << parameters.dx << " m, h = " << parameters.h
            << " m, c = " << parameters.c0 << " m/s, artificial stress "
            << (parameters.artificial_stress.enabled ? "on" : "off") << ", "
            << omp_get_max_threads() << " threads" << std::endl;
  sph::StandaloneRun<SolidSolver> run(solver, parameters.run, args.out_dir, "solid",
                                      {{"tip_dx", "m"},
                                       {"tip_dy", "m"},
                                       {"kinetic_energy", "J/m"},
                                       {"elastic_energy", "J/m"},
                                       {"max_speed", "m/s"},
                                       {"max_von_mises", "Pa"},
                                       {"failed", "1"}},
                                      [](const SolidSolver& s) {
                                        const auto g = s.gauges();
                                        return std::vector<double>{g.tip_dx,
                                                                   g.tip_dy,
                                                                   g.kinetic_energy,
                                                                   g.elastic_energy,
                                                                   g.max_speed,
                                                                   g.max_von_mises,
                                                                   static_cast<double>(g.failed)};
                                      });
  return run.run();
}

}  // namespace

int main(int argc, char** argv) {
  return sph::run_guarded("cosph-solid", [&] { return run_solid(argc, argv); });
}
