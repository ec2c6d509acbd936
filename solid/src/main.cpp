// cosph-solid: the SPH linear elastic solid solver (Gray, Monaghan & Swift
// 2001). Runs a case alone when the case has no fluid; coupled runs come
// through the coupler.
#include <omp.h>

#include <iostream>

#include "participant/run_solver.hpp"
#include "solid_parameters.hpp"
#include "solid_solver.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/solver_cli.hpp"

namespace {

using cosph::solid::SolidSolver;

int run_solid(int argc, char** argv) {
  const sph::SolverArgs args = sph::parse_solver_args(
      argc, argv, "cosph-solid", "SPH linear elastic solid solver (SPEC.md \"Solid\").");
  const sph::CaseFile case_file = sph::load_case(args.case_path, args.overrides);
  const auto parameters = cosph::solid::read_solid_parameters(case_file);
  cosph::solid::require_model(case_file, parameters, cosph::solid::SolidModel::jaumann);
  const bool coupled = !args.endpoint.empty();
  sph::require(coupled || !case_file.config.has_fluid(), case_file, "fluid",
               "this case is coupled: run it with coupler/cosph, which starts the coupler");
  sph::make_output_dir(args.out_dir);
  sph::install_stop_handlers();

  sph::RunThreads threads(parameters.run.threads);
  SolidSolver solver(case_file, parameters);
  threads.settle(solver.particles().size());
  long clamped = 0;
  for (auto c : solver.particles().clamped) clamped += c;
  std::cout << "cosph-solid: " << solver.particles().size() << " solid particles (" << clamped
            << " clamped), dx = " << parameters.dx << " m, h = " << parameters.h
            << " m, c = " << parameters.c0 << " m/s, artificial stress "
            << (parameters.artificial_stress.enabled ? "on" : "off") << ", "
            << omp_get_max_threads() << " threads" << std::endl;
  return cosph::coupling::run_solver(solver, parameters.run, case_file, args, "solid",
                                     cosph::coupling::PhaseKind::solid, "cosph-solid (jaumann)");
}

}  // namespace

int main(int argc, char** argv) {
  return sph::run_guarded("cosph-solid", [&] { return run_solid(argc, argv); });
}
