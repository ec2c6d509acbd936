// cosph-fluid: the weakly compressible SPH water solver. Runs a case alone
// when it has no solid; with --endpoint it takes part in a coupled run.
#include <omp.h>

#include <iostream>
#include <string>

#include "fluid_parameters.hpp"
#include "fluid_solver.hpp"
#include "participant/run_solver.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/output_lock.hpp"
#include "sphcore/particle_budget.hpp"
#include "sphcore/run_threads.hpp"
#include "sphcore/solver_cli.hpp"

namespace {

using cosph::fluid::FluidSolver;

int run_fluid(int argc, char** argv) {
  const sph::SolverArgs args = sph::parse_solver_args(
      argc, argv, "cosph-fluid", "Weakly compressible SPH water solver (docs/physics.md).");
  const sph::CaseFile case_file = sph::load_case(args.case_path, args.overrides);
  const auto parameters = cosph::fluid::read_fluid_parameters(case_file);
  sph::check_particle_budget(case_file);
  if (const std::string warning = cosph::fluid::kernel_resolution_warning(parameters);
      !warning.empty())
    std::cerr << "cosph-fluid: warning: " << case_file.path << ": " << warning << std::endl;
  const bool coupled = !args.endpoint.empty();
  sph::require(coupled || !case_file.config.has_solid(), case_file, "solid",
               "this case is coupled: run it with coupler/cosph, which starts the coupler");
  sph::make_output_dir(args.out_dir);
  sph::lock_output_dir(args.out_dir, args.endpoint, sph::command_line(argc, argv));
  sph::install_stop_handlers();

  sph::RunThreads threads(parameters.run.threads);
  FluidSolver solver(case_file, parameters);
  threads.settle(solver.particles().size());
  std::cout << "cosph-fluid: " << solver.gauges().water_particles << " water and "
            << solver.particles().size() - solver.gauges().water_particles
            << " wall particles, dx = " << parameters.dx << " m, h = " << parameters.h
            << " m, c0 = " << parameters.c0 << " m/s, " << omp_get_max_threads() << " threads"
            << std::endl;

  const int status = cosph::coupling::run_solver(solver, parameters.run, case_file, args, "fluid",
                                                 cosph::coupling::PhaseKind::fluid,
                                                 "cosph-fluid (WCSPH)", threads);
  if (solver.spray_removed() > 0)
    std::cout << "cosph-fluid: " << solver.spray_removed()
              << (solver.spray_removed() == 1 ? " water particle" : " water particles")
              << " thinned to spray and left the run (timeseries.csv column spray_removed;"
                 " README \"Spray\")"
              << std::endl;
  if (const std::string note = cosph::fluid::mach_number_note(solver.fastest_water(), parameters);
      !note.empty())
    std::cout << "cosph-fluid: note: " << note << std::endl;
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  return sph::run_guarded("cosph-fluid", [&] { return run_fluid(argc, argv); });
}
