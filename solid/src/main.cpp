// cosph-solid: the SPH linear elastic solid solver (Gray, Monaghan & Swift
// 2001). Runs a case alone when the case has no fluid; coupled runs come
// through the coupler.
#include <omp.h>

#include <iostream>

#include "solid_parameters.hpp"
#include "solid_solver.hpp"
#include "participant/coupled_run.hpp"
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
  const bool coupled = !args.endpoint.empty();
  sph::require(coupled || !case_file.config.has_fluid(), case_file, "fluid",
               "this case is coupled: run it with coupler/cosph, which starts the coupler");
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
  if (coupled) {
    const double timeout = case_file.config.coupling().timeout() > 0.0
                               ? case_file.config.coupling().timeout()
                               : 10.0;
    cosph::coupling::CoupledRun<SolidSolver> run(
        solver, parameters.run,
        {args.out_dir, "solid", cosph::coupling::PhaseKind::solid,
         "cosph-solid (jaumann)", args.endpoint, timeout});
    return run.run();
  }
  std::vector<sph::Column> columns;
  for (const sph::Gauge& gauge : solver.gauge_values()) columns.push_back({gauge.name, gauge.unit});
  sph::StandaloneRun<SolidSolver> run(solver, parameters.run, args.out_dir, "solid", columns,
                                      [](const SolidSolver& s) {
                                        std::vector<double> values;
                                        for (const auto& gauge : s.gauge_values())
                                          values.push_back(gauge.value);
                                        return values;
                                      });
  return run.run();
}

}  // namespace

int main(int argc, char** argv) {
  return sph::run_guarded("cosph-solid", [&] { return run_solid(argc, argv); });
}
